// SPDX-License-Identifier: MIT
// The hourglass as a timer in the window, and the canvas's first contact: the rate holds when
// frames are slow, a turn animates the view, and a first stroke on a fresh canvas shows sand
// under the cursor's path.
#include "support/app_test_support.hpp"

#include "app/application.hpp"
#include "app/cli/view_options.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace sandglass;

namespace {

ApplicationOptions hiddenWindow(const char* scene, int resolution) {
    ViewOptions view;
    view.scene.scene = scene;
    view.scene.settings.request.resolution = resolution;
    view.size = "640x480";
    ApplicationOptions options = applicationOptionsFrom(view, 640, 480);
    options.window.visible = false;
    options.window.vsync = false;
    options.offscreen = true;
    options.initial.showGui = false;
    return options;
}

} // namespace

TEST_CASE("window: at 3 frames per second the flow of 30 steps/s is kept, and the readout says so") {
    std::optional<Application> app = testing::openApplication(hiddenWindow("hourglass", 40), "the step rate");
    if (!app) return;
    app->state().simulationRunning = true;
    app->state().stepsPerSecond = 30.0;
    const std::uint64_t before = app->scene().counters().stepsDone;
    for (int frame = 0; frame < 12; ++frame) app->renderFrame(1.0 / 3.0); // 4 s of slow frames
    const double stepsRun = double(app->scene().counters().stepsDone - before);
    CHECK(stepsRun == doctest::Approx(120.0).epsilon(0.02));
    CHECK(app->state().stats.stepsPerSecond == doctest::Approx(30.0).epsilon(0.02));
    CHECK_FALSE(app->state().stats.rateCapped);
    // Faster frames than the flow: the readout is still the flow, not the rate of frames with a step.
    for (int frame = 0; frame < 240; ++frame) app->renderFrame(1.0 / 120.0);
    CHECK(app->state().stats.stepsPerSecond == doctest::Approx(30.0).epsilon(0.02));
}

TEST_CASE("window: steps run before the first frame are not timed, so the readout has no ms per step until one runs") {
    std::optional<Application> app = testing::openApplication(hiddenWindow("hourglass", 40), "the step readout");
    if (!app) return;
    app->runSteps(50); // as --steps does: the panel then says that no step was timed yet
    app->renderFrame(0.0);
    CHECK(app->scene().counters().stepsDone == 50);
    CHECK(app->state().stats.millisecondsPerStep == 0.0f);
    app->state().simulationRunning = true;
    app->state().stepsPerSecond = 30.0;
    app->renderFrame(1.0 / 3.0); // 10 steps, each timed
    CHECK(app->scene().counters().stepsDone == 60);
    CHECK(app->state().stats.millisecondsPerStep > 0.0f);
}

TEST_CASE("window: T turns the hourglass over, the view turns back upright, and two turns are the identity") {
    std::optional<Application> app = testing::openApplication(hiddenWindow("hourglass", 40), "turning over");
    if (!app) return;
    app->runSteps(100);
    const std::uint64_t hash = app->scene().stateHash();
    app->state().commands.push(Command::Flip);
    app->renderFrame(0.0);
    CHECK(app->scene().flipped());
    CHECK(app->camera().turn() > 3.0f); // starts upside down, so the picture does not jump
    app->state().commands.push(Command::Flip);
    app->renderFrame(0.0);
    CHECK(app->scene().stateHash() == hash);
}

TEST_CASE("canvas: a first stroke on a fresh canvas puts sand under the cursor's path on screen") {
    std::optional<Application> app = testing::openApplication(hiddenWindow("canvas", 60), "the first stroke");
    if (!app) return;
    app->renderFrame(0.0);
    const RgbImage empty = app->captureFrame();
    // A stroke across the middle of the window, as a hand would draw it, at 30 frames per second.
    const double y = 240.0;
    for (double x = 220.0; x <= 420.0; x += 4.0) {
        app->handleCanvasPointer({x, y, true, false, false});
        app->renderFrame(1.0 / 30.0);
    }
    app->handleCanvasPointer({420.0, y, false, false, false});
    for (int frame = 0; frame < 90; ++frame) app->renderFrame(1.0 / 30.0);
    CHECK(app->scene().grainCount() > 0);
    const RgbImage drawn = app->captureFrame();
    // Where did the sand appear? Rows of pixels that changed, around the stroke's path.
    int changedNearPath = 0, changedElsewhere = 0;
    for (int py = 0; py < drawn.height; ++py)
        for (int px = 0; px < drawn.width; ++px) {
            const auto a = testing::pixelAt(empty, px, py), b = testing::pixelAt(drawn, px, py);
            if (std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) < 60) continue;
            const bool near = px >= 200 && px <= 440 && std::abs(py - int(y)) <= 24;
            (near ? changedNearPath : changedElsewhere) += 1;
        }
    CAPTURE(changedNearPath);
    CAPTURE(changedElsewhere);
    CHECK(changedNearPath > 400);
    CHECK(changedNearPath > 4 * changedElsewhere);
}
