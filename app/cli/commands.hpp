#pragma once
// Each subcommand adds itself to the parser and, when chosen, runs from a callback that
// stores its exit code in `exitCode`.

#include <CLI/CLI.hpp>

namespace sandglass {

void addSimulateCommand(CLI::App& app, int& exitCode);   ///< SPEC C1: headless simulation
void addBenchCommand(CLI::App& app, int& exitCode);      ///< SPEC C4: the speed-against-error report
void addVoxelizeCommand(CLI::App& app, int& exitCode);   ///< SPEC C2: model voxelization report

} // namespace sandglass
