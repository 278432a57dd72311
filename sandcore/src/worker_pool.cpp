// SPDX-License-Identifier: MIT
#include "worker_pool.hpp"

#include "sandcore/scene.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

namespace sandcore {

namespace {
// A step dispatches many short loops back to back, and the next step's first loop follows the
// last one after the step's serial tail (tens of microseconds): workers spin that long before
// sleeping, so they catch the next loop without a futex round trip (whose wake-up can cost as
// much as the loop), and sleep when the simulation idles.
constexpr auto kSpinBeforeSleep = std::chrono::microseconds(300);
constexpr int kSpinsBeforeSleep = 1 << 14; // the caller's wait for tasks others claimed, before it yields
constexpr std::uint64_t kFieldMask = (std::uint64_t{1} << 21) - 1;

constexpr std::uint64_t nextTaskOf(std::uint64_t ticket) { return ticket & kFieldMask; }
constexpr std::uint64_t taskCountOf(std::uint64_t ticket) { return (ticket >> 21) & kFieldMask; }
} // namespace

WorkerPool::WorkerPool(int threads, const TaskSystem& host) : host_(host), hostThreads_(std::max(threads, 1)) {
    if (host_.active()) return;
    const int workers = std::max(threads, 1) - 1;
    workers_.reserve(std::size_t(workers));
    for (int i = 0; i < workers; ++i) workers_.emplace_back([this] { workerLoop(); });
}

WorkerPool::~WorkerPool() {
    stopping_.store(true, std::memory_order_release);
    wakeups_.fetch_add(1, std::memory_order_release);
    wakeups_.notify_all();
    // jthread joins on destruction
}

void WorkerPool::claimAndRunTasks() {
    std::uint64_t ticket = ticket_.load(std::memory_order_acquire);
    while (nextTaskOf(ticket) < taskCountOf(ticket)) {
        if (!ticket_.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel, std::memory_order_acquire))
            continue; // another thread claimed it; ticket now holds the new value
        try {
            (*task_)(int(nextTaskOf(ticket)));
        } catch (...) {
            const std::lock_guard lock(failureMutex_);
            if (!failure_) failure_ = std::current_exception();
        }
        unfinished_.fetch_sub(1, std::memory_order_release);
        ticket = ticket_.load(std::memory_order_acquire);
    }
}

void WorkerPool::runOnHost(int count, const std::function<void(int)>& task) {
    struct Loop {
        const std::function<void(int)>* task;
        std::mutex failureMutex;
        std::exception_ptr failure; // the first exception a task threw
    } loop{&task, {}, {}};
    const TaskSystem::Task run = [](int first, int last, void* context) {
        Loop& running = *static_cast<Loop*>(context);
        for (int i = first; i < last; ++i) try {
                (*running.task)(i);
            } catch (...) {
                const std::lock_guard lock(running.failureMutex);
                if (!running.failure) running.failure = std::current_exception();
            }
    };
    if (void* userTask = host_.enqueue(run, count, 1, &loop, host_.userContext)) host_.finish(userTask, host_.userContext);
    if (loop.failure) std::rethrow_exception(loop.failure);
}

void WorkerPool::parallelFor(int count, const std::function<void(int)>& task) {
    if (count < 0 || std::uint64_t(count) > kFieldMask) throw std::invalid_argument("parallelFor: bad task count");
    if (host_.active() && count > 1) return runOnHost(count, task);
    if (workers_.empty() || count <= 1) {
        std::exception_ptr first;
        for (int i = 0; i < count; ++i) try {
                task(i);
            } catch (...) {
                if (!first) first = std::current_exception();
            }
        if (first) std::rethrow_exception(first);
        return;
    }
    task_ = &task;
    unfinished_.store(count, std::memory_order_relaxed);
    ++loopNumber_;
    ticket_.store((loopNumber_ << 42) | (std::uint64_t(count) << 21), std::memory_order_release);
    wakeups_.fetch_add(1, std::memory_order_release);
    wakeups_.notify_all();
    claimAndRunTasks();
    // Only tasks that others claimed can still be running: wait for those, not for idle workers.
    for (int spins = 0; unfinished_.load(std::memory_order_acquire) != 0; ++spins)
        if (spins > kSpinsBeforeSleep) std::this_thread::yield();
    const std::lock_guard lock(failureMutex_);
    if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

void WorkerPool::workerLoop() {
    std::uint32_t seen = wakeups_.load(std::memory_order_acquire);
    while (!stopping_.load(std::memory_order_acquire)) {
        claimAndRunTasks();
        std::uint32_t now = wakeups_.load(std::memory_order_acquire);
        const auto sleepAt = std::chrono::steady_clock::now() + kSpinBeforeSleep;
        for (int spins = 1; now == seen; ++spins) {
            if (spins % 256 == 0 && std::chrono::steady_clock::now() > sleepAt) break; // the clock read costs ~20 ns
            now = wakeups_.load(std::memory_order_acquire);
        }
        if (now == seen) wakeups_.wait(seen, std::memory_order_acquire);
        seen = wakeups_.load(std::memory_order_acquire);
    }
}

void parallelFor(WorkerPool* pool, int count, const std::function<void(int)>& task) {
    if (pool != nullptr) {
        pool->parallelFor(count, task);
        return;
    }
    for (int i = 0; i < count; ++i) task(i);
}

} // namespace sandcore
