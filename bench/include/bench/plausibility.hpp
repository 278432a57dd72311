// SPDX-License-Identifier: MIT
#pragma once
// Physical plausibility of the sand as error figures (SPEC B2): how steady the hourglass
// discharges (real sand: constant rate, Beverloo's law) and how steep the settled pile stands
// (dry sand: 30-35 degrees).

#include "sandcore/scene.hpp"

#include <cstdint>
#include <vector>

namespace sandbench {

/// Grains that passed from the upper into the lower grid in each step of a drain.
struct DischargeSeries {
    std::vector<std::int64_t> grainsPerStep; ///< one entry per step, from the first step on
    std::int64_t grainsAtStart = 0;          ///< grains in the upper grid before the first step
};

/// Steps the scene until it settles (or maxSteps) and records the discharge of every step.
DischargeSeries recordDischarge(sandcore::Scene& scene, std::int64_t maxSteps);

/// Discharge rates averaged over windows of `window` steps, over the steps in which the drained
/// share of the upper grid's sand lies in [fromShare, toShare].
std::vector<double> windowedDischargeRates(const DischargeSeries& series, int window, double fromShare,
                                           double toShare);

/// The discharge over the middle of a drain: the steps from the first at whose end a share
/// fromShare of the upper grid's sand has passed to the first at whose end toShare has, cut into
/// `parts` runs of steps as equal as whole steps allow, each run's grains per step.
struct MiddleDischarge {
    double rate = 0;                ///< grains per step over all those steps
    std::vector<double> partRates;  ///< grains per step of each part
    std::int64_t steps = 0;         ///< steps in the middle
};
MiddleDischarge middleDischarge(const DischargeSeries& series, int parts, double fromShare, double toShare);

/// Coefficient of variation (standard deviation / mean) of a series; 0 for fewer than 2 values.
double coefficientOfVariation(const std::vector<double>& values);

/// Slopes of a settled pile, in degrees.
struct ReposeAngles {
    double alongAxes = 0.0;      ///< mean over the +x, -x, +z, -z flanks
    double alongDiagonals = 0.0; ///< mean over the four diagonal flanks
    int flanksMeasured = 0;      ///< flanks with enough points for a fit (of 8)
};

/// Fits a line to the column heights along the 8 directions out of the pile's highest column
/// (the centre of the highest plateau), over the flank between the plateau's edge and the
/// floor or the first INVALID column, and returns the mean angles. Horizontal distance is
/// measured in cells (a diagonal step is sqrt(2)).
ReposeAngles measureReposeAngles(const sandcore::CellGrid& grid);

} // namespace sandbench
