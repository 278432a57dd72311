// SPDX-License-Identifier: MIT
// Moving bodies (moving_body.hpp, Scene::moveBody): pushes conserve every grain and its id, leave
// no grain inside a body or a wall, never tunnel, and give the same state for any thread count
// and with sleeping on or off; a blade dragged through a bed leaves a trench between two heaps.
#include "sandcore/moving_body.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <vector>

using namespace sandcore;

namespace {

bool same(Int3 a, Int3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// A random scene to dig in: a canvas with a bed of uneven columns, maybe an obstacle, a body and
// a path through the bed, all drawn from one seed.
struct DigCase {
    PhysicsLevel physics = PhysicsLevel::Granular;
    Int3 box{20, 14, 20};
    std::vector<int> columnHeights;  // per column x + sizeX * z
    std::vector<CellBox> obstacles;
    MovingBody body;
    std::vector<Int3> path;          // the anchor's cells after the start
    std::vector<int> turns;          // the heading it turns to at each point reached
    int speed = 1;                   // unit moves per step
};

DigCase randomCase(std::uint32_t seed) {
    std::mt19937 random(seed);
    auto pick = [&](int low, int high) { return std::uniform_int_distribution<int>(low, high)(random); };
    DigCase c;
    c.physics = seed % 2 ? PhysicsLevel::Granular : PhysicsLevel::Classic;
    c.box = {pick(14, 24), pick(10, 16), pick(14, 24)};
    for (int n = 0; n < c.box.x * c.box.z; ++n) c.columnHeights.push_back(pick(1, c.box.y / 2));
    if (pick(0, 1)) {
        const Int3 min{pick(0, c.box.x - 3), 0, pick(0, c.box.z - 3)};
        c.obstacles.push_back({min, {min.x + pick(1, 3), pick(2, c.box.y), min.z + pick(1, 3)}});
    }
    switch (pick(0, 2)) {
    case 0: c.body.shape = makeBladeShape(pick(2, 8), pick(2, 6), pick(1, 2)); break;
    case 1: c.body.shape = makeBoxShape({pick(1, 4), pick(1, 4), pick(1, 4)}); break;
    default: c.body.shape = makeBallShape(pick(1, 5)); break;
    }
    c.body.quarterTurns = pick(0, 3);
    auto randomPoint = [&] { return Int3{pick(0, c.box.x - 1), pick(0, c.box.y / 2), pick(0, c.box.z - 1)}; };
    c.body.position = randomPoint();
    for (int i = pick(2, 5); i > 0; --i) {
        c.path.push_back(randomPoint());
        c.turns.push_back(pick(0, 3));
    }
    c.speed = pick(1, 4);
    return c;
}

Scene buildCase(const DigCase& c, int threads, bool sleeping) {
    StepSettings step;
    step.physics.level = c.physics;
    step.threads = threads;
    step.sleeping = sleeping;
    Scene scene = makeCanvasScene({{c.box.x, 2, c.box.z}, c.box}, step);
    for (const CellBox& box : c.obstacles) scene.addObstacle(GridLevel::Lower, box);
    const CellGrid& grid = scene.grid(GridLevel::Lower);
    for (int z = 0; z < c.box.z; ++z)
        for (int x = 0; x < c.box.x; ++x)
            for (int y = 0; y < c.columnHeights[std::size_t(x + c.box.x * z)]; ++y)
                scene.addGrain(GridLevel::Lower, grid.index(x, y, z));
    return scene;
}

std::vector<std::uint32_t> sortedIdentities(const Scene& scene) {
    std::vector<std::uint32_t> identities = scene.grains().identity;
    std::sort(identities.begin(), identities.end());
    return identities;
}

// Every grain's record names a cell that names it back, and no body cell holds anything but INVALID.
void requireConsistent(const Scene& scene) {
    const GrainStore& grains = scene.grains();
    for (std::uint32_t id = 0; id < grains.size(); ++id)
        REQUIRE(scene.grid(grains.level[id])[grains.place[id].cell] == CellValue(id));
    REQUIRE(scene.grid(GridLevel::Lower).countGrains() + scene.grid(GridLevel::Upper).countGrains() == scene.grainCount());
    for (std::size_t b = 0; b < scene.bodies().size(); ++b)
        for (std::uint32_t n : scene.bodyCells(b)) REQUIRE(scene.grid(GridLevel::Lower)[n] == kInvalid);
    REQUIRE(scene.sweepsMatchCells());
}

// Drives the case's body along its path, `speed` cells a step, and returns the state hash after
// each step, checking conservation and consistency as it goes.
struct CaseRun {
    std::vector<std::uint64_t> hashes; // after each step; empty when the body did not fit at its start
    std::int64_t grainsPushed = 0;
};

CaseRun runCase(const DigCase& c, int threads, bool sleeping) {
    Scene scene = buildCase(c, threads, sleeping);
    const std::vector<std::uint32_t> identities = sortedIdentities(scene);
    std::vector<std::uint64_t> hashes;
    const std::int64_t body = scene.addBody(c.body);
    if (body < 0) return {}; // placed on a wall: nothing to drive (the same for every setting)
    requireConsistent(scene);
    for (std::size_t leg = 0; leg < c.path.size(); ++leg) {
        const Int3 point = c.path[leg];
        for (int guard = 0; guard < 200; ++guard) {
            const BodyMove move = scene.moveBody(std::size_t(body), point, c.speed);
            scene.step();
            hashes.push_back(scene.stateHash());
            requireConsistent(scene);
            REQUIRE(sortedIdentities(scene) == identities);
            if (move.stopped || same(move.reached, point)) break;
        }
        scene.turnBody(std::size_t(body), c.turns[leg]); // turning in place pushes as moving does
        scene.step();
        hashes.push_back(scene.stateHash());
        requireConsistent(scene);
        REQUIRE(sortedIdentities(scene) == identities);
    }
    for (int i = 0; i < 10; ++i) scene.step();
    hashes.push_back(scene.stateHash());
    requireConsistent(scene);
    REQUIRE(sortedIdentities(scene) == identities);
    return {hashes, scene.grainsPushedTotal()};
}

int columnHeight(const Scene& scene, int x, int z) {
    const CellGrid& grid = scene.grid(GridLevel::Lower);
    for (int y = grid.size().y - 1; y >= 0; --y)
        if (grid.at(x, y, z) >= 0) return y + 1;
    return 0;
}

} // namespace

TEST_CASE("random bodies on random paths through random beds, turning on the way, keep every grain and agree on 1, 2 and 4 threads, sleeping or not") {
    int driven = 0;
    for (std::uint32_t seed = 1; seed <= 24; ++seed) {
        CAPTURE(seed);
        const DigCase c = randomCase(seed);
        const CaseRun reference = runCase(c, 1, true);
        if (!reference.hashes.empty() && reference.grainsPushed > 0) ++driven;
        for (int threads : {1, 2, 4})
            for (bool sleeping : {true, false}) {
                if (threads == 1 && sleeping) continue;
                CAPTURE(threads);
                CAPTURE(sleeping);
                const CaseRun run = runCase(c, threads, sleeping);
                REQUIRE(run.hashes == reference.hashes);
                REQUIRE(run.grainsPushed == reference.grainsPushed);
            }
    }
    // Most cases dig: a body on a wall at its start, or one that never meets sand, tests little.
    CHECK(driven >= 16);
}

TEST_CASE("a body pushes the grains in its way, each once, into EMPTY cells outside it") {
    Scene scene = makeSandboxScene({{16, 2, 16}, {16, 12, 16}}, 4);
    const std::int64_t grains = scene.grainCount();
    // A 4-wide blade sunk into the bed from above pushes the 4 x 1 x 4 grains it covers.
    const std::int64_t body = scene.addBody({makeBladeShape(4, 6, 1), {8, 0, 8}, 0});
    REQUIRE(body == 0);
    CHECK(scene.grainsPushedTotal() == 16);
    CHECK(scene.grainCount() == grains);
    requireConsistent(scene);
    const BodyMove move = scene.moveBody(0, {8, 0, 12}, 100);
    CHECK(same(move.reached, {8, 0, 12}));
    CHECK(move.cellsMoved == 4);
    CHECK(move.grainsPushed >= 4 * 4 * 4); // each unit move enters a 4 x 4 face of sand, and what it pushed ahead
    CHECK(scene.grainCount() == grains);
    requireConsistent(scene);
    scene.removeBody(0);
    CHECK(scene.bodies().empty());
    CHECK(scene.grid(GridLevel::Lower).at(8, 0, 12) == kEmpty); // the cells it left are open again
    requireConsistent(scene);
}

TEST_CASE("a blade's pushes stay near it: the sand rises ahead and beside it, or flows under it") {
    const int width = 48, bed = 8, bladeWidth = 12, thickness = 2;
    Scene scene = makeSandboxScene(canvasSettingsForWidth(width), bed);
    REQUIRE(scene.addBody({makeBladeShape(bladeWidth, bed + 4, thickness), {width / 2, bed - 5, 10}, 0}) == 0);
    for (int i = 0; i < 6; ++i) scene.step();
    std::vector<int> before;
    for (int z = 0; z < width; ++z)
        for (int x = 0; x < width; ++x) before.push_back(columnHeight(scene, x, z));
    const BodyMove move = scene.moveBody(0, {width / 2, bed - 5, 11}, 1);
    REQUIRE(move.cellsMoved == 1);
    CHECK(move.grainsPushed >= bladeWidth * 5);
    requireConsistent(scene);
    // The blade now covers z 10..11 (its anchor's z and the cell before it).
    int changed = 0;
    for (int z = 0; z < width; ++z)
        for (int x = 0; x < width; ++x) {
            if (columnHeight(scene, x, z) == before[std::size_t(x + width * z)]) continue;
            ++changed;
            CAPTURE(x);
            CAPTURE(z);
            CHECK(std::abs(x - width / 2) <= bladeWidth / 2 + Scene::kPushReach);
            CHECK(z >= 10 - Scene::kPushReach);
            CHECK(z <= 11 + Scene::kPushReach);
        }
    CHECK(changed > 0);
}

TEST_CASE("a body pressed down into sand, wider than a straight way reaches, still pushes every grain out") {
    Scene scene = makeSandboxScene(canvasSettingsForWidth(48), 6);
    const std::int64_t grains = scene.grainCount();
    const int side = 2 * Scene::kPushReach + 4; // its middle lies further than a walk from its edges
    REQUIRE(scene.addBody({makeBoxShape({side, 2, side}), {24, 8, 24}, 0}) == 0);
    const BodyMove move = scene.moveBody(0, {24, 3, 24}, 100);
    CHECK(same(move.reached, {24, 3, 24}));
    CHECK(move.grainsPushed >= std::int64_t(side) * side * 3);
    CHECK(scene.grainCount() == grains);
    requireConsistent(scene);
}

TEST_CASE("a fast body stops at a wall and leaves no sand inside itself") {
    for (int speed : {3, 7, 50}) {
        CAPTURE(speed);
        Scene scene = makeSandboxScene({{24, 2, 24}, {24, 12, 24}}, 4);
        // A wall one cell thick across the whole box at z = 14.
        scene.addObstacle(GridLevel::Lower, {{0, 0, 14}, {24, 12, 15}});
        const std::int64_t grains = scene.grainCount();
        REQUIRE(scene.addBody({makeBoxShape({4, 4, 3}), {12, 1, 4}, 0}) == 0);
        // Far past the wall: it must stop with its front face against it.
        BodyMove move{};
        for (int i = 0; i < 20 && !move.stopped; ++i) {
            move = scene.moveBody(0, {12, 1, 22}, speed);
            scene.step();
            requireConsistent(scene);
        }
        CHECK(move.stopped);
        CHECK(same(scene.bodies()[0].position, {12, 1, 12})); // cells z 11..13, the wall at 14
        CHECK(scene.grainCount() == grains);
        for (std::uint32_t n : scene.bodyCells(0)) CHECK(scene.grid(GridLevel::Lower).coordinate(n).z < 14);
    }
}

TEST_CASE("a body stops rather than destroy a grain it finds no room for") {
    // A box full to the top: no EMPTY cell anywhere in the lower grid.
    Scene scene = makeSandboxScene({{8, 2, 8}, {8, 6, 8}}, 6);
    const std::int64_t grains = scene.grainCount();
    CHECK(scene.addBody({makeBoxShape({2, 2, 2}), {4, 2, 4}, 0}) == -1);
    CHECK(scene.bodies().empty());
    CHECK(scene.grainCount() == grains);
    requireConsistent(scene);
}

TEST_CASE("a blade dragged across a bed leaves a trench with heaps along both sides") {
    const int width = 48, bed = 8;
    Scene scene = makeSandboxScene(canvasSettingsForWidth(width), bed);
    const std::int64_t grains = scene.grainCount();
    const int bladeWidth = 12, cut = 5; // the blade's bottom 5 layers below the bed's top
    REQUIRE(scene.addBody({makeBladeShape(bladeWidth, bed + 4, 2), {width / 2, bed - cut, 4}, 0}) == 0);
    for (int i = 0; i < 400; ++i) {
        const BodyMove move = scene.moveBody(0, {width / 2, bed - cut, width - 6}, 1);
        scene.step();
        if (move.cellsMoved == 0) break;
    }
    REQUIRE(same(scene.bodies()[0].position, {width / 2, bed - cut, width - 6}));
    scene.removeBody(0);
    for (int i = 0; i < 600 && !scene.settled(); ++i) scene.step();
    CHECK(scene.grainCount() == grains);
    // Along the middle of its way: lower in the blade's track, higher just beside it.
    double track = 0, left = 0, right = 0;
    int columns = 0;
    for (int z = 12; z < width - 14; ++z, ++columns) {
        track += columnHeight(scene, width / 2, z);
        left += columnHeight(scene, width / 2 - bladeWidth / 2 - 2, z);
        right += columnHeight(scene, width / 2 + bladeWidth / 2 + 1, z);
    }
    track /= columns;
    left /= columns;
    right /= columns;
    MESSAGE("trench ", track, ", beside it ", left, " and ", right, " (bed ", bed, ")");
    // The heaps beside it slide partly back in: the trench is shallower than the cut, and the sides
    // stand above the bed.
    CHECK(track < bed - 1.0);
    CHECK(track > bed - cut);
    CHECK(left > bed + 0.25);
    CHECK(right > bed + 0.25);
}

TEST_CASE("bodies: an undo snapshot takes the body back with the sand, and reset keeps it standing") {
    Scene scene = makeSandboxScene({{16, 2, 16}, {16, 12, 16}}, 4);
    REQUIRE(scene.addBody({makeBladeShape(6, 6, 1), {8, 1, 3}, 0}) == 0);
    const SceneSnapshot before = scene.snapshot();
    const std::uint64_t hash = scene.stateHash();
    scene.moveBody(0, {8, 1, 12}, 100);
    scene.step();
    scene.restore(before);
    CHECK(scene.stateHash() == hash);
    CHECK(same(scene.bodies()[0].position, {8, 1, 3}));
    requireConsistent(scene);
    scene.reset();
    requireConsistent(scene);
    CHECK(scene.grid(GridLevel::Lower).at(8, 1, 3) == kInvalid);
}

TEST_CASE("body shapes: blade, box and ball cells, turned a quarter at a time") {
    CHECK(makeBladeShape(5, 3, 1).countInside() == 15);
    CHECK(makeBoxShape({2, 3, 4}).countInside() == 24);
    const InsideMask ball = makeBallShape(5);
    CHECK(ball.at(2, 2, 2));
    CHECK_FALSE(ball.at(0, 0, 0));
    CHECK(makeBallShape(1).countInside() == 1);
    CHECK_THROWS_AS(makeBladeShape(0, 3, 1), std::invalid_argument);
    CHECK_THROWS_AS(makeBallShape(0), std::invalid_argument);
    // A 3-wide blade along x turns into one along z.
    const std::vector<Int3> turned = bodyOffsets(makeBladeShape(3, 1, 1), 1);
    REQUIRE(turned.size() == 3);
    for (const Int3& offset : turned) CHECK(offset.x == 0);
    CHECK(std::minmax({turned[0].z, turned[1].z, turned[2].z}) == std::pair{-1, 1});
}

TEST_CASE("a blade's dig through the sandbox has recorded hashes (granular and classic)") {
    // R7 for digging: the same pushes and the same sand afterwards on every platform and build.
    std::vector<std::uint64_t> hashes;
    std::vector<std::int64_t> pushed;
    for (PhysicsLevel physics : {PhysicsLevel::Granular, PhysicsLevel::Classic}) {
        StepSettings step;
        step.physics.level = physics;
        Scene scene = makeSandboxScene(canvasSettingsForWidth(32), 7, step);
        REQUIRE(scene.addBody({makeBladeShape(8, 10, 2), {16, 3, 4}, 0}) == 0);
        for (int i = 0; i < 60; ++i) {
            scene.moveBody(0, i < 30 ? Int3{16, 3, 26} : Int3{26, 3, 26}, 2);
            if (i == 30) scene.turnBody(0, 1);
            scene.step();
        }
        hashes.push_back(scene.stateHash());
        pushed.push_back(scene.grainsPushedTotal());
    }
    CHECK(hashes[0] == 9186277622045610897ull);
    CHECK(pushed[0] == 2024);
    CHECK(hashes[1] == 17715852765768350900ull);
    CHECK(pushed[1] == 2042);
}
