// SPEC E1, E2, E3 in the window: the File section's Save, Open and Export commands, and a file
// that cannot be opened leaving the running scene as it was.
#include "support/app_test_support.hpp"
#include "support/temporary_folder.hpp"

#include "app/application.hpp"

#include <doctest/doctest.h>

#include <fstream>
#include <optional>

using namespace sandglass;

TEST_CASE("file commands: save, run on, open gives back the saved scene, and a damaged file changes nothing") {
    ApplicationOptions options;
    options.window = {96, 96, false, false, "sandglass file test"};
    options.offscreen = true;
    options.initial.showGui = false;
    options.initial.scene.request.kind = sandcore::SceneKind::Hourglass;
    options.initial.scene.request.modelPath.clear();
    options.initial.scene.request.shape = "hourglass";
    options.initial.scene.request.resolution = 24;
    std::optional<Application> app = testing::openApplication(std::move(options), "file commands");
    if (!app) return;
    TemporaryFolder folder;
    app->runSteps(40);
    const std::uint64_t saved = app->scene().stateHash();
    app->state().files.statePath = (folder / "glass.sand").string();
    app->state().files.exportPath = (folder / "glass.ply").string();
    app->state().commands.push(Command::SaveState);
    app->state().commands.push(Command::Export);
    app->serveCommands();
    CHECK(std::filesystem::exists(folder / "glass.sand"));
    CHECK(std::filesystem::exists(folder / "glass.ply"));
    app->runSteps(40);
    REQUIRE(app->scene().stateHash() != saved);
    app->state().commands.push(Command::LoadState);
    app->serveCommands();
    CHECK(app->scene().stateHash() == saved);
    CHECK(app->state().loaded.request.shape == "hourglass");
    CHECK(app->state().statusLine == "opened " + (folder / "glass.sand").string());

    std::ofstream(folder / "broken.sand") << "not a state";
    const std::uint64_t running = app->scene().stateHash();
    app->state().files.statePath = (folder / "broken.sand").string();
    app->state().commands.push(Command::LoadState);
    app->serveCommands();
    CHECK(app->scene().stateHash() == running);
    CHECK(app->state().statusLine.rfind((folder / "broken.sand").string() + ": ", 0) == 0);
}
