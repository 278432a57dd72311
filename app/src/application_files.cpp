// SPDX-License-Identifier: MIT
// The application's files: opening whatever is dropped or chosen (a state, a draft image, a
// model), saving and opening states, the file dialog's answers, and screenshots.
#include "app/application.hpp"

#include "app/user_settings.hpp"

#include "scene/data_paths.hpp"
#include "scene/draft_image.hpp"
#include "scene/file_io.hpp"
#include "scene/state_file.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace sandglass {

namespace {

bool isStateFile(const std::filesystem::path& path) { return path.extension() == ".sand"; }

// Where the file dialog starts for a choice: the path the panel holds for it.
std::string startPathFor(const AppState& state, FileChoice choice) {
    switch (choice) {
    case FileChoice::OpenState:
    case FileChoice::SaveState: return state.files.statePath;
    case FileChoice::Export: return state.files.exportPath;
    case FileChoice::Model: return state.scene.request.modelPath;
    case FileChoice::Draft: return state.painting.draftPath;
    case FileChoice::DiggerBody: return state.digger.modelPath;
    case FileChoice::ScreenshotFolder: return state.files.screenshotFolder + "/";
    }
    return {};
}

} // namespace

bool Application::openFile(const std::string& path) {
    // A .sand file opens straight away: the state path changes only when it opens, so a file
    // that fails to open is never the one the next Save writes over.
    if (isStateFile(path)) return loadStateFile(path);
    if (isDraftImageFile(path)) {
        if (host_.kind() == sandcore::SceneKind::Canvas) return loadDraft(path);
        // An image is painted over on the canvas: build one, then show the draft on it.
        state_.scene.request.kind = sandcore::SceneKind::Canvas;
        state_.scene.request.modelPath.clear();
        state_.scene.request.shape.clear();
        state_.scene.request.resolution = defaultResolution(sandcore::SceneKind::Canvas);
        draftAfterBuild_ = path;
        state_.commands.push(Command::Rebuild);
        return true;
    }
    // Every other file is a model, built as an hourglass unless a sculpture runs.
    state_.scene.request.modelPath = path;
    state_.scene.request.shape.clear();
    if (state_.scene.request.kind == sandcore::SceneKind::Canvas) state_.scene.request.kind = sandcore::SceneKind::Hourglass;
    state_.commands.push(Command::Rebuild);
    return true;
}

bool Application::loadStateFile(const std::string& path) {
    try {
        LoadedState loaded = loadState(path);
        // The running scene stays untouched unless the whole file loaded.
        host_.adoptLoaded(std::move(loaded.scene), loaded.settings);
        state_.files.statePath = path;
        state_.loaded = host_.loaded();
        state_.scene = state_.loaded;
        canvas_.sceneReplaced();
        timer_.stop();
        turnStarted_.reset();
        camera_.setTurn(0.0f);
        frameCamera();
        state_.files.unsavedEdits = 0;
        state_.statusLine = "opened " + path;
        addRecentFile(state_.files.recentFiles, path);
        return true;
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        return false;
    }
}

bool Application::saveStateFile() {
    try {
        saveState(state_.files.statePath, host_.scene(), state_.loaded.request);
        state_.files.unsavedEdits = 0;
        state_.statusLine = "saved to " + state_.files.statePath;
        addRecentFile(state_.files.recentFiles, state_.files.statePath);
        return true;
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        return false;
    }
}

bool Application::loadDraft(const std::string& path) {
    try {
        renderer_.setDraftImage(canvas_.loadDraft(path));
        state_.painting.loadedDraft = path;
        state_.painting.draftPath = path;
        state_.painting.showDraft = true;
        state_.statusLine = "draft " + path;
        if (std::filesystem::path(path).parent_path() != modelsFolder()) addRecentFile(state_.files.recentFiles, path);
        return true;
    } catch (const std::exception& error) {
        state_.statusLine = error.what(); // the previous draft, if any, stays in use
        return false;
    }
}

void Application::chooseFile() {
    const std::string problem = fileChooser_.open(state_.files.choosing, startPathFor(state_, state_.files.choosing));
    if (!problem.empty()) state_.statusLine = problem;
}

void Application::serveChosenFile(const ChosenFile& chosen) {
    if (chosen.path.empty()) return; // cancelled: nothing changes
    switch (chosen.choice) {
    case FileChoice::OpenState:
        loadStateFile(chosen.path);
        break;
    case FileChoice::SaveState:
        state_.files.statePath = chosen.path;
        saveStateFile();
        break;
    case FileChoice::Export:
        state_.files.exportPath = chosen.path;
        serve(Command::Export);
        break;
    case FileChoice::Model:
        state_.scene.request.modelPath = chosen.path;
        state_.scene.request.shape.clear();
        if (state_.scene.request.kind == sandcore::SceneKind::Canvas) state_.scene.request.kind = sandcore::SceneKind::Hourglass;
        serve(Command::Rebuild);
        break;
    case FileChoice::Draft: loadDraft(chosen.path); break;
    case FileChoice::DiggerBody: loadDiggerBody(chosen.path); break;
    case FileChoice::ScreenshotFolder:
        state_.files.screenshotFolder = chosen.path;
        state_.statusLine = "screenshots go to " + chosen.path;
        break;
    }
}

bool Application::saveScreenshot(const std::filesystem::path& file) {
    try {
        writePng(file, captureFrame());
        std::error_code error;
        const std::filesystem::path shown = std::filesystem::absolute(file, error);
        state_.statusLine = "saved " + (error ? file : shown).string();
        std::printf("screenshot %s\n", file.string().c_str());
        std::fflush(stdout);
        return true;
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        std::fprintf(stderr, "sandglass: %s\n", error.what());
        return false;
    }
}

void Application::saveNumberedScreenshot(const RgbImage& image) {
    // E4: the first free sandglass-N.png in the chosen folder; an earlier file is never replaced.
    try {
        // Numbers count from 1 again in a folder newly chosen.
        if (state_.files.screenshotFolder != screenshotFolderUsed_) screenshotsTaken_ = 0;
        screenshotFolderUsed_ = state_.files.screenshotFolder;
        const std::filesystem::path file = writeNewNumberedFile(state_.files.screenshotFolder, "sandglass", ".png",
                                                                encodePng(image), screenshotsTaken_ + 1);
        const std::string number = file.stem().string().substr(std::string("sandglass-").size());
        screenshotsTaken_ = std::stoi(number);
        std::error_code error;
        const std::filesystem::path shown = std::filesystem::absolute(file, error);
        state_.files.lastScreenshot = (error ? file : shown).string();
        state_.statusLine = "screenshot saved to " + state_.files.lastScreenshot;
        std::printf("screenshot %s\n", state_.files.lastScreenshot.c_str());
        std::fflush(stdout);
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        std::fprintf(stderr, "sandglass: %s\n", error.what());
    }
}

} // namespace sandglass
