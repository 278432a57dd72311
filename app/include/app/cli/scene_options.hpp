// SPDX-License-Identifier: MIT
#pragma once
// The scene options every command that builds a scene shares (simulate, gui, render, bench):
// one registration, one set of ranges (scene_request.hpp), one check (applySceneDefaults).

#include "scene/scene_request.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace sandglass {

/// A scene as typed on the command line.
struct SceneOptions {
    std::string scene = "hourglass"; ///< hourglass, sculpture or canvas
    std::string physics = "granular"; ///< granular (default) or classic (SPEC PH1)
    SceneSettings settings;          ///< request and step settings, filled by the options
    std::vector<std::string> parts;  ///< --part NAME=ROLE, as typed (parsed by sceneSettingsFrom)
};

/// Adds --scene --model --shape --res --neck --fill --stretch --robust --noise --part --up --seed
/// --threads --physics --repose --gravity.
void addSceneOptions(CLI::App& command, SceneOptions& options);

/// The settings the options stand for, defaults applied and every value checked; throws
/// std::invalid_argument with one line naming the option.
SceneSettings sceneSettingsFrom(const SceneOptions& options);

} // namespace sandglass
