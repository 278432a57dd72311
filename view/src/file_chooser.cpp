// SPDX-License-Identifier: MIT
#include "view/file_chooser.hpp"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace sandglass {

namespace {

const char* titleOf(FileChoice choice) {
    switch (choice) {
    case FileChoice::OpenState: return "Open a saved sand state";
    case FileChoice::SaveState: return "Save the sand state as";
    case FileChoice::Export: return "Export the sand as";
    case FileChoice::Model: return "Open a model";
    case FileChoice::Draft: return "Open a draft image";
    case FileChoice::ScreenshotFolder: return "Folder for screenshots";
    }
    return "Choose a file";
}

// Name and glob patterns of the files a choice accepts; empty for a folder.
std::pair<std::string, std::string> filterOf(FileChoice choice) {
    switch (choice) {
    case FileChoice::OpenState:
    case FileChoice::SaveState: return {"sandglass state", "*.sand"};
    case FileChoice::Export: return {"point cloud, voxels or mesh", "*.ply *.vox *.obj *.stl *.glb"};
    case FileChoice::Model: return {"3D model", "*.obj *.stl *.ply *.gltf *.glb *.off *.fbx *.dae *.3ds"};
    case FileChoice::Draft: return {"image", "*.png *.jpg *.jpeg"};
    case FileChoice::ScreenshotFolder: return {};
    }
    return {};
}

bool saves(FileChoice choice) { return choice == FileChoice::SaveState || choice == FileChoice::Export; }

// The program's full path when PATH (or the name itself, if it holds a '/') finds an executable.
std::string findProgram(const std::string& name) {
    if (name.empty()) return {};
    if (name.find('/') != std::string::npos) return ::access(name.c_str(), X_OK) == 0 ? name : std::string();
    const char* path = std::getenv("PATH");
    std::string folders = path ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= folders.size()) {
        std::size_t end = folders.find(':', start);
        if (end == std::string::npos) end = folders.size();
        const std::string candidate = folders.substr(start, end - start) + "/" + name;
        if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return {};
}

} // namespace

std::vector<std::string> fileChooserCommand(const std::string& program, FileChoice choice, const std::string& startPath) {
    const auto [filterName, patterns] = filterOf(choice);
    const bool kde = std::filesystem::path(program).filename() == "kdialog";
    std::vector<std::string> command{program};
    const std::string start = startPath.empty() ? std::string(".") : startPath; // kdialog needs one
    if (kde) {
        command.push_back("--title");
        command.push_back(titleOf(choice));
        if (choice == FileChoice::ScreenshotFolder) {
            command.push_back("--getexistingdirectory");
            command.push_back(start);
        } else {
            command.push_back(saves(choice) ? "--getsavefilename" : "--getopenfilename");
            command.push_back(start);
            command.push_back(patterns + "|" + filterName);
        }
        return command;
    }
    command.push_back("--file-selection");
    command.push_back(std::string("--title=") + titleOf(choice));
    if (!startPath.empty()) command.push_back("--filename=" + startPath);
    if (choice == FileChoice::ScreenshotFolder) command.push_back("--directory");
    if (saves(choice)) {
        command.push_back("--save");
        command.push_back("--confirm-overwrite");
    }
    if (!patterns.empty()) {
        command.push_back("--file-filter=" + filterName + " | " + patterns);
        command.push_back("--file-filter=all files | *");
    }
    return command;
}

FileChooser::~FileChooser() {
    if (child_ > 0) {
        // The dialog's whole process group (a wrapper script and the dialog it starts) goes,
        // and a program that ignores SIGTERM is killed after half a second.
        ::kill(-child_, SIGTERM);
        int status = 0;
        for (int tries = 0; tries < 50 && ::waitpid(child_, &status, WNOHANG) == 0; ++tries) ::usleep(10'000);
        if (::waitpid(child_, &status, WNOHANG) == 0) ::kill(-child_, SIGKILL);
    }
    close();
}

void FileChooser::close() {
    if (output_ >= 0) ::close(output_);
    output_ = -1;
    if (child_ > 0) {
        int status = 0;
        while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {
        }
    }
    child_ = -1;
}

std::string FileChooser::open(FileChoice choice, const std::string& startPath) {
    if (child_ > 0) return "a file dialog is already open";
    std::string program;
    if (const char* chosen = std::getenv("SANDGLASS_FILE_CHOOSER"); chosen && *chosen) {
        program = findProgram(chosen);
        if (program.empty()) return std::string("no file dialog: SANDGLASS_FILE_CHOOSER names ") + chosen + ", which cannot be run";
    } else {
        program = findProgram("zenity");
        if (program.empty()) program = findProgram("kdialog");
        if (program.empty()) return "no file dialog found (install zenity); type the path instead";
    }
    const std::vector<std::string> command = fileChooserCommand(program, choice, startPath);
    std::vector<char*> arguments;
    for (const std::string& argument : command) arguments.push_back(const_cast<char*>(argument.c_str()));
    arguments.push_back(nullptr);

    int pipeEnds[2];
    if (::pipe2(pipeEnds, O_CLOEXEC) != 0) return "cannot open a file dialog (no pipe)";
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], 1);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0); // toolkit warnings
    posix_spawn_file_actions_addclosefrom_np(&actions, 3); // the display's socket, GPU files: not the dialog's
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0); // its own group, so closing the window closes all of it
    pid_t child = -1;
    const int failed = ::posix_spawn(&child, program.c_str(), &actions, &attributes, arguments.data(), environ);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    ::close(pipeEnds[1]);
    if (failed != 0) {
        ::close(pipeEnds[0]);
        return "cannot start " + program + " for the file dialog";
    }
    ::fcntl(pipeEnds[0], F_SETFL, ::fcntl(pipeEnds[0], F_GETFL) | O_NONBLOCK);
    child_ = child;
    output_ = pipeEnds[0];
    choice_ = choice;
    received_.clear();
    return {};
}

std::optional<ChosenFile> FileChooser::poll() {
    if (child_ <= 0) return std::nullopt;
    char buffer[4096];
    for (;;) {
        const ssize_t got = ::read(output_, buffer, sizeof buffer);
        if (got > 0) {
            received_.append(buffer, std::size_t(got));
            continue;
        }
        if (got < 0 && errno == EINTR) continue;
        break; // EAGAIN: nothing more yet; 0: the child closed its output
    }
    int status = 0;
    const pid_t done = ::waitpid(child_, &status, WNOHANG);
    if (done == 0) return std::nullopt; // still open
    child_ = -1;
    // Whatever it wrote before it ended.
    for (ssize_t got; (got = ::read(output_, buffer, sizeof buffer)) > 0;) received_.append(buffer, std::size_t(got));
    close();
    ChosenFile chosen{choice_, {}};
    // Exit status 0 and a first line: the path; anything else (Cancel, Esc, closed): nothing chosen.
    if (done > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        chosen.path = received_.substr(0, received_.find('\n'));
        if (!chosen.path.empty() && chosen.path.back() == '\r') chosen.path.pop_back(); // a name may end in a space
    }
    return chosen;
}

} // namespace sandglass
