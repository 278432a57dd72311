// SPDX-License-Identifier: MIT
// SPEC I5: while a scene is built the window shows its phase and a Cancel; the button and Esc
// stop the build and the running scene goes on unchanged.
#include "support/app_test_support.hpp"
#include "support/phase_gate.hpp"

#include <GLFW/glfw3.h>
#include <doctest/doctest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <chrono>
#include <thread>

using namespace sandglass;

namespace {

ApplicationOptions proceduralHourglassWindow() {
    // Panels hidden: the build's window shows without them, and nothing lies over it.
    return testing::proceduralHourglassOptions(640, 480, 20, "build progress test");
}

// Asks for the bundled hourglass model, held at voxelizing by `gate`, and draws the frames
// that start it and show it.
void startHeldModelBuild(Application& app, testing::PhaseGate& gate) {
    app.host().setBuildPhaseListener(gate.listener());
    app.state().scene.request.shape.clear();
    app.state().scene.request.modelPath = defaultModelFor(sandcore::SceneKind::Hourglass);
    app.state().scene.request.resolution = 24;
    app.state().commands.push(Command::Rebuild);
    app.renderFrame(0.0); // serves the rebuild
    REQUIRE(gate.waitUntilReached());
    app.renderFrame(0.0); // shows it
    app.renderFrame(0.0); // where it stays: an auto-sized window finds its size in its first frame
}

void waitForBuild(Application& app) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    app.serveCommands();
    while (app.host().building() && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        app.serveCommands();
    }
    REQUIRE_FALSE(app.host().building());
}

// The running scene is the procedural hourglass it was, steps and all.
void checkSceneKept(Application& app, std::uint64_t hash) {
    CHECK(app.state().statusLine == "build cancelled; the running scene is kept");
    CHECK(app.scene().stateHash() == hash);
    CHECK(app.host().loaded().request.shape == "hourglass");
    CHECK(app.state().scene.request.modelPath.empty()); // the panel shows the running scene again
    app.renderFrame(0.0);
    const ImGuiWindow* window = ImGui::FindWindowByName("Building scene");
    CHECK((window == nullptr || !window->Active));
}

} // namespace

TEST_CASE("build progress window: a build shows its phase, and Cancel keeps the running scene") {
    if (!testing::requireDisplay("the build progress window")) return;
    std::optional<Application> app = testing::openApplication(proceduralHourglassWindow(), "the build progress window");
    if (!app) return;
    app->runSteps(10);
    const std::uint64_t hash = app->scene().stateHash();
    testing::PhaseGate gate(BuildPhase::Voxelizing);
    startHeldModelBuild(*app, gate);

    CHECK(app->state().building);
    CHECK(app->state().build.phase == "voxelizing");
    CHECK(app->state().build.shareDone == buildShareAtStart(BuildPhase::Voxelizing));
    const ImGuiWindow* window = ImGui::FindWindowByName("Building scene");
    REQUIRE(window != nullptr);
    CHECK(window->Active);
    // Cancel is the window's last item: its right edge and its line's top are where the layout went on from.
    const ImVec2 end = window->DC.CursorPosPrevLine;
    const float height = window->DC.PrevLineSize.y;
    REQUIRE(height > 0.0f);
    const double x = end.x - 4.0, y = end.y + height * 0.5;
    CHECK(window->Rect().Contains(ImVec2(float(x), float(y))));
    app->queueMouseButton(GLFW_MOUSE_BUTTON_LEFT, true, x, y);
    app->queueMouseButton(GLFW_MOUSE_BUTTON_LEFT, false, x, y);
    app->renderFrame(0.0);
    REQUIRE(app->host().buildProgress() != nullptr);
    CHECK(app->host().buildProgress()->cancelRequested());
    CHECK(app->state().build.cancelling);

    gate.open();
    waitForBuild(*app);
    checkSceneKept(*app, hash);
}

TEST_CASE("build progress window: Esc cancels a build instead of quitting, and quits once none runs") {
    if (!testing::requireDisplay("Esc during a build")) return;
    std::optional<Application> app = testing::openApplication(proceduralHourglassWindow(), "Esc during a build");
    if (!app) return;
    const std::uint64_t hash = app->scene().stateHash();
    testing::PhaseGate gate(BuildPhase::Voxelizing);
    startHeldModelBuild(*app, gate);

    // The key as GLFW delivers it, through the application's own callback.
    GLFWwindow* handle = app->window().handle();
    const GLFWkeyfun keyCallback = glfwSetKeyCallback(handle, nullptr);
    glfwSetKeyCallback(handle, keyCallback);
    REQUIRE(bool(keyCallback));
    keyCallback(handle, GLFW_KEY_ESCAPE, 0, GLFW_PRESS, 0);
    CHECK_FALSE(app->state().commands.contains(Command::Quit));
    app->renderFrame(0.0);
    REQUIRE(app->host().buildProgress() != nullptr);
    CHECK(app->host().buildProgress()->cancelRequested());
    gate.open();
    waitForBuild(*app);
    checkSceneKept(*app, hash);

    // With no build left, Esc quits as ever.
    keyCallback(handle, GLFW_KEY_ESCAPE, 0, GLFW_PRESS, 0);
    CHECK(app->state().commands.contains(Command::Quit));
}
