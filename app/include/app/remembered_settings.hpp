// SPDX-License-Identifier: MIT
#pragma once
// SPEC I4: a window starts as the last one was left, and what changed is kept at its end.

#include "app/application.hpp"
#include "app/user_settings.hpp"

namespace sandglass {

/// Puts the remembered window size, position, text size, screenshot folder and recent files
/// into the options of a window about to open; `panelLayout` is ImGui's imgui.ini (empty: none).
/// What the command line chose (scene, mode, palette, size) is applied before, by the caller.
void startAsRemembered(const UserSettings& settings, const std::filesystem::path& panelLayout, ApplicationOptions& options);

/// What to remember of a window about to close: `before` with its size and position, text size,
/// render mode, palette, lighting, scene and model, screenshot folder and recent files.
UserSettings settingsToRemember(const Application& application, const UserSettings& before);

} // namespace sandglass
