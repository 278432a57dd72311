// SPDX-License-Identifier: MIT
// PH5 with falls that sleep: a granular grain falling short of its next cell, and the column
// riding on it, are not visited until the step the fall reaches that cell (grid_sweep.hpp). The
// result must be that of a full sweep after every step, whatever lands on them or is edited
// next to them meanwhile.
#include "support/scene_fixtures.hpp"

#include "sandcore/inside_mask.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace sandcore;

namespace {

// A granular box of `lower` cells under one upper layer, at gravity g (cells per step squared).
Scene granularBox(Int3 lower, float gravity) {
    Scene scene = fixtures::boxScene(lower, 1);
    PhysicsSettings physics;
    physics.level = PhysicsLevel::Granular;
    physics.gravity = gravity;
    scene.setPhysics(physics);
    return scene;
}

// Requires `scene` to agree with `full` (a full sweep of the same scene) after a step: the same
// cells, counters and fall states (read up to date).
void requireSameAs(const Scene& scene, const Scene& full) {
    const std::uint64_t n = full.counters().stepsDone;
    REQUIRE_MESSAGE(scene.stateHash() == full.stateHash(), "cells differ after step " << n);
    REQUIRE(scene.counters().movesLastStep == full.counters().movesLastStep);
    REQUIRE_MESSAGE(scene.counters().speedChangesLastStep == full.counters().speedChangesLastStep, "step " << n);
    REQUIRE(scene.grainCount() == full.grainCount());
    for (std::uint32_t id = 0; id < std::uint32_t(scene.grainCount()); ++id)
        REQUIRE_MESSAGE(scene.fallOf(id) == full.fallOf(id), "grain " << id << " after step " << n);
    REQUIRE(scene.sweepsMatchCells());
}

// The same box twice: one sweeping its awake grains (where falls sleep), one every cell.
struct SleepingAndFull {
    Scene sleeping, full;
    SleepingAndFull(Int3 lower, float gravity) : sleeping(granularBox(lower, gravity)), full(granularBox(lower, gravity)) {
        full.setSleeping(false);
    }
    // Applies the same edit to both.
    template <class Edit> void edit(Edit&& f) {
        f(sleeping);
        f(full);
    }
    // Steps both and requires the same cells, counters and fall states (read up to date).
    void step() {
        sleeping.step();
        full.step();
        requireSameAs(sleeping, full);
    }
};

// Adds a column of `height` grains at (x, bottom .. bottom + height - 1, z) of the lower grid.
void addColumn(Scene& scene, int x, int bottom, int height, int z) {
    for (int y = bottom; y < bottom + height; ++y) REQUIRE(fixtures::putLower(scene, x, y, z) >= 0);
}

int lowerY(const Scene& scene, std::int64_t id) {
    return scene.grid(GridLevel::Lower).coordinate(scene.grains().place[std::size_t(id)].cell).y;
}

} // namespace

TEST_CASE("sleeping falls: a column falling from rest is not visited until its fall reaches a cell, "
          "and reads as if it had been") {
    // g = 0.02: a grain at rest needs 10 steps for its first cell, so the column sleeps after its
    // first visit until then, its states kept as of that visit.
    SleepingAndFull box({3, 40, 3}, 0.02f);
    box.edit([](Scene& s) { addColumn(s, 1, 30, 5, 1); });
    box.step();
    CHECK(box.sleeping.counters().visitedLastStep == 5); // the lowest grain, and the four it carries
    for (int step = 2; step <= 9; ++step) {
        box.step();
        const SceneCounters& counters = box.sleeping.counters();
        CHECK(counters.visitedLastStep == 0);
        CHECK(counters.speedChangesLastStep == 5); // the five falls still changed: not settled
        CHECK_FALSE(box.sleeping.settled());
        for (std::uint32_t id = 0; id < 5; ++id) // stored as of step 1, read as of this one
            CHECK_FALSE(box.sleeping.grains().fallOf(id) == box.sleeping.fallOf(id));
    }
    box.step(); // step 10: the fall reaches its first cell
    CHECK(box.sleeping.counters().movesLastStep > 0);
    CHECK(box.sleeping.counters().visitedLastStep >= 5);
    for (int i = 0; i < 50; ++i) box.step();
    CHECK(box.sleeping.settled());
}

TEST_CASE("sleeping falls: a grain landing on a sleeping column takes its speed and joins it") {
    // The lander falls from y = 55 from step 1; the column appears under it at step 60 and sleeps
    // from step 61; the lander, at 1.2 cells a step by then, reaches its top a few steps later,
    // before the column's first move at step 70.
    SleepingAndFull box({3, 60, 3}, 0.02f);
    std::int64_t lander = -1;
    box.edit([&](Scene& s) { lander = fixtures::putLower(s, 1, 55, 1); });
    for (int i = 0; i < 60; ++i) box.step();
    box.edit([](Scene& s) { addColumn(s, 1, 10, 3, 1); });
    const std::int64_t columnBottom = lander + 1;
    int landedAtStep = 0, stepsOnlyLanderVisited = 0;
    for (int i = 0; i < 80; ++i) {
        box.step();
        if (box.sleeping.counters().visitedLastStep == 1 && landedAtStep == 0) ++stepsOnlyLanderVisited;
        if (landedAtStep == 0 && lowerY(box.sleeping, lander) == 13) {
            landedAtStep = int(box.sleeping.counters().stepsDone);
            CHECK(lowerY(box.sleeping, columnBottom) == 10); // the column had not moved yet
        }
    }
    CHECK(landedAtStep > 61);
    CHECK(landedAtStep < 70);
    CHECK(stepsOnlyLanderVisited >= 2); // the column slept while the lander fell onto it
}

TEST_CASE("sleeping falls: edits next to a sleeping column give the full sweep's result") {
    // Each edit is made at step 63, while the column (added at step 0 at g = 0.02) sleeps.
    struct Case {
        std::string name;
        void (*edit)(Scene&);
    };
    const Case cases[] = {
        {"a grain put on top", [](Scene& s) { REQUIRE(fixtures::putLower(s, 2, 34, 2) >= 0); }},
        {"a grain put under the gatherer", [](Scene& s) { REQUIRE(fixtures::putLower(s, 2, 29, 2) >= 0); }},
        {"an obstacle under the gatherer",
         [](Scene& s) { s.addObstacle(GridLevel::Lower, {{2, 29, 2}, {3, 30, 3}}); }},
        {"the gatherer taken away",
         [](Scene& s) { REQUIRE(s.removeGrain(GridLevel::Lower, s.grid(GridLevel::Lower).index(2, 30, 2))); }},
        {"a rider taken away",
         [](Scene& s) { REQUIRE(s.removeGrain(GridLevel::Lower, s.grid(GridLevel::Lower).index(2, 32, 2))); }},
        {"an obstacle over a rider", [](Scene& s) { s.addObstacle(GridLevel::Lower, {{2, 31, 2}, {3, 32, 3}}); }},
    };
    for (const Case& c : cases) {
        CAPTURE(c.name);
        SleepingAndFull box({5, 40, 5}, 0.02f);
        for (int i = 0; i < 62; ++i) box.step();
        box.edit([](Scene& s) { addColumn(s, 2, 30, 4, 2); });
        box.step(); // step 63: the column gathers, and sleeps
        REQUIRE(box.sleeping.counters().visitedLastStep > 0);
        box.step();
        REQUIRE(box.sleeping.counters().visitedLastStep == 0); // asleep: nothing visited
        box.edit(c.edit);
        for (int i = 0; i < 80; ++i) box.step();
    }
}

TEST_CASE("sleeping falls: a snapshot taken while a column sleeps holds every state up to date") {
    SleepingAndFull box({3, 40, 3}, 0.02f);
    box.edit([](Scene& s) { addColumn(s, 1, 30, 4, 1); });
    for (int i = 0; i < 5; ++i) box.step();
    REQUIRE(box.sleeping.counters().visitedLastStep == 0);
    const SceneSnapshot saved = box.sleeping.snapshot();
    for (std::uint32_t id = 0; id < saved.grains.size(); ++id) {
        CHECK(saved.grains.fallOf(id) == box.sleeping.fallOf(id));
        CHECK(saved.grains.fallOf(id).gatheringSince == 0); // no sweep's bookkeeping in a file
    }
    // Restored into a scene of its own, the fall goes on as in the original and the full sweep.
    Scene restored = granularBox({3, 40, 3}, 0.02f);
    restored.restore(saved);
    for (int i = 0; i < 50; ++i) {
        box.step();
        restored.step();
        requireSameAs(restored, box.full);
    }
}

TEST_CASE("sleeping falls: a pour at low gravity gives the same state as a full sweep after every step, "
          "on 1 and 2 threads") {
    // Grains poured one a step fall, land on the pile and on each other, slide off its edges and
    // fall again from rest: every way into and out of a sleep, many times over.
    for (float gravity : {0.005f, 0.02f}) {
        CAPTURE(gravity);
        StepSettings step;
        step.physics.level = PhysicsLevel::Granular;
        step.physics.gravity = gravity;
        Scene sleeping = makeCanvasScene({{24, 4, 24}, {24, 40, 24}}, step);
        Scene twoThreads = makeCanvasScene({{24, 4, 24}, {24, 40, 24}}, step);
        Scene full = makeCanvasScene({{24, 4, 24}, {24, 40, 24}}, step);
        twoThreads.setThreads(2);
        full.setSleeping(false);
        std::int64_t visitsSleeping = 0, visitsFull = 0;
        for (int i = 0; i < 700; ++i) {
            for (Scene* s : {&sleeping, &twoThreads, &full}) {
                if (i < 500 && i % 2 == 0) s->addGrain(GridLevel::Upper, pourCell(*s));
                s->step();
            }
            requireSameAs(sleeping, full);
            requireSameAs(twoThreads, full);
            visitsSleeping += sleeping.counters().visitedLastStep;
            visitsFull += full.counters().visitedLastStep;
        }
        CHECK(visitsSleeping * 20 < visitsFull);
    }
}

TEST_CASE("sleeping falls: a wide slab collapsing at low gravity, its layers split into strips over threads, "
          "gives the full sweep's result after every step") {
    // Wide enough that its busy layers hold 24 awake rows and more, which the sweep splits into
    // strips of 8 rows over the threads; the grains that slide off its edges fall from rest and
    // sleep, with the columns on them, in strips that neighbours' visits touch.
    InsideMask slab = InsideMask::empty({72, 6, 40});
    for (int y = 0; y < 6; ++y)
        for (int z = 0; z < 40; ++z)
            for (int x = 0; x < 72; ++x) slab.set(x, y, z, true);
    StepSettings step;
    step.seed = 5;
    step.physics.level = PhysicsLevel::Granular;
    step.physics.gravity = 0.02f;
    Scene one = makeSculptureScene(slab, step), three = makeSculptureScene(slab, step), full = makeSculptureScene(slab, step);
    three.setThreads(3);
    full.setSleeping(false);
    std::int64_t speedChanges = 0;
    for (int i = 0; i < 120; ++i) {
        for (Scene* s : {&one, &three, &full}) s->step();
        requireSameAs(one, full);
        requireSameAs(three, full);
        speedChanges += full.counters().speedChangesLastStep;
    }
    CHECK(speedChanges > 10'000); // many falls, and columns riding them, went through the sleeps
}
