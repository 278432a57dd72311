// SPDX-License-Identifier: MIT
// SPEC V8 (with R8): grains kept on the GPU, only what changed uploaded, positions worked out by
// the vertex shader. The GPU's positions, read back by transform feedback, equal the CPU's
// writeDisplayPositions after steps and after every kind of edit; a step uploads in proportion
// to the grains it moved, a settled scene nothing; and both paths draw the same picture.
#include "support/app_test_support.hpp"

#include "app/application.hpp"
#include "scene/scene_host.hpp"
#include "view/render/scene_renderer.hpp"
#include "view/render/shader_program.hpp"

#include "sandcore/display_positions.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <vector>

using namespace sandglass;

namespace {

ApplicationOptions hourglassOptions(int resolution, int steps, RenderSettings render = {}) {
    ApplicationOptions options = testing::proceduralHourglassOptions(160, 160, resolution, "sandglass gpu upload test");
    options.initial.render = render;
    options.initial.simulationRunning = false;
    options.stepsBeforeStart = steps;
    return options;
}

SceneSettings hourglassSettings(int resolution) {
    SceneSettings settings;
    settings.request.kind = sandcore::SceneKind::Hourglass;
    settings.request.shape = "hourglass";
    settings.request.resolution = resolution;
    applySceneDefaults(settings);
    return settings;
}

// R8 on the GPU: every grain exactly where the CPU puts it.
void requireGpuEqualsCpu(SceneRenderer& renderer, const sandcore::Scene& scene, float stepFraction,
                         const RenderSettings& settings) {
    CAPTURE(stepFraction);
    const std::vector<sandcore::Vec3> gpu = renderer.captureGpuPositions(scene, stepFraction, settings);
    std::vector<sandcore::Vec3> cpu(scene.grains().size());
    sandcore::writeDisplayPositions(scene, stepFraction, {settings.cellSize, settings.jitter}, cpu);
    REQUIRE(gpu.size() == cpu.size());
    int gliding = 0;
    for (std::size_t id = 0; id < cpu.size(); ++id) {
        CAPTURE(id);
        REQUIRE(gpu[id].x == cpu[id].x);
        REQUIRE(gpu[id].y == cpu[id].y);
        REQUIRE(gpu[id].z == cpu[id].z);
        gliding += scene.grains().place[id].movedAtStep == scene.counters().stepsDone ? 1 : 0;
    }
    (void)gliding;
}

} // namespace

TEST_CASE("V8: the GPU's display positions equal writeDisplayPositions after steps, mid-glide too") {
    if (!testing::requireDisplay("GPU display positions")) return;
    std::optional<Application> app = testing::openApplication(hourglassOptions(24, 0), "GPU display positions");
    if (!app) return; // its context is current: the renderer below draws into it
    SceneHost host(hourglassSettings(24));
    SceneRenderer renderer(shaderDirectory());
    RenderSettings settings = thesisLook(); // unlit: the surface below keeps no per-grain keys
    settings.cellSize = 0.37f; // not a power of two: every rounding step shows
    settings.jitter = 0.8f;
    renderer.setScene(host.scene(), host.kind(), settings.cellSize);
    renderer.useSurface(&host.surfaceUpkeep(false));
    requireGpuEqualsCpu(renderer, host.scene(), 1.0f, settings);
    std::int64_t moved = 0;
    for (int step = 0; step < 60; ++step) {
        host.runSteps(1);
        moved += host.scene().counters().movesLastStep;
        for (float fraction : {0.0f, 0.3f, 0.75f, 1.0f}) requireGpuEqualsCpu(renderer, host.scene(), fraction, settings);
        REQUIRE(!renderer.stats().fullUpload); // a step goes up as changes only
    }
    CHECK(moved > 0);
    CHECK(host.scene().counters().grainsLower > 0); // grains crossed into the lower grid
}

TEST_CASE("V8: on 2 threads the places and cell bits, written by both threads, leave the GPU equal to the scene") {
    if (!testing::requireDisplay("stores shared among threads")) return;
    std::optional<Application> app = testing::openApplication(hourglassOptions(24, 0), "stores shared among threads");
    if (!app) return;
    SceneSettings scene = hourglassSettings(160);
    scene.step.threads = 2;
    SceneHost host(scene);
    SceneRenderer renderer(shaderDirectory());
    RenderSettings settings;
    settings.lighting = true; // inner grains drawn and lit: the cell bits path on any GL
    renderer.setScene(host.scene(), host.kind(), settings.cellSize);
    host.runSteps(150);
    renderer.useSurface(&host.surfaceUpkeep(renderer.gpuStore().trackingFor(host.scene(), settings)));
    requireGpuEqualsCpu(renderer, host.scene(), 1.0f, settings);
    std::size_t mostMoves = 0, mostChanges = 0;
    for (int step = 0; step < 4; ++step) {
        host.runSteps(1);
        mostMoves = std::max(mostMoves, host.scene().movedGrains().size());
        mostChanges = std::max(mostChanges, host.surfaceUpkeep(renderer.gpuStore().trackingFor(host.scene(), settings)).changedCells().size());
        requireGpuEqualsCpu(renderer, host.scene(), 0.5f, settings);
        REQUIRE(!renderer.stats().fullUpload);
    }
    // Enough for both stores to be shared out (2048 places, 1024 changed cells and more).
    CHECK(mostMoves >= 2048);
    CHECK(mostChanges >= 1024);
    // The cell bits the GPU holds are the grids' occupancy, word for word.
    const GrainGpuStore& store = renderer.gpuStore();
    REQUIRE(store.flagsFromBits());
    const std::vector<std::uint32_t> words = store.readCellBits();
    std::size_t compared = 0;
    for (int set = 0; set < 4; ++set) {
        const auto level = set % 2 == 1 ? sandcore::GridLevel::Upper : sandcore::GridLevel::Lower;
        const sandcore::CellGrid& grid = host.scene().grid(level);
        const std::size_t first = std::size_t(store.cellBitsOffsets()[std::size_t(set)]);
        for (std::uint32_t cell = 0; cell < grid.cellCount(); ++cell) {
            const bool bit = ((words.at(first + cell / 32) >> (cell % 32)) & 1u) != 0;
            const bool expected = set < 2 ? grid[cell] >= 0 : grid[cell] != sandcore::kEmpty;
            if (bit != expected) FAIL_CHECK("set " << set << " cell " << cell);
            ++compared;
        }
    }
    CHECK(compared > 0);
}

TEST_CASE("V8: every edit that bypasses the step uploads everything, and the GPU then matches the scene") {
    if (!testing::requireDisplay("uploads after edits")) return;
    std::optional<Application> app = testing::openApplication(hourglassOptions(24, 0), "uploads after edits");
    if (!app) return;
    SceneHost host(hourglassSettings(24));
    SceneRenderer renderer(shaderDirectory());
    RenderSettings settings = thesisLook(); // unlit: the surface below keeps no per-grain keys
    renderer.setScene(host.scene(), host.kind(), settings.cellSize);
    host.runSteps(40);
    // The renderer is told nothing but the surface: as the application draws.
    auto frameAfter = [&](const char* what, bool full) {
        CAPTURE(what);
        renderer.useSurface(&host.surfaceUpkeep(false));
        requireGpuEqualsCpu(renderer, host.scene(), 1.0f, settings);
        CHECK(renderer.stats().fullUpload == full);
    };
    frameAfter("first frame", true);
    host.runSteps(1);
    frameAfter("a step", false);
    frameAfter("nothing", false);
    CHECK(renderer.stats().uploadBytes == 0);
    const sandcore::SceneSnapshot saved = host.scene().snapshot();
    const sandcore::GrainStore& grains = host.scene().grains();
    host.editScene().removeGrain(grains.level[0], grains.place[0].cell); // the last grain takes id 0
    frameAfter("grain removal by swap", true);
    host.runSteps(1);
    frameAfter("a step after the removal", false);
    const sandcore::CellGrid& lower = host.scene().grid(sandcore::GridLevel::Lower);
    host.editScene().addGrain(sandcore::GridLevel::Lower, lower.index(lower.size().x / 2, 1, lower.size().z / 2), 0xff0000ffu);
    frameAfter("painting a grain", true);
    host.editLayout().addObstacle(sandcore::GridLevel::Upper, {{0, 0, 0}, {12, 6, 12}});
    frameAfter("an obstacle", true);
    host.editScene().restore(saved);
    frameAfter("undo", true);
    host.runSteps(2);
    frameAfter("two steps in one frame", false);
    host.flip();
    frameAfter("flip", true);
    host.runSteps(3);
    frameAfter("steps after the flip", false);
    host.reset();
    frameAfter("reset", true);
    host.adoptLoaded(host.scene().clone(), host.loaded());
    frameAfter("a loaded scene", true);
    host.requestBuild(hourglassSettings(20));
    host.finishBuilds();
    renderer.setScene(host.scene(), host.kind(), settings.cellSize); // as the application does on a new layout
    frameAfter("a rebuilt scene", true);
    host.runSteps(5);
    frameAfter("steps in the new scene", false);
    settings.jitter = 0.2f;
    frameAfter("a new jitter", true);
}

TEST_CASE("V8: mid-drain on the res-96 hourglass a frame uploads at most 32 bytes per moved grain plus 4 KiB") {
    if (!testing::requireDisplay("upload per moved grain")) return;
    for (bool light : {false, true}) {
        CAPTURE(light);
        RenderSettings render;
        render.lighting = light;
        render.normals = sandcore::NormalMethod::ColumnHeights;
        std::optional<Application> app = testing::openApplication(hourglassOptions(96, 300, render), "upload per moved grain");
        if (!app) return;
        app->renderFrame(0.0);
        CHECK(app->renderer().stats().fullUpload);
        std::int64_t moved = 0;
        for (int frame = 0; frame < 10; ++frame) {
            app->runSteps(1);
            app->renderFrame(0.0);
            const RenderStats& stats = app->renderer().stats();
            const auto moves = std::int64_t(app->scene().movedGrains().size());
            CAPTURE(moves);
            REQUIRE(!stats.fullUpload);
            CHECK(stats.uploadBytes <= 32 * moves + 4096);
            moved += moves;
        }
        CHECK(moved > 10 * 100); // sand really flows: the bound is not met by an idle scene
        // Frames between steps upload nothing.
        app->renderFrame(0.0);
        CHECK(app->renderer().stats().uploadBytes == 0);
    }
}

TEST_CASE("V8: a settled scene uploads nothing, stepping or not") {
    if (!testing::requireDisplay("settled upload")) return;
    std::optional<Application> app = testing::openApplication(hourglassOptions(16, 0), "settled upload");
    if (!app) return;
    while (!app->scene().settled()) app->runSteps(1);
    app->renderFrame(0.0);
    for (int frame = 0; frame < 3; ++frame) {
        app->runSteps(1);
        app->renderFrame(0.0);
        CHECK(app->renderer().stats().uploadBytes == 0);
    }
}

TEST_CASE("V8: the GPU path draws the same picture as the full CPU upload, every mode, lit and unlit") {
    if (!testing::requireDisplay("same picture on both paths")) return;
    for (RenderMode mode : kRenderModes)
        for (bool light : {false, true})
            for (bool inner : {true, false}) {
                CAPTURE(renderModeName(mode));
                CAPTURE(light);
                CAPTURE(inner);
                std::vector<RgbImage> images;
                for (GrainPath path : {GrainPath::CpuFullUpload, GrainPath::GpuInterpolated}) {
                    RenderSettings render;
                    render.mode = mode;
                    render.lighting = light;
                    render.innerGrains = inner;
                    render.grainPath = path;
                    std::optional<Application> app =
                        testing::openApplication(hourglassOptions(24, 40, render), "same picture on both paths");
                    if (!app) return;
                    app->renderFrame(0.0);
                    images.push_back(app->captureFrame());
                }
                CHECK(testing::differentPixels(images[0], images[1]) == 0);
            }
}

namespace {

// Draws `frames` frames with one step before each (only changes uploaded) and captures the last.
RgbImage pictureAfterSteppedFrames(GrainPath path, int frames, bool* persistent) {
    RenderSettings render;
    render.lighting = true; // by the occupancy gradient: the per-grain normals change too
    render.innerGrains = false; // the visible list changes
    render.grainPath = path;
    std::optional<Application> app = testing::openApplication(hourglassOptions(24, 40, render), "stepped frames");
    REQUIRE(app);
    app->renderFrame(0.0);
    for (int frame = 0; frame < frames; ++frame) {
        app->runSteps(1);
        app->renderFrame(0.0);
        if (path == GrainPath::GpuInterpolated) REQUIRE(!app->renderer().stats().fullUpload);
    }
    if (persistent != nullptr) *persistent = app->renderer().gpuStore().persistent();
    return app->captureFrame();
}

} // namespace

TEST_CASE("V8: after frames that upload only changes, both grain paths draw the same picture, mapped buffers or not") {
    if (!testing::requireDisplay("same picture after changes")) return;
    const RgbImage reference = pictureAfterSteppedFrames(GrainPath::CpuFullUpload, 12, nullptr);
    for (bool mapping : {true, false}) {
        CAPTURE(mapping);
        if (!mapping) setenv("SANDGLASS_GL_BUFFER_STORAGE", "0", 1);
        bool persistent = false;
        const RgbImage gpu = pictureAfterSteppedFrames(GrainPath::GpuInterpolated, 12, &persistent);
        unsetenv("SANDGLASS_GL_BUFFER_STORAGE");
        if (!mapping) CHECK(!persistent); // the runs path really ran
        CHECK(testing::differentPixels(gpu, reference) == 0);
    }
}
