// SPDX-License-Identifier: MIT
// R6: an embedder's own task system runs the step's parallel loops, with the same result.
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"
#include "sandcore/task_system.hpp"
#include "worker_pool.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

namespace {

// A host's task system as simple as one can be: each loop's items are cut into three ranges, run
// on threads started for it, and joined in finish. It counts what the scene asked of it.
struct ThreeThreadHost {
    std::atomic<int> enqueued{0}, finished{0};

    struct Running {
        std::vector<std::jthread> threads;
    };

    static void* enqueue(sandcore::TaskSystem::Task task, int items, int minRange, void* taskContext, void* user) {
        auto& host = *static_cast<ThreeThreadHost*>(user);
        ++host.enqueued;
        auto* running = new Running;
        const int parts = std::clamp(items / std::max(minRange, 1), 1, 3);
        for (int p = 0; p < parts; ++p)
            running->threads.emplace_back([=] { task(items * p / parts, items * (p + 1) / parts, taskContext); });
        return running;
    }
    static void finish(void* userTask, void* user) {
        ++static_cast<ThreeThreadHost*>(user)->finished;
        delete static_cast<Running*>(userTask); // joins its threads
    }
    sandcore::TaskSystem tasks() { return {&enqueue, &finish, this}; }
};

sandcore::Scene hourglass(const sandcore::StepSettings& step) {
    return sandcore::makeHourglassScene(sandcore::makeHourglassMask({48, 4.0f}), {}, step);
}

} // namespace

TEST_CASE("R6: a scene steps on the host's task system, to the same state as on its own threads") {
    for (sandcore::PhysicsLevel physics : {sandcore::PhysicsLevel::Classic, sandcore::PhysicsLevel::Granular}) {
        CAPTURE(int(physics));
        sandcore::StepSettings own;
        own.threads = 2;
        own.physics.level = physics;
        ThreeThreadHost host;
        sandcore::StepSettings hosted = own;
        hosted.tasks = host.tasks();
        sandcore::Scene a = hourglass(own), b = hourglass(hosted);
        for (int i = 0; i < 150; ++i) {
            a.step();
            b.step();
        }
        CHECK(a.stateHash() == b.stateHash());
        CHECK(b.counters().grainsLower > 0);
        CHECK(host.enqueued.load() > 0);
        CHECK(host.finished.load() == host.enqueued.load());
    }
}

TEST_CASE("R6: a task that throws on the host's threads is rethrown to the caller once the loop is done") {
    ThreeThreadHost host;
    sandcore::WorkerPool pool(3, host.tasks());
    CHECK(pool.threadCount() == 3);
    std::atomic<int> ran{0};
    CHECK_THROWS_AS(pool.parallelFor(9, [&](int i) {
        ++ran;
        if (i == 4) throw std::runtime_error("task 4");
    }), std::runtime_error);
    CHECK(ran.load() == 9);
    CHECK(host.finished.load() == host.enqueued.load());
}
