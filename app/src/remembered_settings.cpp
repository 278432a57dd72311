// SPDX-License-Identifier: MIT
#include "app/remembered_settings.hpp"

#include "scene/file_io.hpp"

#include <GLFW/glfw3.h>

#include <cmath>
#include <system_error>

namespace sandglass {

void startAsRemembered(const UserSettings& settings, const std::filesystem::path& panelLayout, ApplicationOptions& options) {
    options.initial.uiScale = settings.uiScale;
    options.initial.files.recentFiles = settings.recentFiles;
    if (settings.windowPlaced) options.windowPosition = std::array<int, 2>{settings.windowX, settings.windowY};
    std::error_code error;
    // A folder that is gone (an unplugged disk) falls back to the pictures folder.
    if (options.screenshotFolder.empty() && !settings.screenshotFolder.empty() &&
        std::filesystem::is_directory(settings.screenshotFolder, error))
        options.screenshotFolder = settings.screenshotFolder;
    options.panelLayoutFile = panelLayout;
}

UserSettings settingsToRemember(const Application& application, const UserSettings& before) {
    UserSettings after = before;
    const ApplicationOptions& options = application.options();
    if (options.window.visible && !options.offscreen) {
        // GLFW grows the window with the monitor's content scale; the file keeps it at scale 1.
        GLFWwindow* window = application.window().handle();
        const float scale = std::max(application.window().contentScale(), 0.25f);
        int width = 0, height = 0, x = 0, y = 0;
        glfwGetWindowSize(window, &width, &height);
        glfwGetWindowPos(window, &x, &y);
        if (width > 0 && height > 0) {
            after.windowWidth = int(std::lround(float(width) / scale));
            after.windowHeight = int(std::lround(float(height) / scale));
        }
        after.windowPlaced = true;
        after.windowX = x;
        after.windowY = y;
    }
    const AppState& state = application.state();
    after.uiScale = state.uiScale;
    after.mode = state.render.mode;
    after.palette = state.render.palette;
    after.lighting = state.render.lighting;
    after.scene = state.loaded.request.kind;
    after.model = state.loaded.request.kind == sandcore::SceneKind::Canvas ? std::string() : state.loaded.request.modelPath;
    // The pictures folder is the default: only a folder the user chose is remembered.
    after.screenshotFolder =
        state.files.screenshotFolder == defaultPicturesFolder().string() ? std::string() : state.files.screenshotFolder;
    after.recentFiles = state.files.recentFiles;
    return after;
}

} // namespace sandglass
