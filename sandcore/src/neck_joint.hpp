// SPDX-License-Identifier: MIT
#pragma once
// SPEC W2: two bulbs that a neck narrower than a cell keeps apart, joined through one column of
// the neck's own wall cells. Private to sandcore.

#include "space_grid.hpp"
#include "wall_cavities.hpp"

#include <array>
#include <optional>
#include <vector>

namespace sandcore {

// Where a space lies along each column across an axis: its lowest and highest layer there.
struct ColumnSpans {
    std::array<std::vector<int>, 3> low, high; // per axis, per column of the plane across it
    std::array<double, 3> centreU{}, centreV{};  // the space's centre in each plane
};

/// The plane across an axis: its two axes.
std::array<int, 2> planeOf(int axis);

/// Where the cells lie along each column across each axis.
ColumnSpans columnSpansOf(const CellList& cells, const Grid& grid);

/// A column cut through a wall between two bulbs.
struct NeckJoint {
    CellList cells;    ///< the wall cells cut through, ascending
    int axis = -1;     ///< the column's axis
    int low = 0;       ///< its first layer along the axis
    int high = 0;      ///< its last layer
};

/// The column that joins two spaces (their spans as columnSpansOf() gives them) through a wall a
/// few cells thick along an axis (a neck narrower than a cell, sealed by its own surface cells),
/// where they come closest, nearest their common centre; none when no wall that thin parts them.
std::optional<NeckJoint> jointAcrossNeck(const ColumnSpans& spansA, const ColumnSpans& spansB, const MaskCells& walls,
                                         const Grid& grid);

} // namespace sandcore
