#pragma once
// A small pool of persistent worker threads for the step (R6). The caller takes part in every
// parallel loop, so a pool of N threads starts N - 1 workers.

#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace sandcore {

class WorkerPool {
public:
    /// A pool that runs loops on `threads` threads in all (the caller included); at least 1.
    explicit WorkerPool(int threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    /// Threads that share a loop, the caller included.
    int threadCount() const { return int(workers_.size()) + 1; }

    /// Calls task(i) for every i in [0, count), spread over the threads; returns when all are done.
    /// Tasks must not depend on which thread runs them or in which order.
    void parallelFor(int count, const std::function<void(int)>& task);

private:
    void workerLoop();
    void runTasks();

    std::vector<std::jthread> workers_;
    const std::function<void(int)>* task_ = nullptr;
    int taskCount_ = 0;
    std::atomic<int> nextTask_{0};
    std::atomic<int> busyWorkers_{0};
    std::atomic<std::uint64_t> generation_{0};
    std::atomic<bool> stopping_{false};
};

} // namespace sandcore
