// SPDX-License-Identifier: MIT
// Scene::movedGrains and SurfaceUpkeep (R12, R13 kept by the step): the list of moved grains
// matches a full comparison of every grain's cell before and after the step, and the flags and
// column normals kept up to date around the changed cells equal a full recompute after every
// step, classic and granular, on 1 and 2 threads, across the hourglass's two grids.
#include "sandcore/inner_grains.hpp"
#include "sandcore/normals.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"
#include "sandcore/surface_upkeep.hpp"
#include "support/scene_fixtures.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <set>
#include <vector>

using namespace sandcore;

namespace {

StepSettings stepSettings(std::uint64_t seed, int threads, bool granular) {
    StepSettings step;
    step.seed = seed;
    step.threads = threads;
    step.physics.level = granular ? PhysicsLevel::Granular : PhysicsLevel::Classic;
    if (granular) step.physics.gravity = 0.3f;
    return step;
}

struct Place {
    GridLevel level;
    std::uint32_t cell;
    friend bool operator==(const Place&, const Place&) = default;
};

std::vector<Place> placesOf(const Scene& scene) {
    std::vector<Place> places;
    for (std::uint32_t id = 0; id < scene.grains().size(); ++id)
        places.push_back({scene.grains().level[id], scene.grains().place[id].cell});
    return places;
}

// Moved = changed cell or grid, or (a transition with no glide) moved in this very step.
void checkMovedGrains(const Scene& scene, const std::vector<Place>& before) {
    const std::vector<std::uint32_t> moved = fixtures::movedIds(scene);
    const std::set<std::uint32_t> listed(moved.begin(), moved.end());
    REQUIRE(listed.size() == moved.size()); // each once
    // movesLastStep counts a grain that fell into the neck row and passed on in the same step twice.
    CHECK(std::int64_t(moved.size()) <= scene.counters().movesLastStep);
    const std::vector<Place> after = placesOf(scene);
    for (std::uint32_t id = 0; id < after.size(); ++id) {
        const bool changed = !(after[id] == before[id]);
        const bool listedHere = listed.count(id) > 0;
        if (changed) REQUIRE_MESSAGE(listedHere, "grain " << id << " changed cells but is not listed");
        if (listedHere) REQUIRE_MESSAGE(changed, "grain " << id << " is listed but kept its cell");
    }
}

void checkUpkeepMatchesFullRecompute(const Scene& scene, const SurfaceUpkeep& upkeep) {
    std::vector<std::uint8_t> inner(scene.grains().size());
    const std::int64_t innerCount = flagInnerGrains(scene, inner);
    REQUIRE(upkeep.innerCount() == innerCount);
    REQUIRE(upkeep.grainCount() == scene.grains().size());
    for (std::uint32_t id = 0; id < scene.grains().size(); ++id)
        REQUIRE_MESSAGE(upkeep.isInner(id) == (inner[id] != 0), "inner flag of grain " << id);
    std::vector<Vec3> normals(scene.grains().size());
    estimateGrainNormals(scene, NormalMethod::ColumnHeights, normals);
    for (std::uint32_t id = 0; id < scene.grains().size(); ++id) {
        const GridLevel level = scene.grains().level[id];
        const Vec3 kept = upkeep.columnNormals(level)[scene.grains().place[id].cell % scene.grid(level).layerSize()];
        REQUIRE_MESSAGE((kept.x == normals[id].x && kept.y == normals[id].y && kept.z == normals[id].z),
                        "normal of grain " << id);
    }
    if (upkeep.tracksGradientNormals()) {
        estimateGrainNormals(scene, NormalMethod::OccupancyGradient, normals);
        for (std::uint32_t id = 0; id < scene.grains().size(); ++id) {
            const Vec3 kept = upkeep.gradientNormal(id);
            REQUIRE_MESSAGE((kept.x == normals[id].x && kept.y == normals[id].y && kept.z == normals[id].z),
                            "gradient normal of grain " << id);
            // Ambient occlusion rides in the same key and must follow the same changes.
            const GridLevel level = scene.grains().level[id];
            const int occupied = occupiedNeighbours(scene.grid(level), scene.grains().place[id].cell);
            REQUIRE_MESSAGE(SurfaceUpkeep::occlusionLevelOfKey(upkeep.gradientKeyOf(id)) == occlusionLevel(occupied),
                            "occlusion level of grain " << id);
        }
    }
    for (GridLevel level : {GridLevel::Lower, GridLevel::Upper}) {
        const std::vector<int> heights = columnHeights(scene.grid(level));
        REQUIRE(std::equal(heights.begin(), heights.end(), upkeep.heights(level).begin(), upkeep.heights(level).end()));
    }
}

// Steps the scene, checking movedGrains and the upkeep after every step; the changed lists name
// every flag and column that differs from the previous step's.
int runAndCheck(Scene& scene, int steps) {
    SurfaceUpkeep upkeep;
    upkeep.setTrackGradientNormals(true);
    upkeep.rebuild(scene);
    int moves = 0;
    for (int i = 0; i < steps; ++i) {
        CAPTURE(i);
        const std::vector<Place> before = placesOf(scene);
        std::vector<bool> flagsBefore;
        for (std::uint32_t id = 0; id < upkeep.grainCount(); ++id) flagsBefore.push_back(upkeep.isInner(id));
        upkeep.clearChanges();
        scene.step();
        checkMovedGrains(scene, before);
        moves += int(scene.movedGrains().size());
        upkeep.update(scene);
        checkUpkeepMatchesFullRecompute(scene, upkeep);
        const std::set<std::uint32_t> changed(upkeep.changedInnerFlags().begin(), upkeep.changedInnerFlags().end());
        REQUIRE(changed.size() == upkeep.changedInnerFlags().size());
        for (std::uint32_t id = 0; id < flagsBefore.size(); ++id)
            REQUIRE((flagsBefore[id] != upkeep.isInner(id)) == (changed.count(id) > 0));
        CHECK(upkeep.movedGrains().size() == scene.movedGrains().size());
        // The places listed for the renderer are the moved grains' records, in the step's order.
        REQUIRE(upkeep.movedPlaceCount() == scene.movedGrains().size());
        REQUIRE(upkeep.placesComplete());
        const GrainStore& grains = scene.grains();
        std::vector<MovedPlace> places;
        upkeep.forEachMovedPlace([&](const MovedPlace& place) { places.push_back(place); });
        REQUIRE(places.size() == scene.movedGrains().size());
        for (std::size_t m = 0; m < places.size(); ++m) {
            const MovedPlace& place = places[m];
            const std::uint32_t id = scene.movedGrains()[m].grain;
            REQUIRE(place.grain == id);
            REQUIRE(place.cell == grains.place[id].cell);
            REQUIRE(place.level == (grains.level[id] == GridLevel::Upper ? 1u : 0u));
            REQUIRE(place.cameFrom == grains.place[id].cameFrom);
            REQUIRE(place.movedStep == std::uint32_t(grains.place[id].movedAtStep));
        }
    }
    return moves;
}

} // namespace

TEST_CASE("moved grains and the kept flags and normals match a full recompute: hourglass, classic, 1 and 2 threads") {
    for (int threads : {1, 2}) {
        CAPTURE(threads);
        Scene scene = makeHourglassScene(makeHourglassMask({28, 2.0f, 0.0f}), {}, stepSettings(7, threads, false));
        // Long enough for sand to pass the neck into the lower grid and pile up there.
        CHECK(runAndCheck(scene, 120) > 0);
        CHECK(scene.counters().grainsLower > 0);
    }
}

TEST_CASE("moved grains and the kept flags and normals match a full recompute: granular hourglass and sculpture") {
    for (int threads : {1, 2}) {
        CAPTURE(threads);
        Scene hourglass = makeHourglassScene(makeHourglassMask({28, 2.0f, 0.0f}), {}, stepSettings(3, threads, true));
        CHECK(runAndCheck(hourglass, 100) > 0);
        CHECK(hourglass.counters().grainsLower > 0);
        Scene sculpture = makeSculptureScene(makeSphereMask(16), stepSettings(5, threads, true));
        CHECK(runAndCheck(sculpture, 60) > 0);
    }
}

TEST_CASE("moved grains: the same list for 1 and 2 threads, empty once settled and after a reset") {
    Scene one = makeSculptureScene(makeSphereMask(18), stepSettings(11, 1, false));
    Scene two = makeSculptureScene(makeSphereMask(18), stepSettings(11, 2, false));
    for (int i = 0; i < 40; ++i) {
        one.step();
        two.step();
        std::vector<std::uint32_t> a = fixtures::movedIds(one);
        std::vector<std::uint32_t> b = fixtures::movedIds(two);
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        REQUIRE(a == b);
        REQUIRE(one.stateHash() == two.stateHash());
    }
    CHECK(!one.movedGrains().empty());
    while (!two.settled()) two.step();
    CHECK(two.movedGrains().empty());
    two.reset();
    CHECK(two.movedGrains().empty());
}

TEST_CASE("surface upkeep: a painted grain is caught by rebuild, and update rebuilds when the count changed") {
    Scene scene = makeCanvasScene({{12, 4, 12}, {12, 8, 12}});
    SurfaceUpkeep upkeep;
    upkeep.rebuild(scene);
    for (int i = 0; i < 30; ++i) {
        scene.addGrain(GridLevel::Upper, pourCell(scene));
        scene.step();
        upkeep.update(scene); // the count changed: a rebuild, still exact
        checkUpkeepMatchesFullRecompute(scene, upkeep);
    }
}

namespace {

// A canvas with columns of grains in the air: they fall, each grain entering the cell the grain
// below it left in the same step.
Scene canvasWithColumn(GridLevel level, int x, int z, int yFrom, int yTo) {
    Scene scene = makeCanvasScene({{12, 4, 12}, {12, 10, 12}}, stepSettings(1, 1, false));
    const CellGrid& grid = scene.grid(level);
    for (int y = yFrom; y <= yTo; ++y) scene.addGrain(level, grid.index(x, y, z));
    return scene;
}

// A column that reaches from the upper grid's layer 2 down into the lower grid's top rows, so
// grains leave the upper grid's bottom row (the shared row) as others enter it, in one step; and a
// second column one cell over, resting on nothing, in the upper grid only.
Scene canvasWithSeamColumns(int threads = 1) {
    Scene scene = makeCanvasScene({{12, 4, 12}, {12, 10, 12}}, stepSettings(1, threads, false));
    const CellGrid& upper = scene.grid(GridLevel::Upper);
    const CellGrid& lower = scene.grid(GridLevel::Lower);
    for (int y = 0; y <= 2; ++y) scene.addGrain(GridLevel::Upper, upper.index(5, y, 6));
    for (int y = 6; y <= 8; ++y) scene.addGrain(GridLevel::Lower, lower.index(5, y, 6));
    for (int y = 0; y <= 3; ++y) scene.addGrain(GridLevel::Upper, upper.index(6, y, 6));
    return scene;
}

} // namespace

TEST_CASE("surface upkeep: a falling column moves every grain but changes two cells, and stays exact") {
    Scene scene = canvasWithColumn(GridLevel::Lower, 5, 6, 4, 8); // 5 grains, 4 cells above the floor
    SurfaceUpkeep upkeep;
    upkeep.setTrackGradientNormals(true);
    upkeep.rebuild(scene);
    CHECK(upkeep.netChangesLastUpdate() == 0);
    for (int step = 0; step < 3; ++step) {
        CAPTURE(step);
        upkeep.clearChanges();
        scene.step();
        upkeep.update(scene);
        REQUIRE(scene.movedGrains().size() == 5); // the whole column, one cell down
        CHECK(upkeep.netChangesLastUpdate() == 2); // its bottom filled, its top emptied
        CHECK(upkeep.movedGrains().size() == 5);
        // Every moved grain has a new neighbourhood: its flag and normal were looked at again.
        checkUpkeepMatchesFullRecompute(scene, upkeep);
    }
    while (!scene.settled()) {
        scene.step();
        upkeep.update(scene);
        checkUpkeepMatchesFullRecompute(scene, upkeep);
    }
}

TEST_CASE("surface upkeep: columns falling through the seam from the upper grid into the lower stay exact") {
    Scene scene = canvasWithSeamColumns();
    CHECK(runAndCheck(scene, 25) > 0);
    CHECK(scene.counters().grainsUpper == 0); // every grain crossed the seam
}

TEST_CASE("surface upkeep: net changes in the hourglass are far fewer than the cells its moves touch") {
    Scene scene = makeHourglassScene(makeHourglassMask({40, 2.0f, 0.0f}), {}, stepSettings(9, 1, false));
    for (int i = 0; i < 60; ++i) scene.step(); // a funnel forms over the neck
    SurfaceUpkeep upkeep;
    upkeep.setTrackGradientNormals(true);
    upkeep.rebuild(scene);
    std::size_t moved = 0, net = 0;
    for (int i = 0; i < 20; ++i) {
        scene.step();
        upkeep.update(scene);
        moved += scene.movedGrains().size();
        net += upkeep.netChangesLastUpdate();
    }
    checkUpkeepMatchesFullRecompute(scene, upkeep);
    CHECK(moved > 0);
    CHECK(net < moved); // a move fills one cell and empties one: 2 * moved without the net view
}

namespace {

// Without per-grain flags (what the GPU path asks for): the bits are the grids' occupancy, the
// inner count is flagInnerGrains', the changed cells name every cell whose bits changed, and the
// column heights and normals, when kept, equal a full recompute.
int runBitsOnlyAndCheck(Scene& scene, int steps, bool columns) {
    SurfaceUpkeep upkeep;
    upkeep.setTracking({false, false, columns});
    upkeep.rebuild(scene);
    int netChanges = 0;
    for (int i = 0; i < steps; ++i) {
        CAPTURE(i);
        std::vector<std::uint8_t> before[2];
        for (GridLevel level : {GridLevel::Lower, GridLevel::Upper}) {
            const CellGrid& grid = scene.grid(level);
            for (std::uint32_t n = 0; n < grid.cellCount(); ++n) before[int(level == GridLevel::Upper)].push_back(grid[n] >= 0);
        }
        upkeep.clearChanges();
        scene.step();
        upkeep.update(scene);
        std::vector<std::uint8_t> inner(scene.grains().size());
        REQUIRE(upkeep.innerCount() == flagInnerGrains(scene, inner));
        REQUIRE(upkeep.movedPlaceCount() == scene.movedGrains().size());
        std::set<std::pair<int, std::uint32_t>> listed;
        for (const CellRef& ref : upkeep.changedCells()) listed.insert({int(ref.level == GridLevel::Upper), ref.cell});
        for (GridLevel level : {GridLevel::Lower, GridLevel::Upper}) {
            const CellGrid& grid = scene.grid(level);
            const int g = int(level == GridLevel::Upper);
            for (std::uint32_t n = 0; n < grid.cellCount(); ++n) {
                REQUIRE(upkeep.grainBits(level).test(n) == (grid[n] >= 0));
                REQUIRE(upkeep.hideBits(level).test(n) == (grid[n] != kEmpty));
                if ((grid[n] >= 0) != (before[g][n] != 0)) REQUIRE_MESSAGE(listed.count({g, n}) == 1, "changed cell " << n);
            }
            if (!columns) continue;
            const std::vector<int> heights = columnHeights(grid);
            REQUIRE(std::equal(heights.begin(), heights.end(), upkeep.heights(level).begin(), upkeep.heights(level).end()));
            const Int3 s = grid.size();
            for (int z = 0; z < s.z; ++z)
                for (int x = 0; x < s.x; ++x) {
                    const Vec3 full = columnNormal(heights, s, x, z);
                    const Vec3 kept = upkeep.columnNormals(level)[std::size_t(x) + std::size_t(s.x) * std::size_t(z)];
                    REQUIRE((kept.x == full.x && kept.y == full.y && kept.z == full.z));
                }
        }
        netChanges += int(upkeep.netChangesLastUpdate());
    }
    return netChanges;
}

} // namespace

TEST_CASE("surface upkeep without per-grain flags: bits, changed cells and inner count exact, classic and granular, 1 and 2 threads") {
    for (bool granular : {false, true})
        for (int threads : {1, 2}) {
            CAPTURE(granular);
            CAPTURE(threads);
            Scene scene = makeHourglassScene(makeHourglassMask({28, 2.0f, 0.0f}), {}, stepSettings(13, threads, granular));
            CHECK(runBitsOnlyAndCheck(scene, 110, threads == 2) > 0);
            CHECK(scene.counters().grainsLower > 0); // the seam was crossed
        }
}

TEST_CASE("surface upkeep without per-grain flags: columns through the seam and a sculpture stay exact") {
    // On 2 threads each grid's share of the update runs on its own, and a grain that fell from
    // the upper grid into the lower grid's top row left a cell in the grid the other thread owns.
    for (int threads : {1, 2}) {
        CAPTURE(threads);
        Scene scene = canvasWithSeamColumns(threads);
        const CellGrid& upper = scene.grid(GridLevel::Upper);
        for (int y = 0; y <= 3; ++y) scene.addGrain(GridLevel::Upper, upper.index(0, y, 0)); // at the grid's corner
        CHECK(runBitsOnlyAndCheck(scene, 25, true) > 0);
        CHECK(scene.counters().grainsUpper == 0);
    }
    Scene sculpture = makeSculptureScene(makeSphereMask(16), stepSettings(5, 1, false));
    CHECK(runBitsOnlyAndCheck(sculpture, 40, false) > 0);
}

TEST_CASE("surface upkeep: the places of several steps between two clears, retained before each step, end in every grain's place") {
    for (bool granular : {false, true}) {
        CAPTURE(granular);
        Scene scene = makeHourglassScene(makeHourglassMask({28, 2.0f, 0.0f}), {}, stepSettings(9, 1, granular));
        for (int i = 0; i < 30; ++i) scene.step(); // sand on the way through the neck
        SurfaceUpkeep upkeep;
        upkeep.setTracking({false, false, false});
        upkeep.rebuild(scene);
        upkeep.clearChanges();
        // A mirror of every grain's place, as a renderer keeps it, brought up to date from the
        // listed places only.
        std::vector<MovedPlace> mirror(scene.grains().size());
        auto mirrorOf = [&](std::uint32_t id) {
            const GrainStore& grains = scene.grains();
            return MovedPlace{id, grains.place[id].cell, grains.level[id] == GridLevel::Upper ? 1u : 0u,
                              grains.place[id].cameFrom, std::uint32_t(grains.place[id].movedAtStep)};
        };
        for (std::uint32_t id = 0; id < mirror.size(); ++id) mirror[id] = mirrorOf(id);
        std::size_t moves = 0;
        for (int frame = 0; frame < 12; ++frame) {
            const int steps = 1 + frame % 3;
            for (int s = 0; s < steps; ++s) {
                if (s > 0) upkeep.retainMoves();
                scene.step();
                moves += scene.movedGrains().size();
                upkeep.update(scene);
            }
            REQUIRE(upkeep.placesComplete());
            upkeep.forEachMovedPlace([&](const MovedPlace& place) { mirror[place.grain] = place; });
            upkeep.clearChanges();
            REQUIRE(upkeep.movedPlaceCount() == 0);
            for (std::uint32_t id = 0; id < mirror.size(); ++id) {
                const MovedPlace expected = mirrorOf(id);
                REQUIRE(mirror[id].cell == expected.cell);
                REQUIRE(mirror[id].level == expected.level);
                REQUIRE(mirror[id].cameFrom == expected.cameFrom);
                REQUIRE(mirror[id].movedStep == expected.movedStep);
            }
        }
        CHECK(moves > 0);
        // Stepping again without retaining loses the earlier step's places, and says so.
        scene.step();
        upkeep.update(scene);
        REQUIRE(upkeep.movedPlaceCount() > 0);
        scene.step();
        upkeep.update(scene);
        CHECK_FALSE(upkeep.placesComplete());
        upkeep.clearChanges();
        CHECK(upkeep.placesComplete());
    }
}

TEST_CASE("surface upkeep: places shared out among the scene's threads end in every grain's place") {
    // Big enough that a step moves more grains than one thread takes alone; frames of 1 to 3
    // steps, so earlier steps' places come first and a grain moved twice ends in its last place.
    Scene scene = makeHourglassScene(makeHourglassMask({72, 4.0f, 0.0f}), {}, stepSettings(5, 2, false));
    REQUIRE(scene.workers() != nullptr);
    for (int i = 0; i < 60; ++i) scene.step();
    SurfaceUpkeep upkeep;
    upkeep.setTracking({false, false, false});
    upkeep.rebuild(scene);
    upkeep.clearChanges();
    std::vector<std::uint32_t> cells(scene.grains().size()), steps(scene.grains().size());
    for (std::uint32_t id = 0; id < cells.size(); ++id) {
        cells[id] = scene.grains().place[id].cell;
        steps[id] = std::uint32_t(scene.grains().place[id].movedAtStep);
    }
    std::size_t largest = 0;
    for (int frame = 0; frame < 9; ++frame) {
        for (int s = 0; s < 1 + frame % 3; ++s) {
            if (s > 0) upkeep.retainMoves();
            scene.step();
            largest = std::max(largest, scene.movedGrains().size());
            upkeep.update(scene);
        }
        std::atomic<std::size_t> written{0};
        upkeep.forEachMovedPlace(scene.workers(), [&](const MovedPlace& place) {
            cells[place.grain] = place.cell;
            steps[place.grain] = place.movedStep;
            written.fetch_add(1, std::memory_order_relaxed);
        });
        REQUIRE(written.load() == upkeep.movedPlaceCount());
        upkeep.clearChanges();
        for (std::uint32_t id = 0; id < cells.size(); ++id) {
            REQUIRE(cells[id] == scene.grains().place[id].cell);
            REQUIRE(steps[id] == std::uint32_t(scene.grains().place[id].movedAtStep));
        }
    }
    CHECK(largest >= 2048); // shared out (SurfaceUpkeep shares 2048 places and more)
}
