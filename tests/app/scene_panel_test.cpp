// SPDX-License-Identifier: MIT
// SPEC U3: the Scene panel shows what runs. A typed model path that fails to load never becomes
// the current model: the panel's choice goes back to the loaded model, the summary names it, and
// the next rebuild (a new resolution) builds from what is shown.
#include "support/app_test_support.hpp"

#include "gui/panels.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>
#include <thread>

using namespace sandglass;

namespace {

void waitForBuild(Application& app) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    app.serveCommands();
    while (app.host().building() && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        app.serveCommands();
    }
    REQUIRE_FALSE(app.host().building());
}

} // namespace

TEST_CASE("scene panel: a model path that fails leaves the shown and the loaded model the same") {
    if (!testing::requireDisplay("the scene panel")) return;
    ApplicationOptions options;
    options.window = {320, 240, false, false, "scene panel test"};
    options.offscreen = true;
    options.initial.scene.request.kind = sandcore::SceneKind::Sculpture;
    options.initial.scene.request.modelPath = defaultModelFor(sandcore::SceneKind::Sculpture);
    options.initial.scene.request.resolution = 24;
    std::optional<Application> app = testing::openApplication(std::move(options), "the scene panel");
    if (!app) return;
    app->renderFrame(0.0); // the panels are built (showGui is on)
    AppState& state = app->state();
    const std::string model = state.loaded.request.modelPath;
    REQUIRE(std::filesystem::path(model).filename() == "snowman.obj");
    CHECK(state.scene.request.modelPath == model);
    CHECK(sceneSummary(state.loaded.request).find("snowman.obj") != std::string::npos);

    // What the panel's path field does on Enter.
    state.scene.request.modelPath = "/no/such/folder/missing-model.obj";
    state.commands.push(Command::Rebuild);
    waitForBuild(*app);
    app->renderFrame(0.0);
    CHECK(state.statusLine.find("missing-model.obj") != std::string::npos);
    CHECK(state.loaded.request.modelPath == model);
    CHECK(app->host().loaded().request.modelPath == model);
    CHECK(state.scene.request.modelPath == model); // the panel shows the loaded model again
    CHECK(sceneSummary(state.loaded.request).find("snowman.obj") != std::string::npos);

    // The resolution slider's rebuild builds what is shown, not the path that failed.
    state.scene.request.resolution = 28;
    state.commands.push(Command::Rebuild);
    waitForBuild(*app);
    CHECK(app->host().loaded().request.modelPath == model);
    CHECK(app->host().loaded().request.resolution == 28);
    CHECK(state.scene.request.modelPath == state.loaded.request.modelPath);
    CHECK(sceneSummary(state.loaded.request).find("resolution 28") != std::string::npos);
}

TEST_CASE("scene panel: the summary names the built-in shape or the canvas") {
    SceneRequest request;
    request.kind = sandcore::SceneKind::Hourglass;
    request.modelPath.clear();
    request.shape = "hourglass";
    request.resolution = 40;
    CHECK(sceneSummary(request) == "hourglass: hourglass (built-in shape), resolution 40");
    request.kind = sandcore::SceneKind::Canvas;
    request.shape.clear();
    CHECK(sceneSummary(request) == "canvas, resolution 40");
}
