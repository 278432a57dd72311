// SPDX-License-Identifier: MIT
#pragma once
// SPEC W2: the spaces a model's walls enclose, with gaps of a few cells closed. Private to sandcore.

#include "sandcore/inside_mask.hpp"

#include <cstdint>
#include <vector>

namespace sandcore {

/// Cells as indices into a grid (InsideMask's layout), ascending.
using CellList = std::vector<std::uint32_t>;

/// `cells` (1 = set) grown by `radius` cells in every direction: a cube of side 2 * radius + 1.
MaskCells grownBy(const MaskCells& cells, Int3 size, int radius);

/// The regions that `walls` (1 = wall) enclose once every gap of up to 2 * closing cells is
/// closed: the walls are grown by `closing` cells (a cube), the grown walls' cavities found, and
/// each cavity grown back, face step by face step, into the free cells it had lost, a cell going
/// to whichever side reaches it first (the outside on a tie, so the grown walls' gaps are shared
/// with the outside and never leave a cavity). Cavities that meet while growing back are one
/// region: a neck the grown walls closed opens again. Regions come in order of their first cell.
std::vector<CellList> enclosedRegions(const MaskCells& walls, Int3 size, int closing);

/// The 6-connected components of `cells` (ascending indices into a `size` grid), each ascending,
/// in order of their first cell.
std::vector<CellList> componentsOf(const CellList& cells, Int3 size);

/// Free cells that a wall bounds on all four sides across `axis` (0 = x, 1 = y, 2 = z): the
/// inside of a vessel open along that axis, such as a funnel.
CellList laterallyEnclosed(const MaskCells& walls, Int3 size, int axis);

/// How many cells of `cells` have a 6-neighbour in `mask`.
std::int64_t cellsTouching(const CellList& cells, const MaskCells& mask, Int3 size);

} // namespace sandcore
