// SPDX-License-Identifier: MIT
// R2/R3/R4 on small hand-built grids with exact expected contents.
#include "support/scene_fixtures.hpp"

#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <map>

using namespace sandcore;
using fixtures::boxScene;
using fixtures::lowerAt;
using fixtures::putLower;

TEST_CASE("fall: a grain drops one cell per step and rests on the floor") {
    Scene scene = boxScene({3, 4, 3});
    const auto id = putLower(scene, 1, 3, 1);
    for (int y = 2; y >= 0; --y) {
        scene.step();
        CHECK(lowerAt(scene, 1, y, 1) == id);
        CHECK(lowerAt(scene, 1, y + 1, 1) == kEmpty);
        CHECK(scene.counters().movesLastStep == 1);
    }
    scene.step();
    CHECK(lowerAt(scene, 1, 0, 1) == id);
    CHECK(scene.counters().movesLastStep == 0);
    CHECK(scene.settled());
}

TEST_CASE("slip: a grain on a grain moves to the only empty successor") {
    // Floor layer: everything filled or INVALID except (2, 0, 1).
    std::vector<Int3> invalid = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 2}, {1, 0, 2}, {2, 0, 2}};
    Scene scene = boxScene({3, 3, 3}, 1, invalid);
    putLower(scene, 0, 0, 1);
    putLower(scene, 1, 0, 1);
    const auto top = putLower(scene, 1, 1, 1);
    scene.step();
    CHECK(lowerAt(scene, 2, 0, 1) == top);
    CHECK(lowerAt(scene, 1, 1, 1) == kEmpty);
    for (const Int3& c : invalid) CHECK(lowerAt(scene, c.x, c.y, c.z) == kInvalid);
}

TEST_CASE("slip never enters INVALID: with every successor INVALID or full the grain stays") {
    std::vector<Int3> invalid;
    for (int z = 0; z < 3; ++z)
        for (int x = 0; x < 3; ++x)
            if (!(x == 1 && z == 1)) invalid.push_back({x, 0, z});
    Scene scene = boxScene({3, 3, 3}, 1, invalid);
    const auto support = putLower(scene, 1, 0, 1);
    const auto top = putLower(scene, 1, 1, 1);
    for (int i = 0; i < 5; ++i) scene.step();
    CHECK(lowerAt(scene, 1, 1, 1) == top);
    CHECK(lowerAt(scene, 1, 0, 1) == support);
    for (const Int3& c : invalid) CHECK(lowerAt(scene, c.x, c.y, c.z) == kInvalid);
}

TEST_CASE("slip picks each empty successor, uniformly over seeds") {
    std::map<std::pair<int, int>, int> landed;
    const int trials = 4000;
    for (int seed = 1; seed <= trials; ++seed) {
        Scene scene = boxScene({3, 2, 3}, 1, {}, std::uint64_t(seed));
        putLower(scene, 1, 0, 1);
        const auto top = putLower(scene, 1, 1, 1);
        scene.step();
        const Int3 c = scene.grid(GridLevel::Lower).coordinate(scene.grains().place[std::size_t(top)].cell);
        REQUIRE(c.y == 0);
        ++landed[{c.x, c.z}];
    }
    CHECK(landed.size() == 8); // every one of the 8 empty successors, never the full one below
    CHECK(landed.count({1, 1}) == 0);
    for (const auto& [cell, count] : landed) {
        CHECK(count > trials / 8 * 3 / 4); // 500 expected each; a 25% band is > 6 sigma
        CHECK(count < trials / 8 * 5 / 4);
    }
}

TEST_CASE("grid edges: a grain in a corner only slips to successors inside the box") {
    for (int seed = 1; seed <= 200; ++seed) {
        Scene scene = boxScene({3, 2, 3}, 1, {}, std::uint64_t(seed));
        putLower(scene, 0, 0, 0);
        const auto top = putLower(scene, 0, 1, 0);
        scene.step();
        const Int3 c = scene.grid(GridLevel::Lower).coordinate(scene.grains().place[std::size_t(top)].cell);
        CHECK(c.y == 0);
        CHECK(c.x <= 1);
        CHECK(c.z <= 1);
        CHECK(!(c.x == 0 && c.z == 0));
    }
}

TEST_CASE("a falling column moves down together in one step") {
    Scene scene = boxScene({1, 8, 1});
    std::vector<std::int64_t> ids;
    for (int y = 3; y < 8; ++y) ids.push_back(putLower(scene, 0, y, 0));
    scene.step();
    for (int i = 0; i < 5; ++i) CHECK(lowerAt(scene, 0, 2 + i, 0) == ids[std::size_t(i)]);
    CHECK(lowerAt(scene, 0, 7, 0) == kEmpty);
    CHECK(scene.counters().movesLastStep == 5);
}

TEST_CASE("a step never moves a grain twice") {
    Scene scene = boxScene({5, 10, 5});
    const auto id = putLower(scene, 2, 9, 2);
    for (int step = 1; step <= 9; ++step) {
        scene.step();
        const Int3 c = scene.grid(GridLevel::Lower).coordinate(scene.grains().place[std::size_t(id)].cell);
        CHECK(c.y == 9 - step);
        CHECK(scene.grains().place[std::size_t(id)].movedAtStep == std::uint64_t(step));
    }
}

TEST_CASE("transition moves exactly the grains of the shared row whose lower cell is EMPTY") {
    Scene scene = boxScene({3, 3, 3}, 3);
    const CellGrid& upper = scene.grid(GridLevel::Upper);
    // Upper bottom row: grains at (0,0,0) and (2,0,2); a grain one layer up at (1,1,1).
    const auto a = scene.addGrain(GridLevel::Upper, upper.index(0, 0, 0));
    const auto b = scene.addGrain(GridLevel::Upper, upper.index(2, 0, 2));
    const auto c = scene.addGrain(GridLevel::Upper, upper.index(1, 2, 1));
    // The lower top-row cell under b is blocked by an INVALID obstacle.
    scene.addObstacle(GridLevel::Lower, {{2, 2, 2}, {3, 3, 3}});
    scene.step();
    const CellGrid& lower = scene.grid(GridLevel::Lower);
    CHECK(scene.grains().level[std::size_t(a)] == GridLevel::Lower);
    CHECK(scene.grains().place[std::size_t(a)].cell == lower.index(0, 2, 0));
    CHECK(upper.at(0, 0, 0) == kEmpty);
    CHECK(upper.at(2, 0, 2) == b); // blocked: stays in the upper grid
    CHECK(upper.at(1, 1, 1) == c); // fell one layer, not into the lower grid
    CHECK(scene.counters().grainsUpper == 2);
    CHECK(scene.counters().grainsLower == 1);
    CHECK(scene.grainCount() == 3);
}

TEST_CASE("transition keeps the world position of the grain") {
    Scene scene = boxScene({2, 4, 2}, 2);
    const CellGrid& upper = scene.grid(GridLevel::Upper);
    const auto id = scene.addGrain(GridLevel::Upper, upper.index(1, 0, 1));
    const Int3 before = scene.gridOrigin(GridLevel::Upper);
    scene.step();
    const Int3 cell = scene.grid(GridLevel::Lower).coordinate(scene.grains().place[std::size_t(id)].cell);
    const Int3 origin = scene.gridOrigin(GridLevel::Lower);
    CHECK(before.y == 3); // the upper grid's bottom row is the lower grid's top row
    CHECK(cell.y + origin.y == 0 + before.y);
    CHECK(cell.x == 1);
    CHECK(cell.z == 1);
    CHECK(scene.grains().place[std::size_t(id)].cameFrom == kNoMove);
}

TEST_CASE("a grain that falls into the shared row and passes to the lower grid in one step still glides") {
    Scene scene = boxScene({3, 4, 3}, 3);
    const CellGrid& upper = scene.grid(GridLevel::Upper);
    const auto id = std::size_t(scene.addGrain(GridLevel::Upper, upper.index(1, 1, 1)));
    scene.step(); // (1,1,1) -> (1,0,1) in the upper grid, then the transition into the lower grid
    CHECK(scene.grains().level[id] == GridLevel::Lower);
    CHECK(scene.grains().place[id].movedAtStep == 1);
    CHECK(scene.grains().place[id].cameFrom == packMove(0, 1, 0)); // it came from one cell above, in world terms
}
