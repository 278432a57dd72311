#include "sandcore/worker_pool.hpp"

#include <algorithm>

namespace sandcore {

namespace {
// A step dispatches many short loops back to back; workers spin briefly before sleeping so
// they catch the next loop without a futex round trip, and sleep when the simulation idles.
constexpr int kSpinsBeforeSleep = 1 << 14;
} // namespace

WorkerPool::WorkerPool(int threads) {
    const int workers = std::max(threads, 1) - 1;
    workers_.reserve(std::size_t(workers));
    for (int i = 0; i < workers; ++i) workers_.emplace_back([this] { workerLoop(); });
}

WorkerPool::~WorkerPool() {
    stopping_.store(true, std::memory_order_release);
    generation_.fetch_add(1, std::memory_order_acq_rel);
    generation_.notify_all();
    // jthread joins on destruction
}

void WorkerPool::runTasks() {
    for (;;) {
        const int i = nextTask_.fetch_add(1, std::memory_order_relaxed);
        if (i >= taskCount_) return;
        (*task_)(i);
    }
}

void WorkerPool::parallelFor(int count, const std::function<void(int)>& task) {
    if (workers_.empty() || count <= 1) {
        for (int i = 0; i < count; ++i) task(i);
        return;
    }
    task_ = &task;
    taskCount_ = count;
    nextTask_.store(0, std::memory_order_relaxed);
    busyWorkers_.store(int(workers_.size()), std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release); // publishes task_ and taskCount_
    generation_.notify_all();
    runTasks();
    // Every worker checks in for this generation before task may go out of scope.
    for (int spins = 0; busyWorkers_.load(std::memory_order_acquire) != 0; ++spins)
        if (spins > kSpinsBeforeSleep) std::this_thread::yield();
}

void WorkerPool::workerLoop() {
    std::uint64_t seen = 0;
    for (;;) {
        std::uint64_t now = generation_.load(std::memory_order_acquire);
        for (int spins = 0; now == seen && spins < kSpinsBeforeSleep; ++spins)
            now = generation_.load(std::memory_order_acquire);
        while (now == seen) {
            generation_.wait(seen, std::memory_order_acquire);
            now = generation_.load(std::memory_order_acquire);
        }
        seen = now;
        if (stopping_.load(std::memory_order_acquire)) return;
        runTasks();
        busyWorkers_.fetch_sub(1, std::memory_order_release);
    }
}

} // namespace sandcore
