// SPDX-License-Identifier: MIT
#pragma once
// Exact procedural masks: the shapes tests and benchmarks need, independent of any model file.

#include "sandcore/inside_mask.hpp"

namespace sandcore {

/// A ball touching all six faces of a resolution^3 box (cell centres within radius resolution/2).
InsideMask makeSphereMask(int resolution);

/// A solid cube filling a resolution^3 box except a one-cell margin on each side.
InsideMask makeCubeMask(int resolution);

/// Shape of the procedural hourglass of revolution.
struct HourglassShape {
    int height = 64;             ///< cells along y (the largest extent)
    float neckRadius = 2.0f;     ///< radius of the neck opening, in cells (>= 0.5)
    float bulbRadius = 0.0f;     ///< widest radius of each bulb, in cells; 0 = 0.27 * height
};

/// The neck radius the procedural hourglass gets when none is asked for: height / 24, at least
/// 1.5 cells (wide enough that sand never jams at low resolutions).
float defaultNeckRadius(int height);

/// The size of the mask makeHourglassMask would make, without making it.
Int3 hourglassMaskSize(const HourglassShape& shape);

/// An hourglass of revolution about the vertical axis: two bulbs joined at a neck in the
/// middle layer. Throws std::invalid_argument for a height below 8 or a neck wider than the bulbs.
InsideMask makeHourglassMask(const HourglassShape& shape);

} // namespace sandcore
