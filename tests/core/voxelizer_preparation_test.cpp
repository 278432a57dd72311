// SPDX-License-Identifier: MIT
// SPEC S2, S5: voxelize welds, drops repeated faces, measures closedness and orients the faces
// in parallel; whatever the thread count, its results are those of the step-by-step public
// functions (weldVertices, withoutRepeatedTriangles, closednessOf, orientedOutward,
// voxelizeGridSpace), on clean meshes and on meshes damaged the ways model files are.
#include "sandcore/mesh_shapes.hpp"
#include "sandcore/voxelizer.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

using namespace sandcore;

namespace {

constexpr int kSize = 32; // the meshes span [0, kSize] on every axis: grid coordinates are model coordinates

struct Random {
    std::uint64_t state;
    std::uint32_t next() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return std::uint32_t(state >> 33);
    }
    bool chance(double p) { return next() < p * 2147483648.0; }
    std::uint32_t below(std::size_t n) { return std::uint32_t(next() % n); }
};

TriangleMesh moved(TriangleMesh mesh, float scale, Vec3 by) {
    for (Vec3& v : mesh.vertices) v = {v.x * scale + by.x, v.y * scale + by.y, v.z * scale + by.z};
    return mesh;
}

// A Moebius strip: no choice of face orientations agrees across all of its edges.
TriangleMesh moebiusStrip(Vec3 centre, float radius, float width, int segments) {
    TriangleMesh mesh;
    for (int i = 0; i < segments; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / segments, twist = angle / 2.0;
        for (int side : {-1, 1}) {
            const double r = radius + side * width * std::cos(twist), h = side * width * std::sin(twist);
            mesh.vertices.push_back({centre.x + float(r * std::cos(angle)), centre.y + float(h),
                                     centre.z + float(r * std::sin(angle))});
        }
    }
    for (int i = 0; i < segments; ++i) {
        const std::uint32_t a = std::uint32_t(2 * i), b = a + 1;
        // The last segment closes the loop with the sides swapped: the half twist.
        const bool last = i + 1 == segments;
        const std::uint32_t c = last ? 1 : a + 2, d = last ? 0 : a + 3;
        mesh.triangles.push_back({a, c, b});
        mesh.triangles.push_back({b, c, d});
    }
    return mesh;
}

// A sphere and a torus that overlap, and two small boxes in opposite corners that pin the
// bounds to [0, kSize]^3.
TriangleMesh cleanModel() {
    TriangleMesh mesh = moved(makeIcosphereMesh(4, 1.0f), 9.0f, {13.0f, 15.0f, 16.0f});
    mesh.append(moved(makeTorusMesh(1.0f, 0.4f, 40, 20), 8.0f, {19.0f, 16.5f, 17.0f}));
    mesh.append(makeBoxMesh({0, 0, 0}, {1.5f, 1.5f, 1.5f}));
    mesh.append(makeBoxMesh({kSize - 2.0f, kSize - 2.0f, kSize - 2.0f}, {float(kSize), float(kSize), float(kSize)}));
    return mesh;
}

// The model as files bring it: corners unwelded (some zeros written as -0.0; not with `welded`,
// as a loader that welds gives it), faces shuffled, flipped, written twice either way,
// degenerate, missing (holes), fins on edges (non-manifold), unused vertices far outside, and
// optionally a Moebius strip.
TriangleMesh damaged(TriangleMesh mesh, std::uint64_t seed, bool moebius, bool welded = false) {
    Random random{seed};
    if (moebius) mesh.append(moebiusStrip({16.0f, 6.0f, 16.0f}, 5.0f, 1.5f, 24));
    if (!welded)
        for (auto& t : mesh.triangles)
            for (std::uint32_t& i : t)
                if (random.chance(0.3)) {
                    Vec3 copy = mesh.vertices[i];
                    for (float* c : {&copy.x, &copy.y, &copy.z})
                        if (*c == 0.0f && random.chance(0.5)) *c = -0.0f;
                    mesh.vertices.push_back(copy);
                    i = std::uint32_t(mesh.vertices.size() - 1);
                }
    const std::size_t original = mesh.triangles.size();
    for (std::size_t n = 0; n < original; ++n) {
        auto t = mesh.triangles[n];
        if (random.chance(0.04)) mesh.triangles.push_back(t);
        if (random.chance(0.03)) mesh.triangles.push_back({t[0], t[2], t[1]});
        if (random.chance(0.01)) mesh.triangles.push_back({t[0], t[0], t[1]});
        if (random.chance(0.005)) { // a fin on the edge t[0]-t[1]
            const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]];
            mesh.vertices.push_back({(a.x + b.x) / 2 + 0.3f, (a.y + b.y) / 2 + 0.2f, (a.z + b.z) / 2 + 0.1f});
            mesh.triangles.push_back({t[0], t[1], std::uint32_t(mesh.vertices.size() - 1)});
        }
    }
    std::vector<std::array<std::uint32_t, 3>> kept;
    for (auto t : mesh.triangles) {
        if (random.chance(0.002)) continue; // a hole
        if (random.chance(0.3)) std::swap(t[1], t[2]);
        kept.push_back(t);
    }
    for (std::size_t n = kept.size(); n > 1; --n) std::swap(kept[n - 1], kept[random.below(n)]);
    mesh.triangles = std::move(kept);
    mesh.vertices.push_back({1000.0f, -1000.0f, 1000.0f}); // unused: outside the bounds
    return mesh;
}

// What voxelize must report, from the public functions one after the other.
void checkAgainstSteps(const TriangleMesh& mesh, bool robust) {
    VoxelizeSettings settings;
    settings.resolution = kSize;
    settings.robust = robust;
    const TriangleMesh prepared = orientedOutward(withoutRepeatedTriangles(mesh));
    const MeshClosedness closedness = closednessOf(mesh);
    const InsideMask expected = voxelizeGridSpace(mesh, {kSize, kSize, kSize}, settings);
    const double volume = std::abs(signedVolume(prepared));
    const bool meaningful = closedness.closed && closednessOf(prepared).inconsistentEdges == 0;
    for (int threads : {1, 2, 3, 5}) {
        CAPTURE(threads);
        settings.threads = threads;
        const VoxelizeResult result = voxelize(mesh, settings);
        REQUIRE(result.placement.size == Int3{kSize, kSize, kSize});
        CHECK(result.placement.scale[0] == 1.0);
        CHECK(result.mask.inside == expected.inside);
        CHECK(result.cellsInside == expected.countInside());
        CHECK(result.closedness.boundaryEdges == closedness.boundaryEdges);
        CHECK(result.closedness.nonManifoldEdges == closedness.nonManifoldEdges);
        CHECK(result.closedness.inconsistentEdges == closedness.inconsistentEdges);
        CHECK(result.closedness.closed == closedness.closed);
        CHECK(result.meshVolume == volume);
        CHECK(result.volumeMeaningful == meaningful);
    }
}

} // namespace

TEST_CASE("voxelize agrees with the step-by-step functions on a clean model, for any thread count") {
    const TriangleMesh mesh = cleanModel();
    CHECK(closednessOf(mesh).closed);
    for (bool robust : {false, true}) {
        CAPTURE(robust);
        checkAgainstSteps(mesh, robust);
    }
}

TEST_CASE("voxelize agrees with the step-by-step functions on damaged models, open and non-manifold ones included") {
    for (std::uint64_t seed : {1u, 2u, 3u})
        for (bool moebius : {false, true}) {
            CAPTURE(seed);
            CAPTURE(moebius);
            const TriangleMesh mesh = damaged(cleanModel(), seed, moebius);
            // The damage is there: otherwise this test would check nothing new.
            const MeshClosedness closedness = closednessOf(mesh);
            CHECK_FALSE(closedness.closed);
            CHECK(closedness.nonManifoldEdges > 0);
            CHECK(closedness.inconsistentEdges > 0);
            CHECK(withoutRepeatedTriangles(mesh).triangles.size() < mesh.triangles.size());
            for (bool robust : {false, true}) {
                CAPTURE(robust);
                checkAgainstSteps(mesh, robust);
            }
        }
}

// A mesh with no two vertices at one position is used as given, not copied: the damage that
// needs no weld (flips, repeated and degenerate faces, holes, fins) must still be handled, and
// robust mode must cast its rays through the flipped copy of the triangles.
TEST_CASE("voxelize agrees with the step-by-step functions on welded models, damaged and clean") {
    const TriangleMesh clean = weldVertices(cleanModel());
    REQUIRE(weldVertices(clean).vertices.size() == clean.vertices.size());
    for (bool robust : {false, true}) checkAgainstSteps(clean, robust);
    // Flipped faces alone: no face goes, so only the orientation changes the triangles.
    TriangleMesh flipped = clean;
    Random random{6};
    for (auto& t : flipped.triangles)
        if (random.chance(0.3)) std::swap(t[1], t[2]);
    REQUIRE(closednessOf(flipped).inconsistentEdges > 0);
    REQUIRE(withoutRepeatedTriangles(flipped).triangles.size() == flipped.triangles.size());
    for (bool robust : {false, true}) checkAgainstSteps(flipped, robust);
    for (std::uint64_t seed : {4u, 5u})
        for (bool moebius : {false, true}) {
            CAPTURE(seed);
            CAPTURE(moebius);
            const TriangleMesh mesh = damaged(clean, seed, moebius, true);
            REQUIRE(weldVertices(mesh).vertices.size() == mesh.vertices.size()); // nothing to weld
            CHECK(closednessOf(mesh).inconsistentEdges > 0);
            CHECK(withoutRepeatedTriangles(mesh).triangles.size() < mesh.triangles.size());
            for (bool robust : {false, true}) {
                CAPTURE(robust);
                checkAgainstSteps(mesh, robust);
            }
        }
}

// A closed mesh of one part (the common case) takes its volume from the orientation's own sum,
// with no pass of its own: it must be signedVolume's bit for bit, faces flipped or not.
TEST_CASE("the volume of a mesh of one part is signedVolume's, with and without flipped faces") {
    for (const TriangleMesh& shape : {makeIcosphereMesh(4, 1.0f), makeTorusMesh(1.0f, 0.4f, 40, 20)}) {
        for (double flipShare : {0.0, 0.3, 1.0}) {
            CAPTURE(flipShare);
            TriangleMesh mesh = moved(shape, 9.5f, {13.1f, 15.3f, 16.7f});
            Random random{7};
            for (auto& t : mesh.triangles)
                if (random.chance(flipShare)) std::swap(t[1], t[2]);
            const TriangleMesh prepared = orientedOutward(withoutRepeatedTriangles(mesh));
            for (int threads : {1, 2}) {
                VoxelizeSettings settings;
                settings.resolution = 48;
                settings.threads = threads;
                const VoxelizeResult result = voxelize(mesh, settings);
                const auto& scale = result.placement.scale;
                CHECK(result.volumeMeaningful);
                CHECK(result.meshVolume == std::abs(signedVolume(prepared)) * scale[0] * scale[1] * scale[2]);
                CHECK(result.meshVolume > 0.0);
            }
        }
    }
}

TEST_CASE("a Moebius strip beside a closed model: open, no meaningful volume, the same cells as step by step") {
    TriangleMesh mesh = cleanModel();
    checkAgainstSteps(mesh, false);
    mesh.append(moebiusStrip({16.0f, 6.0f, 16.0f}, 5.0f, 1.5f, 24));
    VoxelizeSettings settings;
    settings.resolution = kSize;
    const VoxelizeResult result = voxelize(mesh, settings);
    CHECK_FALSE(result.closedness.closed); // the strip's rim is a boundary
    CHECK_FALSE(result.volumeMeaningful);
    checkAgainstSteps(mesh, false);
    checkAgainstSteps(mesh, true);
}

TEST_CASE("a face written twice in opposite directions is a closed part of zero volume") {
    TriangleMesh mesh = cleanModel();
    const std::uint32_t base = std::uint32_t(mesh.vertices.size());
    mesh.vertices.push_back({5.0f, 25.0f, 5.0f});
    mesh.vertices.push_back({9.0f, 25.0f, 5.0f});
    mesh.vertices.push_back({5.0f, 28.0f, 9.0f});
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 1});
    CHECK(closednessOf(mesh).closed);
    checkAgainstSteps(mesh, false);
    checkAgainstSteps(mesh, true);
}
