// SPDX-License-Identifier: MIT
// SPEC E1-E4: the desktop's file dialog as a child process, with a stand-in program that answers
// as zenity does (the path on standard output, exit status 0; 1 when cancelled).
#include "view/file_chooser.hpp"

#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <csignal>
#include <thread>

using namespace sandglass;

namespace {

bool has(const std::vector<std::string>& command, const std::string& argument) {
    return std::find(command.begin(), command.end(), argument) != command.end();
}

// A script that records its arguments and then answers with `answer`.
std::filesystem::path fakeChooser(const TemporaryFolder& folder, const std::string& answer) {
    const std::filesystem::path script = folder / "chooser.sh";
    std::ofstream(script) << "#!/bin/sh\nprintf '%s\\n' \"$@\" > '" << (folder / "arguments.txt").string() << "'\n"
                          << answer << "\n";
    std::filesystem::permissions(script, std::filesystem::perms::owner_all);
    return script;
}

// Polls like the window loop does, for at most ten seconds.
std::optional<ChosenFile> waitFor(FileChooser& chooser) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < until) {
        if (std::optional<ChosenFile> chosen = chooser.poll()) return chosen;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return std::nullopt;
}

std::string contentOf(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

TEST_CASE("file dialog: zenity and kdialog are asked for the right kind of dialog") {
    const auto open = fileChooserCommand("/usr/bin/zenity", FileChoice::OpenState, "work/a.sand");
    CHECK(open.front() == "/usr/bin/zenity");
    CHECK(has(open, "--file-selection"));
    CHECK(has(open, "--filename=work/a.sand"));
    CHECK(has(open, "--file-filter=sandglass state | *.sand"));
    CHECK_FALSE(has(open, "--save"));
    const auto save = fileChooserCommand("zenity", FileChoice::Export, "sand.ply");
    CHECK(has(save, "--save"));
    CHECK(has(save, "--confirm-overwrite"));
    CHECK(has(fileChooserCommand("zenity", FileChoice::ScreenshotFolder, "/home/me/"), "--directory"));
    const auto kde = fileChooserCommand("/usr/bin/kdialog", FileChoice::SaveState, "a.sand");
    CHECK(has(kde, "--getsavefilename"));
    CHECK(has(kde, "*.sand|sandglass state"));
    CHECK(has(fileChooserCommand("kdialog", FileChoice::ScreenshotFolder, "/tmp"), "--getexistingdirectory"));
}

TEST_CASE("file dialog: the chosen path comes back once, without blocking, and only one dialog is open") {
    TemporaryFolder folder;
    ::setenv("SANDGLASS_FILE_CHOOSER", fakeChooser(folder, "sleep 0.2; echo '/data/my sand.sand'").c_str(), 1);
    FileChooser chooser;
    REQUIRE(chooser.open(FileChoice::OpenState, "start.sand") == "");
    CHECK(chooser.isOpen());
    CHECK(chooser.poll() == std::nullopt); // still open: the window keeps drawing
    CHECK(chooser.open(FileChoice::Model, "") == "a file dialog is already open");
    const std::optional<ChosenFile> chosen = waitFor(chooser);
    REQUIRE(chosen);
    CHECK(chosen->choice == FileChoice::OpenState);
    CHECK(chosen->path == "/data/my sand.sand");
    CHECK_FALSE(chooser.isOpen());
    CHECK(chooser.poll() == std::nullopt);
    CHECK(contentOf(folder / "arguments.txt").find("--filename=start.sand\n") != std::string::npos);
}

TEST_CASE("file dialog: Cancel gives an empty path, and a missing program is one line") {
    TemporaryFolder folder;
    ::setenv("SANDGLASS_FILE_CHOOSER", fakeChooser(folder, "exit 1").c_str(), 1);
    FileChooser chooser;
    REQUIRE(chooser.open(FileChoice::Draft, "") == "");
    const std::optional<ChosenFile> cancelled = waitFor(chooser);
    REQUIRE(cancelled);
    CHECK(cancelled->path.empty());
    ::setenv("SANDGLASS_FILE_CHOOSER", (folder / "no-such-program").c_str(), 1);
    const std::string problem = chooser.open(FileChoice::Draft, "");
    CHECK(problem.find("no-such-program") != std::string::npos);
    CHECK(problem.find('\n') == std::string::npos);
    CHECK_FALSE(chooser.isOpen());
}

TEST_CASE("file dialog: closing the window closes the dialog and whatever it started") {
    TemporaryFolder folder;
    // A wrapper script that starts the real dialog (here a long sleep) and waits for it.
    const std::filesystem::path pidFile = folder / "dialog.pid";
    ::setenv("SANDGLASS_FILE_CHOOSER",
             fakeChooser(folder, "sleep 30 & echo $! > '" + pidFile.string() + "'; wait").c_str(), 1);
    pid_t dialog = 0;
    {
        FileChooser chooser;
        REQUIRE(chooser.open(FileChoice::Model, "") == "");
        for (int wait = 0; wait < 500 && contentOf(pidFile).empty(); ++wait)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        dialog = pid_t(std::atoi(contentOf(pidFile).c_str()));
        REQUIRE(dialog > 0);
        CHECK(::kill(dialog, 0) == 0);
    } // the window closes
    bool gone = false;
    for (int wait = 0; wait < 300 && !gone; ++wait) {
        gone = ::kill(dialog, 0) != 0;
        if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    CHECK(gone);
}
