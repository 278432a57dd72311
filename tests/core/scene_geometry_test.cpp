// SPDX-License-Identifier: MIT
// Scene geometry: grid sizes and memory estimates computed before a scene exists agree with the
// scenes the library builds, and keep the numbers the application's memory check relies on.
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scene_geometry.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>

using namespace sandcore;

namespace {
std::uint64_t cells(Int3 s) { return std::uint64_t(s.x) * std::uint64_t(s.y) * std::uint64_t(s.z); }
} // namespace

TEST_CASE("the canvas is width/6 over 2/3 width high, at least 2 cells each, and the default is width 60") {
    const CanvasSettings sixty = canvasSettingsForWidth(60);
    CHECK(sixty.upperSize == Int3{60, 10, 60});
    CHECK(sixty.lowerSize == Int3{60, 40, 60});
    const CanvasSettings defaults;
    CHECK(defaults.upperSize == sixty.upperSize);
    CHECK(defaults.lowerSize == sixty.lowerSize);
    CHECK(canvasSettingsForWidth(8).upperSize == Int3{8, 2, 8});
    CHECK(canvasSettingsForWidth(8).lowerSize == Int3{8, 5, 8});
    CHECK(canvasSettingsForWidth(3).upperSize == Int3{3, 2, 3});
    CHECK(canvasSettingsForWidth(3).lowerSize == Int3{3, 2, 3});
    CHECK(canvasSettingsForWidth(100).upperSize == Int3{100, 16, 100});
    CHECK(canvasSettingsForWidth(100).lowerSize == Int3{100, 66, 100});
}

TEST_CASE("canvas and sculpture grid sizes are exactly those of the scenes built") {
    for (int width : {8, 13, 60}) {
        const Scene canvas = makeCanvasScene(canvasSettingsForWidth(width));
        const SceneGridSizes sizes = sceneGridSizes(SceneKind::Canvas, {width, width, width});
        CHECK(canvas.grid(GridLevel::Upper).size() == sizes.upper);
        CHECK(canvas.grid(GridLevel::Lower).size() == sizes.lower);
    }
    for (int resolution : {5, 10, 17}) {
        const InsideMask ball = makeSphereMask(resolution);
        const Scene sculpture = makeSculptureScene(ball);
        const SceneGridSizes sizes = sceneGridSizes(SceneKind::Sculpture, ball.size);
        CHECK(sizes.upper == Int3{2 * resolution, resolution, 2 * resolution});
        CHECK(sizes.lower == Int3{2 * resolution, 2 * resolution, 2 * resolution});
        CHECK(sculpture.grid(GridLevel::Upper).size() == sizes.upper);
        CHECK(sculpture.grid(GridLevel::Lower).size() == sizes.lower);
    }
}

TEST_CASE("hourglass grid sizes bound the grids of the scene built, with and without a neck") {
    for (const InsideMask& vessel : {makeHourglassMask({32, 2.0f}), makeHourglassMask({61, 3.0f}), makeCubeMask(12)}) {
        const Scene scene = makeHourglassScene(vessel);
        const SceneGridSizes bound = sceneGridSizes(SceneKind::Hourglass, vessel.size);
        for (GridLevel level : {GridLevel::Upper, GridLevel::Lower}) {
            const Int3 built = scene.grid(level).size();
            const Int3 most = level == GridLevel::Upper ? bound.upper : bound.lower;
            CHECK(built.x <= most.x);
            CHECK(built.y <= most.y);
            CHECK(built.z <= most.z);
        }
    }
}

TEST_CASE("memory estimates keep the application's numbers per cell") {
    const Int3 mask{10, 20, 30}; // 6000 cells
    CHECK(estimateMaskBytes(mask) == 6000u * 2);
    // A grid cell is 5 bytes (the live cell, a layout bit, the sweep's bits), a grain 32, a fill entry 4.
    CHECK(estimateSceneBytes(SceneKind::Hourglass, mask) == 6000u * (2 * 5 + 48));
    CHECK(estimateSceneBytes(SceneKind::Sculpture, mask) == 6000u * (12 * 5 + 48 + 4));
    // The canvas counts its grid cells: 60 x 60 x (10 + 40).
    CHECK(estimateSceneBytes(SceneKind::Canvas, {60, 60, 60}) == 60u * 60 * 50 * 11);
    CHECK(estimateSceneBytes(SceneKind::Canvas, {60, 0, 0}) == 60u * 60 * 50 * 11); // y and z unused
}

TEST_CASE("memory estimates cover the grids and grains of the scene built") {
    const InsideMask vessel = makeHourglassMask({48, 3.0f});
    const InsideMask ball = makeSphereMask(16);
    for (SceneKind kind : {SceneKind::Hourglass, SceneKind::Sculpture}) {
        const InsideMask& mask = kind == SceneKind::Hourglass ? vessel : ball;
        const Scene scene = kind == SceneKind::Hourglass ? makeHourglassScene(mask) : makeSculptureScene(mask);
        // The live grid, a layout bit and the sweep's awake and occupied bits for every cell, and
        // each grain's record (41 bytes of fields).
        const std::uint64_t gridCells = cells(scene.grid(GridLevel::Upper).size()) + cells(scene.grid(GridLevel::Lower).size());
        const std::uint64_t held = sizeof(CellValue) * gridCells + 3 * gridCells / 8 + 41u * std::uint64_t(scene.grainCount());
        CHECK(estimateSceneBytes(kind, mask.size) >= held);
    }
}

TEST_CASE("memory estimates are 0 for empty sizes and saturate instead of wrapping") {
    CHECK(estimateSceneBytes(SceneKind::Hourglass, {0, 10, 10}) == 0);
    CHECK(estimateSceneBytes(SceneKind::Sculpture, {10, -1, 10}) == 0);
    CHECK(estimateSceneBytes(SceneKind::Canvas, {0, 10, 10}) == 0);
    CHECK(estimateMaskBytes({10, 10, 0}) == 0);
    const int huge = std::numeric_limits<int>::max();
    CHECK(estimateSceneBytes(SceneKind::Sculpture, {huge, huge, huge}) == std::numeric_limits<std::uint64_t>::max());
    CHECK(estimateMaskBytes({huge, huge, huge}) == std::numeric_limits<std::uint64_t>::max());
}

TEST_CASE("scene grid sizes are validated before anything is allocated") {
    // A 1024^3 model makes a 2048^3 lower grid: 2^33 cells, over the limit.
    CHECK_THROWS_AS(validateSceneGridSizes(SceneKind::Sculpture, {1024, 1024, 1024}), std::invalid_argument);
    CHECK_NOTHROW(validateSceneGridSizes(SceneKind::Sculpture, {512, 512, 512}));
    CHECK_NOTHROW(validateSceneGridSizes(SceneKind::Hourglass, {1290, 1290, 1290}));
    CHECK_THROWS_AS(validateSceneGridSizes(SceneKind::Hourglass, {1291, 1291, 1291}), std::invalid_argument);
    CHECK_THROWS_AS(validateSceneGridSizes(SceneKind::Sculpture, {1 << 30, 1 << 30, 1 << 30}), std::invalid_argument);
    CHECK_THROWS_AS(validateSceneGridSizes(SceneKind::Canvas, {0, 60, 60}), std::invalid_argument);
    CHECK_NOTHROW(validateSceneGridSizes(SceneKind::Canvas, {60, 60, 60}));
}
