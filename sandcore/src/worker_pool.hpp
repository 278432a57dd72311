// SPDX-License-Identifier: MIT
#pragma once
// A small pool of persistent worker threads for the step (R6). The caller takes part in every
// parallel loop, so a pool of N threads starts N - 1 workers. Given a host's task system, it
// starts none and hands each loop to the host instead.

#include "sandcore/task_system.hpp"

#include <atomic>
#include <exception>
#include <mutex>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace sandcore {

/// Persistent threads that share short parallel loops; the caller works too.
class WorkerPool {
public:
    /// A pool that runs loops on `threads` threads in all (the caller included); at least 1.
    /// With an active `host`, loops run on the host's task system, split `threads` ways.
    explicit WorkerPool(int threads, const TaskSystem& host = {});
    ~WorkerPool(); ///< stops and joins the workers
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    /// Threads that share a loop, the caller included.
    int threadCount() const { return host_.active() ? hostThreads_ : int(workers_.size()) + 1; }

    /// Calls task(i) for every i in [0, count < 2^21), spread over the threads; returns when all are done.
    /// Tasks must not depend on which thread runs them or in which order. If tasks throw, the
    /// first exception is rethrown here once every task has finished.
    void parallelFor(int count, const std::function<void(int)>& task);

private:
    void workerLoop();
    void runOnHost(int count, const std::function<void(int)>& task);
    void claimAndRunTasks();

    TaskSystem host_;
    int hostThreads_ = 1;
    std::vector<std::jthread> workers_;
    // The loop being run. Written only while no task of the previous loop is unfinished, and
    // read only by a thread that has claimed a task of this loop, so no reader sees a stale one.
    const std::function<void(int)>* task_ = nullptr;
    // Tasks are claimed from one word: (loop number << 42) | (task count << 21) | next task.
    // A thread that wakes late cannot claim a task of a loop that has already finished.
    std::atomic<std::uint64_t> ticket_{0};
    std::atomic<int> unfinished_{0};     // tasks of the current loop not yet done
    std::atomic<std::uint32_t> wakeups_{0}; // bumped to wake sleeping workers
    std::uint64_t loopNumber_ = 0;
    std::atomic<bool> stopping_{false};
    std::mutex failureMutex_;
    std::exception_ptr failure_; // the first exception a task of the current loop threw
};

} // namespace sandcore
