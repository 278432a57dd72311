// SPDX-License-Identifier: MIT
// Turning the hourglass over (T1): an exact mirror in y, every grain kept with its identity and
// colour, the identity after two turns, and exactness of the steps that follow.
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <map>
#include <tuple>

using namespace sandcore;

namespace {

// An hourglass whose bulbs differ: a wide box over a narrow neck over a low, wider box,
// off-centre in x, so a mirror is not the same shape.
InsideMask lopsidedVessel() {
    InsideMask mask = InsideMask::empty({20, 30, 16});
    for (int y = 0; y < 30; ++y)
        for (int z = 0; z < 16; ++z)
            for (int x = 0; x < 20; ++x) {
                const bool lowerBulb = y < 8 && x >= 1 && x < 19 && z >= 1 && z < 15;
                const bool neck = y >= 8 && y < 12 && x >= 8 && x < 11 && z >= 7 && z < 9;
                const bool upperBulb = y >= 12 && y < 29 && x >= 4 && x < 14 && z >= 3 && z < 13;
                mask.set(x, y, z, lowerBulb || neck || upperBulb);
            }
    return mask;
}

Scene lopsided(int threads = 1, bool sleeping = true) {
    StepSettings step;
    step.seed = 3;
    step.threads = threads;
    step.sleeping = sleeping;
    return makeHourglassScene(lopsidedVessel(), {}, step);
}

// World position (x, world y, z) -> (identity, colour) of every grain.
std::map<std::tuple<int, int, int, int>, std::pair<std::uint32_t, std::uint32_t>> grainsByWorldCell(const Scene& scene) {
    std::map<std::tuple<int, int, int, int>, std::pair<std::uint32_t, std::uint32_t>> out;
    const GrainStore& grains = scene.grains();
    for (std::uint32_t id = 0; id < grains.size(); ++id) {
        const GridLevel level = grains.level[id];
        const Int3 c = scene.grid(level).coordinate(grains.place[id].cell);
        const int worldY = c.y + scene.gridOrigin(level).y;
        out[{c.x, worldY, c.z, int(level)}] = {grains.identity[id], grains.color[id]};
    }
    return out;
}

int worldHeight(const Scene& scene) {
    return scene.grid(GridLevel::Upper).size().y + scene.grid(GridLevel::Lower).size().y - 1;
}

} // namespace

TEST_CASE("flip: the sand becomes the exact mirror in y, every grain keeps its identity and colour") {
    Scene scene = lopsided();
    for (int i = 0; i < 40; ++i) scene.step(); // some sand below, some above, some in flight
    scene.addGrain(GridLevel::Lower, scene.grid(GridLevel::Lower).index(2, 0, 2), 0xff0000ffu); // a red one
    const auto before = grainsByWorldCell(scene);
    const std::int64_t upper = scene.counters().grainsUpper, lower = scene.counters().grainsLower;
    const int height = worldHeight(scene);
    REQUIRE(upper > 0);
    REQUIRE(lower > 0);

    REQUIRE(scene.flip());
    CHECK(scene.flipped());
    CHECK(worldHeight(scene) == height);
    CHECK(scene.counters().grainsUpper == lower);
    CHECK(scene.counters().grainsLower == upper);
    const auto after = grainsByWorldCell(scene);
    REQUIRE(after.size() == before.size());
    for (const auto& [where, grain] : before) {
        const auto [x, y, z, level] = where;
        const int otherLevel = level == int(GridLevel::Upper) ? int(GridLevel::Lower) : int(GridLevel::Upper);
        const auto mirrored = after.find({x, height - 1 - y, z, otherLevel});
        REQUIRE(mirrored != after.end());
        CHECK(mirrored->second == grain);
    }
    // Every grain sits in a cell of its grid that holds its id, never in an INVALID cell.
    const GrainStore& grains = scene.grains();
    for (std::uint32_t id = 0; id < grains.size(); ++id)
        CHECK(scene.grid(grains.level[id])[grains.place[id].cell] == CellValue(id));
}

TEST_CASE("flip: two flips with no step between give back the same state") {
    Scene scene = lopsided();
    for (int i = 0; i < 150; ++i) scene.step();
    const std::uint64_t hash = scene.stateHash();
    const auto grains = grainsByWorldCell(scene);
    REQUIRE(scene.flip());
    CHECK(scene.stateHash() != hash);
    REQUIRE(scene.flip());
    CHECK_FALSE(scene.flipped());
    CHECK(scene.stateHash() == hash);
    CHECK(grainsByWorldCell(scene) == grains);
}

TEST_CASE("flip: a flip mid-drain keeps every grain, sends the sand back up, and it drains again") {
    Scene scene = makeHourglassScene(makeHourglassMask({48, 2.0f, 0.0f}));
    const std::int64_t grains = scene.grainCount();
    for (int i = 0; i < 20'000 && scene.counters().grainsLower <= scene.counters().grainsUpper; ++i) scene.step();
    REQUIRE(scene.counters().grainsLower > scene.counters().grainsUpper);
    const std::int64_t lowerBefore = scene.counters().grainsLower;
    REQUIRE(scene.flip());
    CHECK(scene.counters().grainsUpper == lowerBefore);
    int steps = 0;
    while (!scene.settled() && steps < 20000) {
        scene.step();
        ++steps;
    }
    CHECK(scene.settled());
    CHECK(scene.counters().grainsUpper == 0);
    CHECK(scene.grainCount() == grains);
    CHECK(scene.grid(GridLevel::Upper).countGrains() + scene.grid(GridLevel::Lower).countGrains() == grains);
}

TEST_CASE("flip: after a turn, sleeping equals a full sweep and two threads equal one") {
    Scene reference = lopsided(1, true), fullSweep = lopsided(1, false), threaded = lopsided(2, true);
    for (Scene* scene : {&reference, &fullSweep, &threaded}) {
        for (int i = 0; i < 120; ++i) scene->step();
        REQUIRE(scene->flip());
        for (int i = 0; i < 200; ++i) scene->step();
    }
    CHECK(fullSweep.stateHash() == reference.stateHash());
    CHECK(threaded.stateHash() == reference.stateHash());
}

TEST_CASE("flip: reset turns the hourglass upright and refills it, and sculptures and canvases do not turn") {
    Scene scene = lopsided();
    const std::uint64_t fresh = scene.stateHash();
    for (int i = 0; i < 60; ++i) scene.step();
    REQUIRE(scene.flip());
    scene.reset();
    CHECK_FALSE(scene.flipped());
    CHECK(scene.stateHash() == fresh);

    Scene canvas = makeCanvasScene();
    const std::uint64_t canvasHash = canvas.stateHash();
    CHECK_FALSE(canvas.flip());
    CHECK(canvas.stateHash() == canvasHash);
}

TEST_CASE("clone: an independent copy with the same state and the same future, turned or not") {
    Scene scene = lopsided();
    for (int i = 0; i < 70; ++i) scene.step();
    REQUIRE(scene.flip());
    Scene copy = scene.clone();
    CHECK(copy.flipped());
    CHECK(copy.stateHash() == scene.stateHash());
    for (int i = 0; i < 90; ++i) {
        scene.step();
        copy.step();
    }
    CHECK(copy.stateHash() == scene.stateHash());
    copy.step();
    CHECK(copy.counters().stepsDone == scene.counters().stepsDone + 1);
}
