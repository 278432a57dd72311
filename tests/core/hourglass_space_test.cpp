// SPDX-License-Identifier: MIT
// W1, W2, W5: the hourglass recipe on meshes made here, where the answer is known exactly.
#include "sandcore/hourglass_space.hpp"
#include "sandcore/mesh_shapes.hpp"
#include "sandcore/mesh_shells.hpp"

#include "wall_cavities.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <climits>
#include <cmath>

using namespace sandcore;

namespace {

// A surface of revolution about y through (radius, y) points, open where the profile does not
// reach the axis: a single-wall glass.
TriangleMesh lathe(const std::vector<ProfilePoint>& profile) { return makeLatheMesh(profile, 48); }

// A single-wall hourglass glass, open at both ends: bulbs of radius 0.9 joined by a neck tube of
// radius `neck`, 0.2 long.
TriangleMesh openGlass(float neck) {
    std::vector<ProfilePoint> profile;
    for (int i = 0; i <= 20; ++i) {
        const float t = float(i) / 20.0f;           // 0 bottom rim .. 1 top rim
        const float s = std::abs(2.0f * t - 1.0f);  // 1 at the rims, 0 at the neck
        const float flare = std::max(0.0f, (s - 0.1f) / 0.9f);
        profile.push_back({neck + (0.9f - neck) * std::sqrt(flare), 0.1f + 2.0f * t});
    }
    return lathe(profile);
}

std::vector<ModelShell> shellsOf(const TriangleMesh& mesh) {
    std::vector<ModelShell> shells;
    for (TriangleMesh& shell : splitIntoShells(weldVertices(mesh))) shells.push_back({std::move(shell)});
    return shells;
}

} // namespace

TEST_CASE("W1: a mesh splits into its connected shells, and doubled faces are dropped whatever their winding") {
    TriangleMesh two = makeBoxMesh({0, 0, 0}, {1, 1, 1});
    two.append(makeBoxMesh({3, 0, 0}, {4, 1, 1}));
    const std::vector<TriangleMesh> shells = splitIntoShells(weldVertices(two));
    REQUIRE(shells.size() == 2);
    CHECK(shells[0].triangles.size() == 12);
    CHECK(boundsOf(shells[1]).min[0] == doctest::Approx(3.0));
    TriangleMesh doubled = makeBoxMesh({0, 0, 0}, {1, 1, 1});
    const auto first = doubled.triangles[0];
    doubled.triangles.push_back(first);                          // the same face again
    doubled.triangles.push_back({first[0], first[2], first[1]}); // and once the other way round
    CHECK(withoutDoubledFaces(doubled).triangles.size() == 12);
}

TEST_CASE("W2: a gap in a wall is closed by growing the walls and the space grown back stays inside") {
    // A closed 12-cell box of wall with a 1-cell hole in its top: open at closing 0, closed at 1.
    const Int3 size{16, 16, 16};
    MaskCells walls(std::size_t(16 * 16 * 16), 0);
    auto at = [&](int x, int y, int z) -> std::uint8_t& { return walls[std::size_t(x + 16 * (z + 16 * y))]; };
    for (int y = 2; y <= 13; ++y)
        for (int z = 2; z <= 13; ++z)
            for (int x = 2; x <= 13; ++x)
                if (x == 2 || x == 13 || y == 2 || y == 13 || z == 2 || z == 13) at(x, y, z) = 1;
    at(7, 13, 7) = 0;
    CHECK(enclosedRegions(walls, walls, size, 0).empty());
    const std::vector<CellList> closed = enclosedRegions(walls, grownBy(walls, size, 1), size, 1);
    REQUIRE(closed.size() == 1);
    // Grown back, it is the whole inside (10^3 cells), and the hole's cell went to the outside.
    CHECK(closed[0].size() == 1000);
    CHECK(!std::binary_search(closed[0].begin(), closed[0].end(), std::uint32_t(7 + 16 * (7 + 16 * 13))));
}

TEST_CASE("W2: an open single-wall glass between two plates with gaps under a cell is an hourglass") {
    TriangleMesh model = openGlass(0.25f);
    // Plates 0.04 above and below the rims: at resolution 48 over 2.4 units a cell is 0.05.
    model.append(makeBoxMesh({-1.1f, -0.2f, -1.1f}, {1.1f, 0.06f, 1.1f}));
    model.append(makeBoxMesh({-1.1f, 2.14f, -1.1f}, {1.1f, 2.4f, 1.1f}));
    HourglassSpaceSettings settings;
    settings.voxelize.resolution = 48;
    const HourglassSpace space = findHourglassSpace(shellsOf(model), settings);
    CHECK(space.isHourglass);
    CHECK(space.note.empty());
    CHECK(space.up == UpAxis::PlusY);
    CHECK(space.kind == SandSpaceKind::Cavity);
    // The space lies within the glass's radius: nothing between the plates outside the glass.
    const Int3 s = space.space.size;
    for (int y = 0; y < s.y; ++y)
        for (int z = 0; z < s.z; ++z)
            for (int x = 0; x < s.x; ++x)
                if (space.space.at(x, y, z)) {
                    const double dx = (x + 0.5 - s.x / 2.0) / space.placement.scale[0];
                    const double dz = (z + 0.5 - s.z / 2.0) / space.placement.scale[2];
                    REQUIRE(std::sqrt(dx * dx + dz * dz) <= 0.95);
                }
    CHECK(space.roles[1] == ShellRole::Frame);
}

TEST_CASE("W2: a neck narrower than a cell is opened to one cell, and found laid on its side") {
    // The neck's surface cells seal it: the two bulbs are two spaces until a column joins them.
    TriangleMesh glass = openGlass(0.005f);
    glass.append(makeBoxMesh({-1.1f, -0.2f, -1.1f}, {1.1f, 0.1f, 1.1f}));
    glass.append(makeBoxMesh({-1.1f, 2.1f, -1.1f}, {1.1f, 2.4f, 1.1f}));
    for (Vec3& v : glass.vertices) v = {v.y, -v.x, v.z}; // up along +x
    HourglassSpaceSettings settings;
    settings.voxelize.resolution = 40;
    const HourglassSpace space = findHourglassSpace(shellsOf(glass), settings);
    CHECK(space.isHourglass);
    CHECK(space.neckOpened);
    CHECK((space.up == UpAxis::PlusX || space.up == UpAxis::MinusX));
    // Turned upright, the neck layer holds exactly the one opened cell.
    std::int64_t narrowest = INT64_MAX;
    int firstLayer = 0, lastLayer = space.space.size.y - 1;
    while (space.space.countInsideLayer(firstLayer) == 0) ++firstLayer;
    while (space.space.countInsideLayer(lastLayer) == 0) --lastLayer;
    for (int y = firstLayer; y <= lastLayer; ++y) narrowest = std::min(narrowest, space.space.countInsideLayer(y));
    CHECK(narrowest == 1);
}

TEST_CASE("W1: modelled sand inside the glass is the initial sand and turns its bulb up") {
    std::vector<ModelShell> shells = shellsOf(openGlass(0.2f));
    shells.push_back({makeBoxMesh({-1.1f, -0.2f, -1.1f}, {1.1f, 0.1f, 1.1f})});
    shells.push_back({makeBoxMesh({-1.1f, 2.1f, -1.1f}, {1.1f, 2.4f, 1.1f})});
    // A block of sand low in the lower bulb: the model stood the wrong way up for a drain.
    shells.push_back({makeBoxMesh({-0.4f, 0.3f, -0.4f}, {0.4f, 0.8f, 0.4f})});
    HourglassSpaceSettings settings;
    settings.voxelize.resolution = 48;
    const HourglassSpace space = findHourglassSpace(shells, settings);
    REQUIRE(space.isHourglass);
    CHECK(space.roles[3] == ShellRole::Sand);
    CHECK(space.up == UpAxis::MinusY);
    const Scene scene = makeHourglassScene(space);
    // As much sand as was modelled, all of it in the upper grid.
    CHECK(scene.counters().grainsUpper == space.modelledSand.countInside());
    CHECK(scene.counters().grainsLower == 0);
}

TEST_CASE("W5: an open funnel is no hourglass: one line says so and its inside runs out of its bottom") {
    const TriangleMesh funnel = lathe({{0.15f, 0.0f}, {0.15f, 0.4f}, {1.0f, 1.5f}});
    HourglassSpaceSettings settings;
    settings.voxelize.resolution = 40;
    const HourglassSpace space = findHourglassSpace(shellsOf(funnel), settings);
    CHECK(!space.isHourglass);
    CHECK(space.kind == SandSpaceKind::OpenVessel);
    CHECK(space.up == UpAxis::PlusY);
    CHECK(space.note.find("runs out of its bottom") != std::string::npos);
    Scene scene = makeHourglassScene(space);
    const std::int64_t grains = scene.grainCount();
    REQUIRE(grains > 0);
    for (int i = 0; i < 400; ++i) scene.step();
    CHECK(scene.counters().grainsLower > 0); // fell out onto the floor
    CHECK(scene.grainCount() == grains);
}

TEST_CASE("an embedder turns a triangle soup into a running hourglass in one call") {
    TriangleMesh model = openGlass(0.25f);
    model.append(makeBoxMesh({-1.1f, -0.2f, -1.1f}, {1.1f, 0.1f, 1.1f}));
    model.append(makeBoxMesh({-1.1f, 2.1f, -1.1f}, {1.1f, 2.4f, 1.1f}));
    Scene scene = makeHourglassFromMesh(model, 32);
    const std::int64_t grains = scene.grainCount();
    REQUIRE(grains > 0);
    for (int i = 0; i < 2000 && scene.counters().grainsUpper > 0; ++i) scene.step();
    CHECK(scene.counters().grainsUpper == 0);
    CHECK(scene.counters().grainsLower == grains);
}
