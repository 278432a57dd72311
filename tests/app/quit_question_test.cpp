// SPDX-License-Identifier: MIT
// SPEC U5: quitting with unsaved painting asks first (Esc, the Exit button or the window's close
// button); without unsaved changes it quits at once; "Save and quit" keeps the work in the file.
#include "support/app_test_support.hpp"
#include "support/temporary_folder.hpp"

#include "app/application.hpp"
#include "scene/state_file.hpp"

#include <doctest/doctest.h>

#include <optional>

using namespace sandglass;

namespace {

// A canvas with one stroke painted on it, run for at most `frames` frames.
bool paintedCanvas(std::optional<Application>& app, int frames) {
    ApplicationOptions options = testing::canvasOptions(160, 120, 24, "sandglass quit test");
    options.frameLimit = frames;
    if (!testing::openApplicationInto(app, std::move(options), "the quit question")) return false;
    // A press and a release in the middle of the canvas: one stroke.
    app->handleCanvasPointer({80.0, 60.0, true, false, false});
    app->handleCanvasPointer({82.0, 60.0, true, false, false});
    app->handleCanvasPointer({82.0, 60.0, false, false, false});
    return true;
}

} // namespace

TEST_CASE("quit question: nothing painted quits at once") {
    std::optional<Application> app;
    ApplicationOptions options = testing::canvasOptions(160, 120, 24, "sandglass quit test");
    options.frameLimit = 5;
    if (!testing::openApplicationInto(app, std::move(options), "the quit question")) return;
    app->state().commands.push(Command::Quit);
    CHECK(app->run() == 0);
    CHECK(app->framesDrawn() == 1);
}

TEST_CASE("quit question: unsaved painting asks, Cancel keeps the window, Quit without saving closes it") {
    std::optional<Application> app;
    if (!paintedCanvas(app, 3)) return;
    REQUIRE(app->state().files.unsavedEdits > 0);
    app->state().commands.push(Command::Quit);
    CHECK(app->run() == 0);
    CHECK(app->framesDrawn() == 3); // it did not quit: it asked
    CHECK(app->state().files.confirmQuit);
    // Esc a second time takes the question back.
    app->state().commands.push(Command::Quit);
    app->serveCommands();
    CHECK_FALSE(app->state().files.confirmQuit);
}

TEST_CASE("quit question: Quit without saving closes the window with the painting unsaved") {
    std::optional<Application> app;
    if (!paintedCanvas(app, 50)) return;
    app->state().commands.push(Command::QuitNow);
    CHECK(app->run() == 0);
    CHECK(app->framesDrawn() == 1);
}

TEST_CASE("quit question: Save and quit writes the painting to the state file, then closes") {
    TemporaryFolder folder;
    std::optional<Application> app;
    if (!paintedCanvas(app, 50)) return;
    app->runSteps(20);
    const std::uint64_t painted = app->scene().stateHash();
    app->state().files.statePath = (folder / "painting.sand").string();
    app->state().commands.push(Command::Quit);
    app->serveCommands();
    REQUIRE(app->state().files.confirmQuit);
    app->state().commands.push(Command::SaveAndQuit);
    const std::uint64_t drawnBefore = app->framesDrawn();
    CHECK(app->run() == 0);
    CHECK(app->framesDrawn() == drawnBefore + 1);
    CHECK(app->state().files.unsavedEdits == 0);
    CHECK(loadState(folder / "painting.sand").scene.stateHash() == painted);
}

TEST_CASE("quit question: a save that fails keeps the window open with the reason shown") {
    TemporaryFolder folder;
    std::optional<Application> app;
    if (!paintedCanvas(app, 2)) return;
    app->state().files.statePath = (folder / "missing" / "painting.sand").string();
    app->state().commands.push(Command::SaveAndQuit);
    CHECK(app->run() == 0);
    CHECK(app->framesDrawn() == 2);
    CHECK(app->state().statusLine.find("missing") != std::string::npos);
    CHECK(app->state().files.unsavedEdits > 0);
}

TEST_CASE("quit question: saving or opening a file clears the unsaved mark") {
    TemporaryFolder folder;
    std::optional<Application> app;
    if (!paintedCanvas(app, 1)) return;
    app->state().files.statePath = (folder / "painting.sand").string();
    app->state().commands.push(Command::SaveState);
    app->serveCommands();
    CHECK(app->state().files.unsavedEdits == 0);
    app->state().commands.push(Command::AddObstacle);
    app->serveCommands();
    CHECK(app->state().files.unsavedEdits > 0);
    app->state().commands.push(Command::LoadState);
    app->serveCommands();
    CHECK(app->state().files.unsavedEdits == 0);
}
