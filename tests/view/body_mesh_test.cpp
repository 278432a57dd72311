// SPDX-License-Identifier: MIT
// A moving body's mesh: one quad per face between a body cell and a cell outside it, normals
// pointing out of the body, turned with the body's heading; and the vessel's hull does not take
// a standing body's cells (INVALID while it stands) for walls.
#include "view/render/body_surfaces.hpp"
#include "view/render/hull_mesh.hpp"

#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

using namespace sandglass;

TEST_CASE("body mesh: a box's six sides, two triangles a cell face, normals outward") {
    const sandcore::InsideMask box = sandcore::makeBoxShape({3, 2, 4});
    const std::vector<BodyVertex> mesh = buildBodyMesh(box, 0, 0.5f);
    const std::size_t faces = 2 * (3 * 2 + 3 * 4 + 2 * 4);
    REQUIRE(mesh.size() == 6 * faces);
    // The box's middle, relative to its anchor (the middle of its bottom layer), world units.
    const float middleX = (0.0f - 1.0f + 1.5f) * 0.5f, middleY = 1.0f * 0.5f, middleZ = (0.0f - 2.0f + 2.0f) * 0.5f;
    for (const BodyVertex& v : mesh) {
        CHECK(std::abs(std::hypot(v.nx, v.ny, v.nz) - 1.0f) < 1e-4f);
        // Each vertex lies on the box's surface, its normal pointing away from the middle.
        CHECK(v.nx * (v.x - middleX) + v.ny * (v.y - middleY) + v.nz * (v.z - middleZ) > 0.0f);
    }
}

TEST_CASE("body mesh: a quarter turn turns the mesh with the body") {
    const sandcore::InsideMask blade = sandcore::makeBladeShape(6, 3, 2);
    const std::vector<BodyVertex> along = buildBodyMesh(blade, 0, 1.0f);
    const std::vector<BodyVertex> across = buildBodyMesh(blade, 1, 1.0f);
    REQUIRE(along.size() == across.size());
    auto extent = [](const std::vector<BodyVertex>& mesh, int axis) {
        float low = 1e30f, high = -1e30f;
        for (const BodyVertex& v : mesh) {
            const float c = axis == 0 ? v.x : v.z;
            low = std::min(low, c), high = std::max(high, c);
        }
        return high - low;
    };
    CHECK(extent(along, 0) == doctest::Approx(6.0f));
    CHECK(extent(along, 2) == doctest::Approx(2.0f));
    CHECK(extent(across, 0) == doctest::Approx(2.0f));
    CHECK(extent(across, 2) == doctest::Approx(6.0f));
}

TEST_CASE("hull mesh: a standing body is no part of the vessel's hull") {
    sandcore::Scene scene = sandcore::makeCanvasScene(sandcore::canvasSettingsForWidth(24));
    const std::size_t without = buildHullMesh(scene, sandcore::SceneKind::Canvas, 1.0f).triangles.size();
    REQUIRE(scene.addBody({sandcore::makeBoxShape({4, 3, 4}), {12, 0, 12}, 0}) == 0);
    CHECK(buildHullMesh(scene, sandcore::SceneKind::Canvas, 1.0f).triangles.size() == without);
}
