// SPDX-License-Identifier: MIT
#include "view/file_chooser.hpp"

#include "process/child_process.hpp"

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <unistd.h>

namespace sandglass {

namespace {

const char* titleOf(FileChoice choice) {
    switch (choice) {
    case FileChoice::OpenState: return "Open a saved sand state";
    case FileChoice::SaveState: return "Save the sand state as";
    case FileChoice::Export: return "Export the sand as";
    case FileChoice::Model: return "Open a model";
    case FileChoice::Draft: return "Open a draft image";
    case FileChoice::DiggerBody: return "Open a model for the digger";
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
    case FileChoice::Model:
    case FileChoice::DiggerBody: return {"3D model", "*.obj *.stl *.ply *.gltf *.glb *.off *.fbx *.dae *.3ds"};
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

FileChooser::FileChooser() = default;

FileChooser::~FileChooser() {
    if (child_) {
        // The dialog's whole process group (a wrapper script and the dialog it starts) goes,
        // and a program that ignores SIGTERM is killed after half a second (by the child's end).
        child_->sendSignal(SIGTERM);
        for (int tries = 0; tries < 50 && !child_->exited(); ++tries) ::usleep(10'000);
    }
}

std::string FileChooser::open(FileChoice choice, const std::string& startPath) {
    if (child_) return "a file dialog is already open";
    std::string program;
    if (const char* chosen = std::getenv("SANDGLASS_FILE_CHOOSER"); chosen && *chosen) {
        program = findProgram(chosen);
        if (program.empty()) return std::string("no file dialog: SANDGLASS_FILE_CHOOSER names ") + chosen + ", which cannot be run";
    } else {
        program = findProgram("zenity");
        if (program.empty()) program = findProgram("kdialog");
        if (program.empty()) return "no file dialog found (install zenity); type the path instead";
    }
    ChildCommand command;
    command.arguments = fileChooserCommand(program, choice, startPath);
    command.output = ChildStream::Pipe;  // the path chosen
    command.errors = ChildStream::Null;  // toolkit warnings
    command.ownProcessGroup = true;      // so closing the window closes all of it
    auto child = std::make_unique<ChildProcess>(command);
    if (!child->started()) return "cannot start " + program + " for the file dialog";
    child_ = std::move(child);
    choice_ = choice;
    received_.clear();
    return {};
}

std::optional<ChosenFile> FileChooser::poll() {
    if (!child_) return std::nullopt;
    child_->readAvailableOutput(received_);
    const std::optional<ChildExit> exit = child_->exited();
    if (!exit) return std::nullopt; // still open
    child_->readAvailableOutput(received_); // whatever it wrote before it ended
    child_.reset();
    ChosenFile chosen{choice_, {}};
    // Exit status 0 and a first line: the path; anything else (Cancel, Esc, closed): nothing chosen.
    if (exit->succeeded()) {
        chosen.path = received_.substr(0, received_.find('\n'));
        if (!chosen.path.empty() && chosen.path.back() == '\r') chosen.path.pop_back(); // a name may end in a space
    }
    return chosen;
}

} // namespace sandglass
