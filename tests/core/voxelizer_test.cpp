// SPDX-License-Identifier: MIT
#include "sandcore/mesh_shapes.hpp"
#include "sandcore/voxelizer.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

using namespace sandcore;

namespace {

VoxelizeSettings plain() { return VoxelizeSettings{}; }

// |x - c| + |y - c| + |z - c| <= r: eight faces, six vertices where four faces meet.
TriangleMesh octahedron(Vec3 c, float r) {
    TriangleMesh mesh;
    mesh.vertices = {{c.x + r, c.y, c.z}, {c.x - r, c.y, c.z}, {c.x, c.y + r, c.z},
                     {c.x, c.y - r, c.z}, {c.x, c.y, c.z + r}, {c.x, c.y, c.z - r}};
    mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return mesh;
}

std::int64_t diamondCells(const InsideMask& mask, int centre, int radius) {
    std::int64_t wrong = 0;
    for (int y = 0; y < mask.size.y; ++y)
        for (int z = 0; z < mask.size.z; ++z)
            for (int x = 0; x < mask.size.x; ++x) {
                const bool expected = std::abs(x - centre) + std::abs(y - centre) + std::abs(z - centre) <= radius;
                wrong += expected != mask.at(x, y, z);
            }
    return wrong;
}

std::int64_t differingCells(const InsideMask& a, const InsideMask& b) {
    REQUIRE(a.size == b.size);
    std::int64_t count = 0;
    for (std::size_t n = 0; n < a.inside.size(); ++n) count += a.inside[n] != b.inside[n];
    return count;
}

} // namespace

TEST_CASE("a ray through the edge shared by two triangles crosses once") {
    // Each box face is split along a diagonal; rows with y == z run through the diagonal of the
    // x faces. Counting it twice or never would leave those rows empty or open.
    const InsideMask mask = voxelizeGridSpace(makeBoxMesh({0, 0, 0}, {4, 4, 4}), {4, 4, 4}, plain());
    CHECK(mask.countInside() == 64);
}

TEST_CASE("a ray through a vertex shared by four triangles crosses once") {
    // The centre row enters and leaves through the octahedron's tips; rows through y = 2.5 or
    // z = 2.5 run along projected edges.
    const InsideMask mask = voxelizeGridSpace(octahedron({2.5f, 2.5f, 2.5f}, 2.5f), {5, 5, 5}, plain());
    CHECK(mask.countInside() == 25);
    CHECK(diamondCells(mask, 2, 2) == 0);
}

TEST_CASE("faces parallel to the ray and centres on faces follow the half-open rule") {
    // Rows at y = 0.5 and y = 2.5 lie in the planes of the bottom and top faces; x faces pass
    // through cell centres. A centre on the surface is inside when a step towards +x, +y, +z enters.
    const InsideMask mask = voxelizeGridSpace(makeBoxMesh({0.5f, 0.5f, 0.5f}, {2.5f, 2.5f, 2.5f}), {4, 4, 4}, plain());
    CHECK(mask.countInside() == 8);
    for (int y = 0; y < 4; ++y)
        for (int z = 0; z < 4; ++z)
            for (int x = 0; x < 4; ++x) CHECK(mask.at(x, y, z) == (x < 2 && y < 2 && z < 2));
}

TEST_CASE("degenerate triangles change nothing") {
    TriangleMesh box = makeBoxMesh({0, 0, 0}, {4, 4, 4});
    const auto base = std::uint32_t(box.vertices.size());
    box.vertices.push_back({1.0f, 0.5f, 0.5f}); // on the row y = z = 0.5 itself
    box.vertices.push_back({2.0f, 0.5f, 0.5f});
    box.vertices.push_back({3.0f, 0.5f, 0.5f});
    box.vertices.push_back({2.0f, 0.0f, 0.0f}); // a segment across rows y = z
    box.vertices.push_back({2.0f, 1.0f, 1.0f});
    box.vertices.push_back({2.0f, 2.0f, 2.0f});
    box.triangles.push_back({base, base + 1, base + 2});
    box.triangles.push_back({base + 3, base + 4, base + 5});
    box.triangles.push_back({base + 4, base + 4, base + 1}); // a repeated vertex
    const InsideMask mask = voxelizeGridSpace(box, {4, 4, 4}, plain());
    CHECK(mask.countInside() == 64);
}

TEST_CASE("parity does not depend on face orientation") {
    const TriangleMesh sphere = makeIcosphereMesh(3, 1.0f);
    VoxelizeSettings settings;
    settings.resolution = 24;
    const VoxelizeResult reference = voxelize(sphere, settings);
    REQUIRE(reference.cellsInside > 0);

    TriangleMesh flipped = sphere, mixed = sphere;
    for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
    for (std::size_t i = 0; i < mixed.triangles.size(); i += 2) std::swap(mixed.triangles[i][1], mixed.triangles[i][2]);
    CHECK(differingCells(voxelize(flipped, settings).mask, reference.mask) == 0);
    CHECK(differingCells(voxelize(mixed, settings).mask, reference.mask) == 0);
    CHECK(voxelize(flipped, settings).meshVolume == doctest::Approx(reference.meshVolume));
}

TEST_CASE("a model far from the origin gives the same cells as at the origin") {
    // Offsets of 2^20..2^22 keep the tips (multiples of 0.5) exact in float.
    VoxelizeSettings settings;
    settings.resolution = 5;
    const VoxelizeResult near = voxelize(octahedron({0, 0, 0}, 2.5f), settings);
    const VoxelizeResult far = voxelize(octahedron({1048576.0f, -2097152.0f, 4194304.0f}, 2.5f), settings);
    CHECK(near.mask.size == Int3{5, 5, 5});
    CHECK(near.cellsInside == 25);
    CHECK(differingCells(near.mask, far.mask) == 0);
}

TEST_CASE("a wall thinner than a cell keeps the one row of centres it covers") {
    const Int3 size{5, 5, 5};
    CHECK(voxelizeGridSpace(makeBoxMesh({2.3f, 0, 0}, {2.7f, 5, 5}), size, plain()).countInside() == 25);
    CHECK(voxelizeGridSpace(makeBoxMesh({0, 2.3f, 0}, {5, 2.7f, 5}), size, plain()).countInside() == 25);
    CHECK(voxelizeGridSpace(makeBoxMesh({0, 0, 2.3f}, {5, 5, 2.7f}), size, plain()).countInside() == 25);
    // A wall between two centres covers none.
    CHECK(voxelizeGridSpace(makeBoxMesh({2.6f, 0, 0}, {3.4f, 5, 5}), size, plain()).countInside() == 0);
    VoxelizeSettings robust;
    robust.robust = true;
    const InsideMask wall = voxelizeGridSpace(makeBoxMesh({2.3f, 0, 0}, {2.7f, 5, 5}), size, robust);
    CHECK(wall.countInside() == 25);
    for (int y = 0; y < 5; ++y) CHECK(wall.at(2, y, 4));
}

TEST_CASE("the result does not depend on thread count or on binning") {
    const TriangleMesh torus = makeTorusMesh(1.0f, 0.35f, 48, 24);
    VoxelizeSettings settings;
    settings.resolution = 40;
    const InsideMask reference = voxelize(torus, settings).mask;
    for (int threads : {2, 3}) {
        settings.threads = threads;
        CHECK(differingCells(voxelize(torus, settings).mask, reference) == 0);
    }
    settings.threads = 2;
    settings.binning = false;
    CHECK(differingCells(voxelize(torus, settings).mask, reference) == 0);
    settings.binning = true;
    settings.robust = true;
    CHECK(differingCells(voxelize(torus, settings).mask, reference) == 0);
}

TEST_CASE("volume error of a closed sphere and torus shrinks with resolution") {
    const TriangleMesh sphere = makeIcosphereMesh(5, 1.0f);
    const TriangleMesh torus = makeTorusMesh(1.0f, 0.4f, 128, 64);
    const int resolutions[3] = {32, 64, 128};
    const double bounds[3] = {0.03, 0.015, 0.01};
    for (int i = 0; i < 3; ++i) {
        VoxelizeSettings settings;
        settings.resolution = resolutions[i];
        settings.threads = 2;
        const VoxelizeResult s = voxelize(sphere, settings), t = voxelize(torus, settings);
        INFO("resolution " << resolutions[i] << ": sphere " << s.relativeError() << ", torus " << t.relativeError());
        CHECK(s.closedness.closed);
        CHECK(std::abs(s.relativeError()) < bounds[i]);
        CHECK(std::abs(t.relativeError()) < bounds[i]);
    }
}

TEST_CASE("scaling keeps the aspect ratio unless stretched, and centres the model") {
    const TriangleMesh box = makeBoxMesh({0, 0, 0}, {2, 4, 1});
    VoxelizeSettings settings;
    settings.resolution = 64;
    const VoxelizeResult kept = voxelize(box, settings);
    CHECK(kept.mask.size == Int3{32, 64, 16});
    CHECK(kept.cellsInside == 32 * 64 * 16);
    CHECK(kept.meshVolume == doctest::Approx(32.0 * 64 * 16));
    CHECK(kept.relativeError() == doctest::Approx(0.0));
    settings.stretch = true;
    CHECK(voxelize(box, settings).mask.size == Int3{64, 64, 64});
    settings.stretch = false;
    settings.resolution = 5;
    const VoxelPlacement odd = placeInGrid(makeBoxMesh({0, 0, 0}, {4, 3, 4}), settings);
    CHECK(odd.size == Int3{5, 4, 5});
    CHECK(odd.padding[1] == doctest::Approx(0.125)); // 3.75 cells of model centred in 4
}

TEST_CASE("robust mode repairs a sphere with a hole below the hole's rim, and plain parity does not") {
    // Radius 15 about (16, 16, 16) in a 32^3 grid, placed directly so the hole cannot move the bounds.
    TriangleMesh sphere = makeIcosphereMesh(3, 15.0f);
    for (Vec3& v : sphere.vertices) v = {v.x + 16.0f, v.y + 16.0f, v.z + 16.0f};
    const Int3 size{32, 32, 32};
    const InsideMask closed = voxelizeGridSpace(sphere, size, plain());
    // Cut the cap beyond x = 16 + 13.5: rows along x through it see one crossing, and rays along
    // y and z beyond the rim plane see none.
    std::erase_if(sphere.triangles, [&](const auto& t) {
        for (std::uint32_t i : t)
            if (sphere.vertices[i].x <= 29.5f) return false;
        return true;
    });
    const MeshClosedness closedness = closednessOf(sphere);
    CHECK_FALSE(closedness.closed);
    CHECK(closedness.boundaryEdges > 0);
    VoxelizeSettings robust;
    robust.robust = true;
    const InsideMask repaired = voxelizeGridSpace(sphere, size, robust);
    const InsideMask open = voxelizeGridSpace(sphere, size, plain());
    std::int64_t wrongBelowRim = 0, wrongPlain = 0, capCells = 0;
    for (int y = 0; y < size.y; ++y)
        for (int z = 0; z < size.z; ++z)
            for (int x = 0; x < size.x; ++x) {
                if (x + 0.5 < 29.0) wrongBelowRim += repaired.at(x, y, z) != closed.at(x, y, z);
                else capCells += closed.at(x, y, z);
                wrongPlain += open.at(x, y, z) != closed.at(x, y, z);
            }
    CHECK(wrongBelowRim == 0);
    // Only cells beyond the rim, in the mouth of the hole, may be lost.
    CHECK(capCells > 0);
    CHECK(differingCells(repaired, closed) <= capCells);
    CHECK(wrongPlain > 100); // plain parity drops whole rows through the hole
}

TEST_CASE("bad meshes and settings are refused with a message") {
    const TriangleMesh box = makeBoxMesh({0, 0, 0}, {1, 1, 1});
    VoxelizeSettings settings;
    settings.resolution = 0;
    CHECK_THROWS_WITH_AS(voxelize(box, settings), "resolution must lie in 1..8192, got 0", std::invalid_argument);
    settings.resolution = 16;
    CHECK_THROWS_WITH_AS(voxelize(makeBoxMesh({0, 0, 0}, {1, 0, 1}), settings), "the model has zero extent along y",
                         std::invalid_argument);
    TriangleMesh broken = box;
    broken.vertices[3].x = std::numeric_limits<float>::quiet_NaN();
    CHECK_THROWS_AS(voxelize(broken, settings), std::invalid_argument);
    CHECK_THROWS_WITH_AS(voxelize(TriangleMesh{}, settings), "the mesh has no triangles", std::invalid_argument);
}

TEST_CASE("a NaN or infinite vertex is named as such, not as a grid range problem") {
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        TriangleMesh mesh = makeBoxMesh({0, 0, 0}, {1, 1, 1});
        mesh.vertices[3].y = bad;
        VoxelizeSettings settings;
        settings.resolution = 8;
        try {
            voxelize(mesh, settings);
            FAIL("a non-finite vertex was accepted");
        } catch (const std::invalid_argument& e) {
            CHECK(std::string(e.what()).find("non-finite coordinate") != std::string::npos);
        }
    }
}
