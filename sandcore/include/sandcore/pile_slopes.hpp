// SPDX-License-Identifier: MIT
#pragma once
// Measuring a heap (SPEC PH2): the angle of its flanks along evenly spaced directions out of its
// peak, from the grid's column heights, as one would measure a real pile from a height map.

#include "sandcore/cell_grid.hpp"

#include <vector>

namespace sandcore {

/// What the measurement fits.
struct PileSlopeSettings {
    int directions = 16;      ///< evenly spaced directions out of the peak (the first along +x)
    double fromShare = 0.15;  ///< fit only heights at or above this share of the peak's (skips the toe)
    double toShare = 0.85;    ///< ... and at or below this share (skips the rounded top)
    /// Rays fitted per direction, spread evenly over its sector (360 / directions degrees wide);
    /// the direction's angle is their mean. 1: the one ray along the direction.
    int raysPerDirection = 1;
};

/// Angles of a heap's flanks.
struct PileSlopes {
    double peakX = 0, peakZ = 0;  ///< centre of the highest columns, cells (column centres at +0.5)
    int peakHeight = 0;           ///< filled cells in the highest column
    std::vector<double> degrees;  ///< per direction: least-squares angle of height over distance, degrees (0 if too few points)
    double meanDegrees() const;   ///< mean over the directions
    double minDegrees() const;    ///< smallest of the directions
    double maxDegrees() const;    ///< largest of the directions
};

/// Least-squares slope of y over x (0 when x does not vary); x and y of equal length.
double leastSquaresSlope(const std::vector<double>& x, const std::vector<double>& y);

/// The flanks of the heap in `grid`: column heights are sampled every half cell along each ray
/// out of the peak (bilinear between column centres) and a line is fitted over the heights
/// between fromShare and toShare of the peak's. A single ray reads the grain-sized roughness of
/// the flank along its line; rays spread over each direction's sector average it out.
PileSlopes measurePileSlopes(const CellGrid& grid, const PileSlopeSettings& settings = {});

} // namespace sandcore
