// SPDX-License-Identifier: MIT
// R10 scenes, R11 obstacles, R14 counters and editing.
#include "support/scene_fixtures.hpp"

#include "hourglass_split.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

using namespace sandcore;

TEST_CASE("hourglass: split at the neck, outside INVALID, upper bulb filled, lower empty") {
    const InsideMask vessel = makeHourglassMask({40, 2.0f, 0.0f});
    const int neck = findNeckLayer(vessel);
    HourglassSettings settings;
    settings.fillFraction = 1.0f;
    Scene scene = makeHourglassScene(vessel, settings);
    const CellGrid& upper = scene.grid(GridLevel::Upper);
    const CellGrid& lower = scene.grid(GridLevel::Lower);
    CHECK(upper.size().y == vessel.size.y - neck);
    CHECK(lower.size().y == neck + 1);
    CHECK(scene.gridOrigin(GridLevel::Upper).y == neck);
    CHECK(scene.counters().grainsLower == 0);
    CHECK(scene.counters().grainsUpper == scene.grainCount());
    // Every lower cell is INVALID exactly where the vessel is outside.
    for (int y = 0; y <= neck; ++y)
        for (int z = 0; z < vessel.size.z; ++z)
            for (int x = 0; x < vessel.size.x; ++x)
                REQUIRE((lower.at(x, y, z) == kInvalid) == !vessel.at(x, y, z));
    // Filled completely: no EMPTY cell is left in the upper grid.
    for (CellValue v : upper.cells()) REQUIRE(v != kEmpty);
}

TEST_CASE("hourglass fill fraction fills whole layers from the neck up") {
    const InsideMask vessel = makeHourglassMask({40, 2.0f, 0.0f});
    HourglassSettings half;
    half.fillFraction = 0.5f;
    Scene scene = makeHourglassScene(vessel, half);
    HourglassSettings full;
    full.fillFraction = 1.0f;
    const std::int64_t all = makeHourglassScene(vessel, full).grainCount();
    CHECK(scene.grainCount() >= all / 2);
    CHECK(scene.grainCount() < all * 3 / 4);
    CHECK_THROWS(makeHourglassScene(vessel, HourglassSettings{0.0f, true}));
}

TEST_CASE("sculpture: upper grid twice as wide and deep, lower twice as wide, deep and high") {
    const InsideMask ball = makeSphereMask(10);
    Scene scene = makeSculptureScene(ball);
    CHECK(scene.grid(GridLevel::Upper).size() == Int3{20, 10, 20});
    CHECK(scene.grid(GridLevel::Lower).size() == Int3{20, 20, 20});
    CHECK(scene.grainCount() == ball.countInside());
    for (CellValue v : scene.grid(GridLevel::Lower).cells()) REQUIRE(v == kEmpty);
    for (int i = 0; i < 200 && !scene.settled(); ++i) scene.step();
    CHECK(scene.settled());
    CHECK(scene.counters().grainsUpper == 0); // collapsed onto the lower grid's floor
}

TEST_CASE("canvas: both grids EMPTY, and a poured grain lands on the floor") {
    Scene scene = makeCanvasScene();
    CHECK(scene.grid(GridLevel::Upper).size() == Int3{60, 10, 60});
    CHECK(scene.grid(GridLevel::Lower).size() == Int3{60, 40, 60});
    CHECK(scene.grainCount() == 0);
    const auto id = scene.addGrain(GridLevel::Upper, pourCell(scene));
    REQUIRE(id == 0);
    for (int i = 0; i < 200 && !scene.settled(); ++i) scene.step();
    CHECK(scene.grains().level[0] == GridLevel::Lower);
    CHECK(scene.grid(GridLevel::Lower).coordinate(scene.grains().place[0].cell) == Int3{30, 0, 30});
    scene.reset();
    CHECK(scene.grainCount() == 0);
}

TEST_CASE("obstacles: sand piles on and beside them, never inside") {
    Scene scene = makeCanvasScene({{16, 3, 16}, {16, 12, 16}});
    const CellBox box{{6, 0, 6}, {10, 4, 10}};
    CHECK(scene.addObstacle(GridLevel::Lower, box) == 0);
    for (int i = 0; i < 100'000 && scene.grainCount() < 900; ++i) {
        scene.addGrain(GridLevel::Upper, pourCell(scene)); // right above the obstacle, once its cell is free
        scene.step();
    }
    REQUIRE(scene.grainCount() == 900);
    for (int i = 0; i < 20'000 && !scene.settled(); ++i) scene.step();
    const CellGrid& lower = scene.grid(GridLevel::Lower);
    for (int y = 0; y < 4; ++y)
        for (int z = 6; z < 10; ++z)
            for (int x = 6; x < 10; ++x) REQUIRE(lower.at(x, y, z) == kInvalid);
    CHECK(lower.at(8, 4, 8) >= 0);   // sand on top of it
    CHECK(lower.at(5, 0, 8) >= 0);   // and beside it on the floor
    CHECK(scene.grainCount() == 900);
}

TEST_CASE("an obstacle placed over sand removes those grains, and clearing it frees the cells") {
    Scene scene = fixtures::boxScene({6, 4, 6});
    for (int x = 0; x < 6; ++x) fixtures::putLower(scene, x, 0, 2);
    CHECK(scene.addObstacle(GridLevel::Lower, {{1, 0, 0}, {3, 2, 6}}) == 2);
    CHECK(scene.grainCount() == 4);
    CHECK(scene.counters().grainsLower == 4);
    CHECK(fixtures::lowerAt(scene, 1, 0, 2) == kInvalid);
    CHECK(!scene.removeGrain(GridLevel::Lower, scene.grid(GridLevel::Lower).index(1, 0, 2))); // never removes INVALID
    scene.reset();
    CHECK(fixtures::lowerAt(scene, 2, 1, 3) == kInvalid); // obstacles survive a reset
    scene.clearObstacles(GridLevel::Lower);
    CHECK(fixtures::lowerAt(scene, 2, 1, 3) == kEmpty);
    CHECK(scene.obstacles(GridLevel::Lower).empty());
}

TEST_CASE("removing a grain keeps ids dense and wakes the grain above") {
    Scene scene = fixtures::boxScene({1, 3, 1}); // a single column: nowhere to slip
    CHECK(fixtures::putLower(scene, 0, 0, 0) == 0);
    CHECK(fixtures::putLower(scene, 0, 1, 0) == 1);
    scene.step();
    REQUIRE(scene.settled());
    CHECK(scene.removeGrain(GridLevel::Lower, scene.grid(GridLevel::Lower).index(0, 0, 0)));
    CHECK(scene.grainCount() == 1);
    CHECK(fixtures::lowerAt(scene, 0, 1, 0) == 0); // the upper grain took id 0
    scene.step();
    CHECK(scene.counters().movesLastStep == 1);
    CHECK(fixtures::lowerAt(scene, 0, 0, 0) == 0); // and fell into the freed cell
}

TEST_CASE("scenes reject bad input") {
    CHECK_THROWS(makeHourglassScene(InsideMask::empty({4, 4, 4})));
    CHECK_THROWS(makeSculptureScene(InsideMask::empty({4, 4, 4})));
    CHECK_THROWS(makeCanvasScene({{10, 2, 10}, {12, 4, 10}}));
    CHECK_THROWS(makeCanvasScene({{10, 0, 10}, {10, 4, 10}}));
    StepSettings noThreads;
    noThreads.threads = 0;
    CHECK_THROWS(makeCanvasScene({}, noThreads));
}

TEST_CASE("restore returns to a snapshot exactly, and the steps after it repeat") {
    Scene scene = makeSculptureScene(makeSphereMask(12));
    for (int i = 0; i < 10; ++i) scene.step();
    const SceneSnapshot saved = scene.snapshot();
    const std::uint64_t hashAtSnapshot = scene.stateHash();
    for (int i = 0; i < 30; ++i) scene.step();
    const std::uint64_t hashLater = scene.stateHash();
    scene.addObstacle(GridLevel::Lower, {{0, 0, 0}, {4, 4, 4}});
    scene.restore(saved);
    CHECK(scene.stateHash() == hashAtSnapshot);
    CHECK(scene.obstacles(GridLevel::Lower).empty());
    CHECK(scene.counters().stepsDone == 10);
    for (int i = 0; i < 30; ++i) scene.step();
    CHECK(scene.stateHash() == hashLater);
    Scene other = makeCanvasScene();
    CHECK_THROWS(other.restore(saved));
}

TEST_CASE("restoring a turned hourglass's snapshot into another scene is refused and leaves it as it was") {
    Scene turned = makeHourglassScene(makeHourglassMask({24, 1.5f, 0.0f}));
    for (int i = 0; i < 20; ++i) turned.step();
    REQUIRE(turned.flip());
    const SceneSnapshot saved = turned.snapshot();
    // Another hourglass, upright and of another height: the turn the snapshot asks for would
    // change its layouts before the sizes are found to differ.
    Scene other = makeHourglassScene(makeHourglassMask({32, 1.5f, 0.0f}));
    for (int i = 0; i < 20; ++i) other.step();
    const std::uint64_t before = other.stateHash();
    const Int3 upperSize = other.grid(GridLevel::Upper).size();
    CHECK_THROWS_AS(other.restore(saved), std::invalid_argument);
    CHECK(other.stateHash() == before);
    CHECK(other.grid(GridLevel::Upper).size() == upperSize);
    CHECK_FALSE(other.flipped());
    other.step(); // and it goes on stepping
    CHECK(other.grainCount() == other.counters().grainsUpper + other.counters().grainsLower);
}
