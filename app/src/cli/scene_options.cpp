// SPDX-License-Identifier: MIT
#include "app/cli/scene_options.hpp"

#include "app/cli/checked_options.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>

namespace sandglass {

void addSceneOptions(CLI::App& command, SceneOptions& options) {
    SceneRequest& request = options.settings.request;
    sandcore::StepSettings& step = options.settings.step;
    command.add_option("--scene", options.scene, "hourglass, sculpture, canvas or sandbox (a canvas with a bed of sand to dig in)")->capture_default_str();
    command.add_option("--model", request.modelPath, "model file (OBJ, STL, PLY, glTF, ...) as vessel or sculpture");
    command.add_option("--shape", request.shape, "procedural shape instead of a model: hourglass, sphere or cube");
    addNumberOption(command, "--res", request.resolution, kResolutionRange.min, kResolutionRange.max,
                    "cells along the shape's largest extent (default 64; the canvas: its width, default 60)");
    addNumberOption(command, "--neck", request.neckRadius, float(kNeckRadiusRange.min), float(kNeckRadiusRange.max),
                    "neck radius of the procedural hourglass in cells (0 = automatic, res/24)");
    addNumberOption(command, "--fill", request.fillFraction, float(kFillRange.min), float(kFillRange.max),
                    "share of the upper bulb filled with sand at the start (default 0.85)");
    command.add_flag("--stretch", request.stretch, "model: scale every axis to --res cells (aspect not kept)");
    command.add_flag("--robust", request.robust, "model: majority-vote inside test for open meshes");
    addNumberOption(command, "--noise", request.noiseThreshold, kNoiseRange.min, kNoiseRange.max,
                    "model: remove cells with at most this many inside face neighbours (-1 = off, default 1)");
    command.add_option("--part", options.parts,
                       "model: set a part's role, NAME=ROLE with ROLE vessel, frame, sand or static (repeatable)");
    command.add_option("--up", request.upAxis,
                       "model: the axis that points up, +x -x +y -y +z -z (default: found for the hourglass, +y for the sculpture)");
    addNumberOption(command, "--seed", step.seed, std::uint64_t{0}, std::numeric_limits<std::uint64_t>::max(),
                    "seed of the slip randomness (default 1)");
    addNumberOption(command, "--threads", step.threads, kThreadsRange.min, kThreadsRange.max,
                    "worker threads of a step (default 1; the result does not depend on it)");
    command.add_option("--physics", options.physics,
                       "granular (repose angle, gravity, Beverloo discharge; the default) or classic (the thesis's rules)")
        ->capture_default_str();
    addNumberOption(command, "--repose", step.physics.reposeDegrees, float(kReposeRange.min), float(kReposeRange.max),
                    "granular: angle of repose of a poured cone in degrees (default 33)");
    addNumberOption(command, "--gravity", step.physics.gravity, float(kGravityRange.min), float(kGravityRange.max),
                    "granular: gravity in cells per step squared (default 0.02; 1 mm cells at 60 steps/s: 2.7)");
}

SceneSettings sceneSettingsFrom(const SceneOptions& options) {
    SceneSettings settings = options.settings;
    applySceneName(settings.request, options.scene);
    for (const std::string& part : options.parts) settings.request.partRoles.push_back(parsePartRoleChoice(part));
    const auto physics = sandcore::parsePhysicsLevel(options.physics);
    if (!physics) throw std::invalid_argument("--physics must be classic or granular, got '" + options.physics + "'");
    settings.step.physics.level = *physics;
    applySceneDefaults(settings);
    return settings;
}

} // namespace sandglass
