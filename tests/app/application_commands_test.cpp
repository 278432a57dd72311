// SPDX-License-Identifier: MIT
// The application's own commands with a real GL context: what a frame shows after steps made
// outside the running clock (single step, `render --steps`), rebuild requests during a build,
// and the B benchmark leaving the user's scene as it was.
#include "support/app_test_support.hpp"

#include "app/application.hpp"
#include "app/frame_benchmark_runner.hpp"

#include <GLFW/glfw3.h>

#include "sandcore/display_positions.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <optional>
#include <thread>

using namespace sandglass;

namespace {

ApplicationOptions smallHourglass(int stepsBeforeStart) {
    ApplicationOptions options;
    options.window = {96, 96, false, false, "sandglass application test"};
    options.offscreen = true;
    options.initial.showGui = false;
    options.initial.render.hull = false;
    options.initial.render.innerGrains = true; // every grain is an instance, in grain order
    options.initial.scene.request.kind = sandcore::SceneKind::Hourglass;
    options.initial.scene.request.modelPath.clear();
    options.initial.scene.request.shape = "hourglass";
    options.initial.scene.request.resolution = 24;
    options.stepsBeforeStart = stepsBeforeStart;
    return options;
}

std::optional<Application> open(ApplicationOptions options) {
    return testing::openApplication(std::move(options), "application");
}

// Every grain moved by the last step is drawn exactly at its new cell's display point (its
// position as the GPU computes it, read back); returns how many such grains there were
// (transitions between the grids keep their world cell and are not among them).
std::int64_t checkMovedGrainsDrawnAtTheirCells(Application& app) {
    const sandcore::Scene& scene = app.scene();
    const sandcore::GrainStore& grains = scene.grains();
    const RenderSettings& render = app.state().render;
    const std::vector<sandcore::Vec3> drawn = app.renderer().readBackGpuPositions(scene, app.displayStepFraction(), render);
    REQUIRE(drawn.size() == std::size_t(grains.size()));
    std::int64_t moved = 0;
    for (std::uint32_t id = 0; id < grains.size(); ++id) {
        if (grains.place[id].movedAtStep != scene.counters().stepsDone) continue;
        ++moved;
        const sandcore::Vec3 cell = sandcore::cellDisplayPoint(scene, grains.level[id], grains.place[id].cell,
                                                               grains.identity[id], {render.cellSize, render.jitter});
        CAPTURE(id);
        CHECK(drawn[id].x == cell.x);
        CHECK(drawn[id].y == cell.y);
        CHECK(drawn[id].z == cell.z);
    }
    return moved;
}

} // namespace

TEST_CASE("application: `render --steps N` draws the state after N steps with grains at their cells") {
    if (!testing::requireDisplay("the rendered step")) return;
    // The render command's setup: steps before the first frame, simulation off, no time passing.
    std::optional<Application> app = open(smallHourglass(30));
    if (!app) return;
    app->renderFrame(0.0);
    REQUIRE(app->scene().counters().stepsDone == 30);
    REQUIRE(app->scene().counters().movesLastStep > 0);
    CHECK(app->displayStepFraction() == 1.0f);
    CHECK(checkMovedGrainsDrawnAtTheirCells(*app) > 0);
}

TEST_CASE("application: a single step while paused shows the grains that moved at their new cells") {
    if (!testing::requireDisplay("the single step")) return;
    std::optional<Application> app = open(smallHourglass(0));
    if (!app) return;
    app->state().simulationRunning = true;
    for (int frame = 0; frame < 20; ++frame) app->renderFrame(1.0 / 45.0); // sand on its way, mid-glide
    app->state().simulationRunning = false;
    app->renderFrame(1.0 / 45.0);
    const std::uint64_t stepsBefore = app->scene().counters().stepsDone;
    REQUIRE(stepsBefore > 0);

    app->state().commands.push(Command::SingleStep);
    app->renderFrame(1.0 / 45.0);
    REQUIRE(app->scene().counters().stepsDone == stepsBefore + 1);
    REQUIRE(app->scene().counters().movesLastStep > 0);
    CHECK(app->displayStepFraction() == 1.0f);
    CHECK(checkMovedGrainsDrawnAtTheirCells(*app) > 0);
    app->renderFrame(1.0 / 45.0); // still paused: the frame stays as it is
    CHECK(app->displayStepFraction() == 1.0f);

    // Running again, the clock's steps glide as before.
    app->state().simulationRunning = true;
    for (int frame = 0; frame < 5; ++frame) app->renderFrame(1.0 / 45.0);
    CHECK(app->displayStepFraction() < 1.0f);
}

TEST_CASE("application: a rebuild requested while a build runs is built next, so the last request wins") {
    if (!testing::requireDisplay("rebuilding")) return;
    std::optional<Application> app = open(smallHourglass(0));
    if (!app) return;
    SceneRequest& request = app->state().scene.request;
    request.kind = sandcore::SceneKind::Canvas;
    request.resolution = 160; // big enough that the second request usually finds it still building
    app->state().commands.push(Command::Rebuild);
    app->serveCommands();
    CHECK(app->state().loaded.request.kind == sandcore::SceneKind::Hourglass); // not adopted yet
    const bool firstStillBuilding = app->host().building();
    request.resolution = 40;
    app->state().commands.push(Command::Rebuild);
    app->serveCommands();
    if (firstStillBuilding && app->host().building()) CHECK(app->host().buildWaiting()); // waits, not dropped
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (app->host().building() && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        app->serveCommands();
    }
    REQUIRE_FALSE(app->host().building());
    CHECK(app->host().kind() == sandcore::SceneKind::Canvas);
    CHECK(app->state().loaded.request.kind == sandcore::SceneKind::Canvas);
    CHECK(app->scene().grid(sandcore::GridLevel::Lower).size().x == 40);
}

TEST_CASE("application: the benchmark leaves the user's scene as it was (state hash)") {
    if (!testing::requireDisplay("the benchmark")) return;
    std::optional<Application> app = open(smallHourglass(0));
    if (!app) return;
    app->runSteps(60); // partly drained: not the state a reset gives
    const std::uint64_t before = app->scene().stateHash();
    const std::uint64_t stepsBefore = app->scene().counters().stepsDone;
    const RenderSettings renderBefore = app->state().render;

    BenchmarkTiming timing;
    timing.warmupFrames = 1;
    timing.minFrames = 3;
    timing.maxFrames = 3;
    timing.maxSeconds = 5.0;
    BenchmarkCase points, pseudo; // the thesis's look
    points.mode = RenderMode::Points;
    points.grainsPerCell = 1;
    pseudo.mode = RenderMode::PseudoBillboards;
    pseudo.grainsPerCell = 4;
    pseudo.lighting = true;
    pseudo.innerGrains = false;
    const BenchmarkReport report = runFrameBenchmark(*app, {points, pseudo}, timing);
    REQUIRE(report.rows.size() == 2);
    for (const BenchmarkRow& row : report.rows) { // B1: every row timed on the GPU too
        CHECK(row.gpuMillisecondsPerFrame > 0.0);
        CHECK(row.cpuMillisecondsPerFrame >= row.appCpuMillisecondsPerFrame);
    }
    CHECK(app->scene().stateHash() == before);
    CHECK(app->scene().counters().stepsDone == stepsBefore);
    CHECK(app->state().render.mode == renderBefore.mode);
    CHECK_FALSE(app->state().simulationRunning);
}

TEST_CASE("application: seed and threads from the panel apply to the next step without a rebuild") {
    if (!testing::requireDisplay("step settings")) return;
    std::optional<Application> app = open(smallHourglass(0));
    if (!app) return;
    app->runSteps(10);
    const std::uint64_t stepsBefore = app->scene().counters().stepsDone;
    app->state().scene.step.threads = 2;
    app->state().scene.step.seed = 5;
    app->state().commands.push(Command::ApplyStepSettings);
    app->serveCommands();
    CHECK_FALSE(app->host().building());
    CHECK(app->scene().settings().threads == 2);
    CHECK(app->scene().settings().seed == 5);
    CHECK(app->scene().counters().stepsDone == stepsBefore); // the same scene runs on
}

TEST_CASE("application: Esc during the frame benchmark stops it without quitting, and says so") {
    if (!testing::requireDisplay("cancelling the benchmark")) return;
    std::optional<Application> app = open(smallHourglass(0));
    if (!app) return;
    GLFWwindow* handle = app->window().handle();
    const GLFWkeyfun keyCallback = glfwSetKeyCallback(handle, nullptr);
    glfwSetKeyCallback(handle, keyCallback);
    REQUIRE(bool(keyCallback));
    BenchmarkTiming timing;
    timing.minFrames = 2;
    timing.maxFrames = 2;
    timing.warmupFrames = 0;
    int frames = 0;
    std::vector<Application::BenchmarkProgress> seen;
    const std::vector<BenchmarkCase> cases(6, BenchmarkCase{});
    const BenchmarkReport report = runFrameBenchmark(*app, cases, timing, [&] {
        seen.push_back(app->benchmarkProgress());
        if (++frames == 5) keyCallback(handle, GLFW_KEY_ESCAPE, 0, GLFW_PRESS, 0); // Esc in the third row
    });
    CHECK(report.cancelled);
    CHECK(report.rows.size() == 2); // the rows finished before Esc
    REQUIRE(seen.size() >= 5);
    CHECK(seen.front().running);
    CHECK(seen.front().rows == 6);
    CHECK(seen[4].rowsDone == 2);
    CHECK_FALSE(app->state().commands.contains(Command::Quit)); // Esc stopped the benchmark, not the program
    CHECK_FALSE(app->benchmarkProgress().running);
    // Esc after the benchmark quits, as ever.
    keyCallback(handle, GLFW_KEY_ESCAPE, 0, GLFW_PRESS, 0);
    CHECK(app->state().commands.contains(Command::Quit));
}
