// SPDX-License-Identifier: MIT
#pragma once
// Each subcommand adds itself to the parser and, when chosen, runs from a callback that
// stores its exit code in `exitCode`.

#include <CLI/CLI.hpp>

#include <string>

namespace sandglass {

void addSimulateCommand(CLI::App& app, int& exitCode);   ///< SPEC C1: headless simulation
void addVoxelizeCommand(CLI::App& app, int& exitCode);   ///< SPEC C2: model voxelization report
void addGuiCommand(CLI::App& app, int& exitCode);        ///< SPEC §6: the window on a scene
void addRenderCommand(CLI::App& app, int& exitCode);     ///< SPEC C3: one frame offscreen to PNG
void addBenchCommand(CLI::App& app, int& exitCode);      ///< SPEC C4/B2 report; B1 frame rates with --render

/// `sandglass [FILE]` without a subcommand: the window on the default hourglass (or on FILE: a
/// .sand state, a model, a draft image), draining; `noSettings` starts from the defaults.
int runDefaultWindow(const std::string& file = {}, bool noSettings = false);

} // namespace sandglass
