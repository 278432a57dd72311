// SPDX-License-Identifier: MIT
#pragma once
// R6: a host's own task system, for an embedder whose program already has one (as Box2D's
// enqueueTask/finishTask). Without it, a scene starts threads of its own (WorkerPool).

namespace sandcore {

/// The host's task system. The step calls enqueue for each of its parallel loops and then finish
/// with what enqueue returned, before it goes on; the loop's items are independent, so the result
/// of a step does not depend on which thread runs which range, nor in which order.
struct TaskSystem {
    /// Runs items [first, last) of a loop; `taskContext` is what enqueue was given.
    using Task = void (*)(int first, int last, void* taskContext);
    /// Starts `task` over items [0, itemCount), in ranges of at least `minRange` items, on the
    /// host's threads; returns a handle for finish, or nullptr when it has run the task already.
    void* (*enqueue)(Task task, int itemCount, int minRange, void* taskContext, void* userContext) = nullptr;
    /// Waits until the task that enqueue returned `userTask` for has run over all its items.
    void (*finish)(void* userTask, void* userContext) = nullptr;
    /// Passed back to enqueue and finish.
    void* userContext = nullptr;

    /// The host's task system is used.
    bool active() const { return enqueue != nullptr && finish != nullptr; }
};

} // namespace sandcore
