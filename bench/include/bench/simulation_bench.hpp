// SPDX-License-Identifier: MIT
#pragma once
// Speed of the step against grid resolution for the hourglass drain (SPEC B2 "Simulation").

#include "bench/report_files.hpp"

#include "sandcore/scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace sandbench {

/// One drain of the procedural hourglass until settled.
struct DrainRun {
    int resolution = 0;          ///< cells along the hourglass height
    std::int64_t grains = 0;     ///< grains in the scene
    std::int64_t cells = 0;      ///< cells of both grids
    std::int64_t steps = 0;      ///< steps until settled
    bool sleeping = true;        ///< R5 on (true) or full sweep
    int threads = 1;             ///< threads sharing each step
    double medianMs = 0.0;       ///< median milliseconds per step
    double stepsPerSecond = 0.0; ///< steps / seconds of the whole drain
    bool conserved = false;      ///< grain count equal to the start, by a full count of both grids
    std::uint64_t hash = 0;      ///< state hash once settled
};

/// Drains the procedural hourglass at each resolution with sleeping on and off, on 1 thread and
/// on step.threads, all with step.seed.
std::vector<DrainRun> measureDrains(const std::vector<int>& resolutions, const sandcore::StepSettings& step);

/// The runs as a table, with the hash check against the first run of the same resolution.
Table drainTable(const std::vector<DrainRun>& runs);

/// True when every run of each resolution ended in the same state and conserved its grains.
bool drainsAgree(const std::vector<DrainRun>& runs);

} // namespace sandbench
