// SPDX-License-Identifier: MIT
#pragma once
// SPEC PH2-PH6 in the speed-against-error report: the granular level's repose angle asked
// against measured in 16 directions, fall time against sqrt(2h/g), the discharge over several
// necks with its fitted Beverloo exponent, and its cost against classic.

#include "bench/plausibility.hpp"
#include "bench/speed_error_report.hpp"

#include "sandcore/physics_settings.hpp"

#include <array>
#include <cstdint>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

namespace sandbench {

/// One section of the report.
struct GranularSection {
    std::string markdown; ///< the section's text, tables and plot links
    bool passed = true;   ///< conservation held and every plot was drawn
};

/// One drain's cost in a cost comparison.
struct DrainCost {
    sandcore::PhysicsLevel level = sandcore::PhysicsLevel::Classic; ///< the rules that drained
    std::int64_t grains = 0;       ///< grains in the scene (kept throughout when conserved)
    bool conserved = false;        ///< the scene still holds every grain at the end
    std::uint64_t steps = 0;       ///< steps until nothing moved
    double msPerStep = 0;          ///< mean over the drain, time in Scene::step only
    double movesPerStep = 0;       ///< mean over the drain
    std::uint64_t hash = 0;        ///< Scene::stateHash at the end
    double neckModelRate = 0;      ///< grains a step the neck-flow model asks (granular), else 0
    DischargeSeries discharge;     ///< grains into the lower grid, step by step
};

/// Granular steps in one turn of drainsInTurns.
inline constexpr int kGranularStepsPerTurn = 100;

/// PH6: the procedural hourglass of this height drained until nothing moves once per level,
/// `step`'s other settings for all, in one process and in turns: after each
/// kGranularStepsPerTurn steps of every granular drain, each classic drain steps until it has
/// passed as large a share of its sand as the first granular one (without a granular drain,
/// the classic ones run to the end in turns of as many steps). A busy machine then slows all
/// alike, which one drain after the other does not (the ratio of two levels moved from 2.8x to
/// 6.5x within hours on a shared machine). Costs in the order of `levels`.
std::vector<DrainCost> drainsInTurns(int height, const sandcore::StepSettings& step,
                                     std::span<const sandcore::PhysicsLevel> levels);

/// drainsInTurns of the classic rules ([0]) and the granular ones ([1]).
std::array<DrainCost, 2> drainCostInTurns(int height, const sandcore::StepSettings& step);

/// Measures the granular level and writes repose.csv, fall_time.csv, necks.csv, cost.csv and
/// their plots into options.outDir; progress goes to log.
GranularSection granularSection(const ReportOptions& options, std::ostream& log);

} // namespace sandbench
