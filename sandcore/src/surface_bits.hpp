// SPDX-License-Identifier: MIT
#pragma once
// What SurfaceUpkeep keeps per grid to look at a grain's neighbourhood cheaply: the grid's shape
// with division-free coordinates and, per cell, whether it holds a grain and whether it hides a
// neighbour. Private: the public header shows the bits as CellBitWords.

#include "sandcore/surface_upkeep.hpp"

#include "cell_bits.hpp"

#include <array>

namespace sandcore {

struct SurfaceUpkeep::Bits {
    std::array<GridShape, 2> shapes; // both grids' sizes, with cheap coordinates
    // Per grid, one bit per cell as of the last update: holds a grain; is not EMPTY (a grain or
    // INVALID: hides a neighbour). A step's net changes are where the grid no longer agrees.
    std::array<CellBits, 2> grain, hide;
};

} // namespace sandcore
