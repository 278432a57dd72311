// SPDX-License-Identifier: MIT
#pragma once
// SPEC I4: what the window remembers between runs, in one JSON file under the desktop's config
// folder ($XDG_CONFIG_HOME/sandglass/settings.json, else ~/.config/sandglass/settings.json), with
// ImGui's own panel layout (imgui.ini) beside it. A missing file means the defaults; a damaged
// one is reported in one line and the defaults are used: it never stops the program.

#include "view/render/render_settings.hpp"

#include "sandcore/scene_geometry.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sandglass {

/// Recent files kept, newest first.
inline constexpr std::size_t kMaxRecentFiles = 10;

/// The remembered settings, each defaulting to what a first start shows.
struct UserSettings {
    int windowWidth = 1280;             ///< client size in screen coordinates at content scale 1
    int windowHeight = 800;             ///< as above
    bool windowPlaced = false;          ///< windowX and windowY were saved (the window manager places a first window)
    int windowX = 0, windowY = 0;       ///< the window's top-left corner on the desktop, screen coordinates
    float uiScale = 1.0f;               ///< text size on top of the monitor's content scale (View tab)
    RenderMode mode = RenderMode::PseudoBillboards; ///< render mode
    SandPalette palette = SandPalette::Desert;      ///< sand colours
    bool lighting = true;               ///< lighting from estimated normals
    sandcore::SceneKind scene = sandcore::SceneKind::Hourglass; ///< the last scene
    std::string model;                  ///< the last model file; empty = the scene's bundled default
    std::string screenshotFolder;       ///< where P saves; empty = the pictures folder
    std::vector<std::string> recentFiles; ///< files opened or saved, newest first, at most kMaxRecentFiles
};

/// $XDG_CONFIG_HOME/sandglass when XDG_CONFIG_HOME is an absolute path, else $HOME/.config/sandglass;
/// empty when neither is known (nothing is then remembered).
std::filesystem::path settingsFolder();

/// The settings in `file`: the defaults when it does not exist. A file that cannot be read, is
/// not JSON or holds a value of the wrong kind gives the defaults (for that value, or all of
/// them when the file is not readable JSON) and `problem` one line naming the file and the cause.
UserSettings readUserSettings(const std::filesystem::path& file, std::string& problem);

/// The settings as the JSON object the file holds.
std::string userSettingsJson(const UserSettings& settings);

/// Writes the settings to `file` (through a temporary file renamed into place), making its
/// folder; throws FileError with one line when it cannot.
void writeUserSettings(const std::filesystem::path& file, const UserSettings& settings);

/// Puts `path` (made absolute) at the front of `recent`, dropping an earlier mention of it and
/// keeping at most kMaxRecentFiles.
void addRecentFile(std::vector<std::string>& recent, const std::string& path);

} // namespace sandglass
