// SPDX-License-Identifier: MIT
// SPEC H3: properties over thousands of random small cases. Each case is made from one seed;
// a failure prints it (CAPTURE), and setting SANDGLASS_PROPERTY_SEED replays that case alone.
#include "sandcore/mesh_shapes.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"
#include "sandcore/voxelizer.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <random>
#include <string>

using namespace sandcore;

namespace {

// The seeds to run: [first, first + count), or the one in SANDGLASS_PROPERTY_SEED.
std::vector<std::uint64_t> caseSeeds(std::uint64_t first, int count) {
    if (const char* one = std::getenv("SANDGLASS_PROPERTY_SEED")) return {std::strtoull(one, nullptr, 10)};
    std::vector<std::uint64_t> seeds;
    for (int i = 0; i < count; ++i) seeds.push_back(first + std::uint64_t(i));
    return seeds;
}

int uniform(std::mt19937_64& random, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); }

// A random blob: a union of a few random boxes and spheres in a small box.
InsideMask randomMask(std::mt19937_64& random) {
    const Int3 size{uniform(random, 3, 9), uniform(random, 3, 9), uniform(random, 3, 9)};
    InsideMask mask = InsideMask::empty(size);
    const int parts = uniform(random, 1, 3);
    for (int p = 0; p < parts; ++p) {
        const int cx = uniform(random, 0, size.x - 1), cy = uniform(random, 0, size.y - 1), cz = uniform(random, 0, size.z - 1);
        const int r = uniform(random, 1, 3);
        for (int y = 0; y < size.y; ++y)
            for (int z = 0; z < size.z; ++z)
                for (int x = 0; x < size.x; ++x)
                    if (std::abs(x - cx) + std::abs(y - cy) + std::abs(z - cz) <= r + 1) mask.set(x, y, z, true);
    }
    return mask;
}

Scene randomScene(std::uint64_t caseSeed, const StepSettings& step) {
    std::mt19937_64 random(caseSeed);
    StepSettings settings = step;
    settings.seed = random();
    switch (uniform(random, 0, 2)) {
    case 0: {
        const int x = uniform(random, 3, 10), z = uniform(random, 3, 10);
        return makeCanvasScene({{x, uniform(random, 2, 4), z}, {x, uniform(random, 3, 10), z}}, settings);
    }
    case 1: return makeSculptureScene(randomMask(random), settings);
    default: {
        const float neck = 1.0f + float(uniform(random, 0, 10)) / 10.0f;
        HourglassSettings hourglass;
        hourglass.fillFraction = 0.3f + 0.1f * float(uniform(random, 0, 6));
        return makeHourglassScene(makeHourglassMask({uniform(random, 10, 18), neck, 0.0f}), hourglass, settings);
    }
    }
}

// Cells that the layout marks INVALID: taken right after construction, before any obstacle.
struct InvalidCells {
    std::vector<char> upper, lower;
};

InvalidCells invalidCellsOf(const Scene& scene) {
    InvalidCells out;
    for (GridLevel level : {GridLevel::Upper, GridLevel::Lower}) {
        auto& into = level == GridLevel::Upper ? out.upper : out.lower;
        for (CellValue v : scene.grid(level).cells()) into.push_back(v == kInvalid);
    }
    return out;
}

// Exact conservation and no grain where none may be, checked on one scene; what is wrong, or
// empty. (One REQUIRE per check rather than per cell keeps the test fast under ASan.)
std::string invariantProblem(const Scene& scene, const InvalidCells& layout, std::int64_t expectedGrains) {
    if (scene.grainCount() != expectedGrains)
        return std::to_string(scene.grainCount()) + " grains, expected " + std::to_string(expectedGrains);
    std::vector<char> seen(std::size_t(scene.grainCount()), 0);
    std::int64_t filled[2] = {0, 0};
    for (GridLevel level : {GridLevel::Upper, GridLevel::Lower}) {
        const CellGrid& grid = scene.grid(level);
        const auto& invalid = level == GridLevel::Upper ? layout.upper : layout.lower;
        std::vector<char> blocked(invalid.begin(), invalid.end());
        for (const CellBox& box : scene.obstacles(level))
            for (int y = std::max(box.min.y, 0); y < std::min(box.max.y, grid.size().y); ++y)
                for (int z = std::max(box.min.z, 0); z < std::min(box.max.z, grid.size().z); ++z)
                    for (int x = std::max(box.min.x, 0); x < std::min(box.max.x, grid.size().x); ++x)
                        blocked[grid.index(x, y, z)] = 1;
        for (std::uint32_t n = 0; n < grid.cellCount(); ++n) {
            const CellValue v = grid[n];
            if (blocked[n] && v != kInvalid) return "cell " + std::to_string(n) + " is INVALID by layout or obstacle but holds " + std::to_string(v);
            if (v >= 0) {
                if (v >= scene.grainCount()) return "grain id " + std::to_string(v) + " out of range";
                if (seen[std::size_t(v)]) return "grain " + std::to_string(v) + " in two cells";
                seen[std::size_t(v)] = 1;
                ++filled[level == GridLevel::Upper ? 0 : 1];
            }
        }
    }
    if (filled[0] + filled[1] != expectedGrains) return "filled cells differ from the grain count";
    if (scene.counters().grainsUpper != filled[0] || scene.counters().grainsLower != filled[1])
        return "the counters differ from the grids";
    return {};
}

} // namespace

namespace {

// Random scenes under `physics`, random edits and steps; after each operation every scene keeps
// its invariants, the three agree, and the sweeps' kept cells agree with the grids.
void checkRandomScenesAndEdits(const PhysicsSettings& physics, std::uint64_t firstSeed, int cases) {
    int operations = 0;
    for (const std::uint64_t caseSeed : caseSeeds(firstSeed, cases)) {
        CAPTURE(caseSeed); // replay: SANDGLASS_PROPERTY_SEED=<caseSeed>
        StepSettings sleeping, sweeping, threaded;
        sleeping.physics = sweeping.physics = threaded.physics = physics;
        sweeping.sleeping = false;
        threaded.threads = 3;
        Scene scenes[3] = {randomScene(caseSeed, sleeping), randomScene(caseSeed, sweeping), randomScene(caseSeed, threaded)};
        const InvalidCells layout = invalidCellsOf(scenes[0]);
        std::int64_t expected = scenes[0].grainCount();
        std::optional<SceneSnapshot> saved;
        std::int64_t savedGrains = 0;
        std::mt19937_64 random(caseSeed * 7919 + 1);
        const int steps = uniform(random, 10, 30);
        for (int op = 0; op < steps; ++op) {
            const int kind = uniform(random, 0, 9);
            CAPTURE(op);
            CAPTURE(kind);
            const GridLevel level = uniform(random, 0, 1) ? GridLevel::Upper : GridLevel::Lower;
            const std::uint32_t cell = std::uint32_t(uniform(random, 0, int(scenes[0].grid(level).cellCount()) - 1));
            if (kind <= 2) { // steps
                const int n = uniform(random, 1, 6);
                for (Scene& s : scenes)
                    for (int i = 0; i < n; ++i) s.step();
            } else if (kind <= 4) { // paint: a few grains, also into the pour cell
                const int n = uniform(random, 1, 8);
                for (int i = 0; i < n; ++i) {
                    const std::uint32_t at = i == 0 ? pourCell(scenes[0]) : std::uint32_t(uniform(random, 0, int(scenes[0].grid(level).cellCount()) - 1));
                    const GridLevel where = i == 0 ? GridLevel::Upper : level;
                    const std::int64_t id = scenes[0].addGrain(where, at);
                    for (int s = 1; s < 3; ++s) REQUIRE(scenes[s].addGrain(where, at) == id);
                    expected += id >= 0;
                }
            } else if (kind == 5) { // erase
                const bool removed = scenes[0].removeGrain(level, cell);
                for (int s = 1; s < 3; ++s) REQUIRE(scenes[s].removeGrain(level, cell) == removed);
                expected -= removed;
            } else if (kind == 6) { // obstacle
                const Int3 c = scenes[0].grid(level).coordinate(cell);
                const CellBox box{c, {c.x + uniform(random, 1, 3), c.y + uniform(random, 1, 2), c.z + uniform(random, 1, 3)}};
                const std::int64_t removed = scenes[0].addObstacle(level, box);
                for (int s = 1; s < 3; ++s) REQUIRE(scenes[s].addObstacle(level, box) == removed);
                expected -= removed;
            } else if (kind == 7) { // reset or clearing obstacles
                const bool reset = uniform(random, 0, 1) == 1;
                for (Scene& s : scenes) reset ? s.reset() : s.clearObstacles(level);
                expected = scenes[0].grainCount();
            } else if (kind == 8) { // save, as undo does
                saved = scenes[0].snapshot();
                savedGrains = expected;
            } else if (saved) { // undo to what was saved
                for (Scene& s : scenes) s.restore(*saved);
                expected = savedGrains;
            }
            ++operations;
            for (const Scene& s : scenes) {
                const std::string problem = invariantProblem(s, layout, expected);
                if (!problem.empty()) FAIL(problem);
            }
            REQUIRE_MESSAGE(scenes[0].stateHash() == scenes[1].stateHash(), "sleeping differs from a full sweep");
            REQUIRE_MESSAGE(scenes[0].stateHash() == scenes[2].stateHash(), "3 threads differ from 1");
            for (const Scene& s : scenes) REQUIRE_MESSAGE(s.sweepsMatchCells(), "the sweeps' EMPTY or INVALID cells differ from the grids");
        }
    }
    MESSAGE(operations << " random operations checked");
}

} // namespace

TEST_CASE("H3: random scenes and edits conserve grains exactly, keep INVALID cells empty, and agree "
          "between sleeping and full sweep and between 1 and 3 threads") {
    checkRandomScenesAndEdits(PhysicsSettings{}, 1000, 400);
}

TEST_CASE("H3 under the granular rules: random scenes and edits keep the same invariants, and the EMPTY and INVALID "
          "cells the granular sweep keeps as bits stay those of the grids") {
    PhysicsSettings granular;
    granular.level = PhysicsLevel::Granular;
    granular.gravity = 0.3f; // falls of several cells a step within a few steps
    checkRandomScenesAndEdits(granular, 5000, 250);
}

namespace {

// Random 3D rotation (uniform quaternion).
std::array<double, 9> randomRotation(std::mt19937_64& random) {
    std::normal_distribution<double> normal;
    double q[4];
    double length = 0.0;
    for (double& c : q) {
        c = normal(random);
        length += c * c;
    }
    length = std::sqrt(length);
    for (double& c : q) c /= length;
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
            2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
            2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

TriangleMesh rotated(TriangleMesh mesh, const std::array<double, 9>& r) {
    for (Vec3& v : mesh.vertices)
        v = {float(r[0] * v.x + r[1] * v.y + r[2] * v.z), float(r[3] * v.x + r[4] * v.y + r[5] * v.z),
             float(r[6] * v.x + r[7] * v.y + r[8] * v.z)};
    return mesh;
}

// A random star-shaped polyhedron: an icosphere whose vertices lie at random radii, stretched.
// Its exact volume is its sum of signed tetrahedra.
TriangleMesh randomStarPolyhedron(std::mt19937_64& random) {
    TriangleMesh mesh = makeIcosphereMesh(uniform(random, 1, 2), 1.0f);
    std::uniform_real_distribution<double> radius(0.7, 1.3), stretch(0.5, 1.5);
    const double sx = stretch(random), sy = stretch(random), sz = stretch(random);
    for (Vec3& v : mesh.vertices) {
        const double r = radius(random);
        v = {float(v.x * r * sx), float(v.y * r * sy), float(v.z * r * sz)};
    }
    return mesh;
}

// A random convex polyhedron: the icosphere's vertices on a random ellipsoid (convex hull of
// points on an ellipsoid, triangulated as the sphere is).
TriangleMesh randomEllipsoidPolyhedron(std::mt19937_64& random) {
    TriangleMesh mesh = makeIcosphereMesh(uniform(random, 1, 3), 1.0f);
    std::uniform_real_distribution<double> axis(0.3, 1.5);
    const double a = axis(random), b = axis(random), c = axis(random);
    for (Vec3& v : mesh.vertices) v = {float(v.x * a), float(v.y * b), float(v.z * c)};
    return mesh;
}

// A union of 2-4 random boxes on a lattice, with its exact volume by coordinate compression.
TriangleMesh randomBoxUnion(std::mt19937_64& random, double& volume) {
    TriangleMesh mesh;
    std::vector<std::array<int, 6>> boxes;
    const int count = uniform(random, 2, 4);
    for (int b = 0; b < count; ++b) {
        std::array<int, 6> box{};
        for (int a = 0; a < 3; ++a) {
            box[std::size_t(a)] = uniform(random, 0, 6);
            box[std::size_t(a + 3)] = box[std::size_t(a)] + uniform(random, 2, 6);
        }
        boxes.push_back(box);
        mesh.append(makeBoxMesh({float(box[0]), float(box[1]), float(box[2])}, {float(box[3]), float(box[4]), float(box[5])}));
    }
    volume = 0.0; // unit cells of the lattice covered by any box
    for (int x = 0; x < 12; ++x)
        for (int y = 0; y < 12; ++y)
            for (int z = 0; z < 12; ++z)
                for (const auto& b : boxes)
                    if (x >= b[0] && x < b[3] && y >= b[1] && y < b[4] && z >= b[2] && z < b[5]) {
                        volume += 1.0;
                        break;
                    }
    return mesh;
}

} // namespace

TEST_CASE("H3: the voxel volume of random closed meshes converges to their exact volume") {
    int meshes = 0;
    for (const std::uint64_t caseSeed : caseSeeds(5000, 200)) {
        CAPTURE(caseSeed); // replay: SANDGLASS_PROPERTY_SEED=<caseSeed>
        std::mt19937_64 random(caseSeed);
        const int kind = int(caseSeed % 3);
        CAPTURE(kind);
        double exact = 0.0; // model units cubed
        TriangleMesh mesh;
        if (kind == 0) mesh = randomStarPolyhedron(random);
        else if (kind == 1) mesh = randomEllipsoidPolyhedron(random);
        else mesh = randomBoxUnion(random, exact);
        mesh = rotated(mesh, randomRotation(random));
        if (kind != 2) exact = std::abs(signedVolume(mesh));
        double previous = 1.0;
        for (int resolution : {8, 16, 32, 64}) {
            CAPTURE(resolution);
            VoxelizeSettings settings;
            settings.resolution = resolution;
            settings.robust = kind == 2; // overlapping boxes: their union
            const VoxelizeResult result = voxelize(mesh, settings);
            const double cellVolume = 1.0 / (result.placement.scale[0] * result.placement.scale[1] * result.placement.scale[2]);
            const double error = std::abs(double(result.cellsInside) * cellVolume - exact) / exact;
            // The error of a surface's cells shrinks like one cell layer: about 1/resolution.
            REQUIRE(error < 2.0 / resolution);
            if (resolution == 64) REQUIRE(error < previous + 0.01);
            previous = error;
        }
        ++meshes;
    }
    MESSAGE(meshes << " random meshes at 4 resolutions");
}
