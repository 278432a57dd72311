// SPDX-License-Identifier: MIT
// SPEC E1, E2, E3 in the window: the File section's Save, Open and Export commands, and a file
// that cannot be opened leaving the running scene as it was.
#include "support/app_test_support.hpp"
#include "support/temporary_folder.hpp"

#include "app/application.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>
#include <optional>

using namespace sandglass;

TEST_CASE("file commands: save, run on, open gives back the saved scene, and a damaged file changes nothing") {
    ApplicationOptions options = testing::proceduralHourglassOptions(96, 96, 24, "sandglass file test");
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

TEST_CASE("file commands: a window started on a state file builds nothing else first") {
    TemporaryFolder folder;
    ApplicationOptions first = testing::proceduralHourglassOptions(96, 96, 20, "sandglass start-state test");
    std::uint64_t saved = 0;
    {
        std::optional<Application> app = testing::openApplication(first, "starting on a state file");
        if (!app) return;
        app->runSteps(25);
        saved = app->scene().stateHash();
        app->state().files.statePath = (folder / "start.sand").string();
        app->state().commands.push(Command::SaveState);
        app->serveCommands();
    }
    // Settings that cannot be built: they would fail if anything but the state were built.
    ApplicationOptions options = first;
    options.initial.scene.request.modelPath = (folder / "no-such-model.obj").string();
    options.stateFile = folder / "start.sand";
    std::optional<Application> app = testing::openApplication(options, "starting on a state file");
    if (!app) return;
    CHECK(app->scene().stateHash() == saved);
    CHECK(app->state().files.statePath == (folder / "start.sand").string());
    CHECK(app->state().loaded.request.shape == "hourglass");
    CHECK(app->state().files.unsavedEdits == 0);
}

TEST_CASE("file commands: a .sand file chosen in the file dialog opens, and Cancel changes nothing") {
    TemporaryFolder folder;
    ApplicationOptions options = testing::proceduralHourglassOptions(96, 96, 20, "sandglass file dialog test");
    std::optional<Application> app = testing::openApplication(std::move(options), "the file dialog");
    if (!app) return;
    app->runSteps(15);
    const std::uint64_t saved = app->scene().stateHash();
    app->state().files.statePath = (folder / "chosen.sand").string();
    app->state().commands.push(Command::SaveState);
    app->serveCommands();
    app->runSteps(15);
    REQUIRE(app->scene().stateHash() != saved);
    // A stand-in for zenity that answers with the saved file.
    const std::filesystem::path chooser = folder / "chooser.sh";
    std::ofstream(chooser) << "#!/bin/sh\necho '" << (folder / "chosen.sand").string() << "'\n";
    std::filesystem::permissions(chooser, std::filesystem::perms::owner_all);
    ::setenv("SANDGLASS_FILE_CHOOSER", chooser.c_str(), 1);
    app->state().files.statePath = "elsewhere.sand";
    app->state().files.choosing = FileChoice::OpenState;
    app->state().commands.push(Command::ChooseFile);
    app->serveCommands();
    for (int frame = 0; frame < 1000 && app->scene().stateHash() != saved; ++frame) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        app->serveCommands();
    }
    CHECK(app->scene().stateHash() == saved);
    CHECK(app->state().files.statePath == (folder / "chosen.sand").string());
    // Cancel: the dialog ends without a path and nothing changes.
    std::ofstream(chooser) << "#!/bin/sh\nexit 1\n";
    app->runSteps(5);
    const std::uint64_t running = app->scene().stateHash();
    app->state().commands.push(Command::ChooseFile);
    app->serveCommands();
    for (int frame = 0; frame < 100; ++frame) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        app->serveCommands();
    }
    CHECK(app->scene().stateHash() == running);
    CHECK(app->state().files.statePath == (folder / "chosen.sand").string());
}

TEST_CASE("file commands: a state file that fails to open never becomes the file Save writes to") {
    TemporaryFolder folder;
    std::optional<Application> app = testing::openApplication(
        testing::proceduralHourglassOptions(96, 96, 20, "sandglass failed open test"), "a failed open");
    if (!app) return;
    app->state().files.statePath = (folder / "mine.sand").string();
    std::ofstream(folder / "dropped.sand") << "SANDGLASS but damaged";
    // What a dropped file does: open it at once.
    CHECK_FALSE(app->loadStateFile((folder / "dropped.sand").string()));
    CHECK(app->state().files.statePath == (folder / "mine.sand").string());
    CHECK(app->state().statusLine.rfind((folder / "dropped.sand").string() + ": ", 0) == 0);
}
