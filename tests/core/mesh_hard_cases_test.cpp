// SPDX-License-Identifier: MIT
// SPEC S2, S5, S6, H2: meshes as they come from real files: faces written twice, closed parts
// that overlap, faces with flipped orientation.
#include "sandcore/mesh_shapes.hpp"
#include "sandcore/voxelizer.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sandcore;

namespace {

TriangleMesh translated(TriangleMesh mesh, Vec3 by) {
    for (Vec3& v : mesh.vertices) v = {v.x + by.x, v.y + by.y, v.z + by.z};
    return mesh;
}

TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b) {
    TriangleMesh out = a;
    out.append(b);
    return out;
}

InsideMask gridMask(const TriangleMesh& mesh, Int3 size, bool robust) {
    VoxelizeSettings settings;
    settings.robust = robust;
    return voxelizeGridSpace(mesh, size, settings);
}

} // namespace

TEST_CASE("a mesh whose every face is written twice voxelizes like the mesh itself") {
    const TriangleMesh sphere = makeIcosphereMesh(3, 1.0f);
    TriangleMesh doubled = sphere;
    doubled.append(sphere); // the same faces again, with their own copies of the vertices
    for (bool robust : {false, true}) {
        CAPTURE(robust);
        VoxelizeSettings settings;
        settings.resolution = 32;
        settings.robust = robust;
        const VoxelizeResult once = voxelize(sphere, settings), twice = voxelize(doubled, settings);
        CHECK(once.cellsInside > 10000);
        CHECK(twice.cellsInside == once.cellsInside);
        CHECK(twice.mask.inside == once.mask.inside);
        CHECK(twice.meshVolume == doctest::Approx(once.meshVolume));
    }
}

TEST_CASE("two overlapping closed spheres are their union in robust mode") {
    // In grid coordinates: both spheres lie in a 40 x 28 x 28 grid and overlap in the middle.
    TriangleMesh a = makeIcosphereMesh(3, 11.0f), b = makeIcosphereMesh(3, 11.0f);
    a = translated(a, {14.3f, 14.1f, 13.9f});
    b = translated(b, {25.7f, 13.8f, 14.2f});
    const Int3 size{40, 28, 28};
    const InsideMask maskA = gridMask(a, size, false), maskB = gridMask(b, size, false);
    const InsideMask both = gridMask(merged(a, b), size, true);
    std::int64_t unionCells = 0, overlap = 0, differing = 0;
    for (std::size_t n = 0; n < maskA.inside.size(); ++n) {
        const bool inUnion = maskA.inside[n] || maskB.inside[n];
        unionCells += inUnion;
        overlap += maskA.inside[n] && maskB.inside[n];
        differing += inUnion != bool(both.inside[n]);
    }
    REQUIRE(overlap > 500); // the test means something
    CHECK(differing == 0);
    CHECK(both.countInside() == unionCells);
    // Parity alone gives the symmetric difference: the overlap is hollow.
    CHECK(gridMask(merged(a, b), size, false).countInside() == unionCells - overlap);
}

TEST_CASE("two overlapping boxes are exactly their union box in robust mode, coplanar faces included") {
    const TriangleMesh a = makeBoxMesh({2.0f, 2.0f, 2.0f}, {12.0f, 10.0f, 10.0f});
    const TriangleMesh b = makeBoxMesh({7.0f, 2.0f, 2.0f}, {17.0f, 10.0f, 10.0f});
    const Int3 size{20, 12, 12};
    CHECK(gridMask(merged(a, b), size, true).inside == gridMask(makeBoxMesh({2, 2, 2}, {17, 10, 10}), size, true).inside);
}

TEST_CASE("half the faces flipped: the same cells, and a volume that is right or reported as meaningless") {
    const TriangleMesh sphere = makeIcosphereMesh(3, 1.0f);
    TriangleMesh flipped = sphere;
    for (std::size_t t = 0; t < flipped.triangles.size(); t += 2) std::swap(flipped.triangles[t][1], flipped.triangles[t][2]);
    CHECK(closednessOf(flipped).inconsistentEdges > 0);
    CHECK(closednessOf(sphere).inconsistentEdges == 0);
    for (bool robust : {false, true}) {
        CAPTURE(robust);
        VoxelizeSettings settings;
        settings.resolution = 40;
        settings.robust = robust;
        const VoxelizeResult right = voxelize(sphere, settings), mixed = voxelize(flipped, settings);
        CHECK(mixed.mask.inside == right.mask.inside);
        // Orientation is repaired before the volume is taken: the error is the true one.
        CHECK(mixed.volumeMeaningful);
        CHECK(mixed.meshVolume == doctest::Approx(right.meshVolume));
        CHECK(std::abs(mixed.relativeError()) < 0.05);
    }
}

TEST_CASE("two closed boxes touching only along an edge: a non-manifold edge, and the right volume") {
    TriangleMesh mesh = makeBoxMesh({0, 0, 0}, {1, 1, 1});
    TriangleMesh other = makeBoxMesh({1, 1, 0}, {2, 2, 1}); // touches along an edge only
    mesh.append(other);
    VoxelizeSettings settings;
    settings.resolution = 16;
    const VoxelizeResult result = voxelize(mesh, settings);
    CHECK(result.closedness.nonManifoldEdges == 1);
    CHECK(result.volumeMeaningful);
    CHECK(result.meshVolume == doctest::Approx(2.0 * 8.0 * 8.0 * 8.0)); // two unit boxes at 8 cells per unit
    CHECK(std::abs(result.relativeError()) < 0.01);
}

TEST_CASE("orientedOutward makes every part wind counter-clockwise seen from outside") {
    TriangleMesh sphere = makeIcosphereMesh(2, 1.0f);
    for (auto& t : sphere.triangles) std::swap(t[1], t[2]); // all inside out
    for (std::size_t t = 0; t < sphere.triangles.size(); t += 3) std::swap(sphere.triangles[t][0], sphere.triangles[t][1]);
    const TriangleMesh oriented = orientedOutward(sphere);
    CHECK(closednessOf(oriented).inconsistentEdges == 0);
    CHECK(signedVolume(oriented) > 4.0);
}
