// SPDX-License-Identifier: MIT
#pragma once
// SPEC S8: the sand space of an hourglass is the inside of its glass. A glass modelled with
// thickness voxelizes to a wall; the cells the walls (and the frame) enclose, not connected to
// the grid's border, are cavities, and the largest one is where the sand goes.

#include "sandcore/inside_mask.hpp"
#include "sandcore/triangle_mesh.hpp"
#include "sandcore/voxelizer.hpp"

#include <cstdint>
#include <vector>

namespace sandcore {

/// The cavities of a solid: empty cells that no 6-connected path of empty cells joins to the grid's border.
struct CavitySearch {
    InsideMask largest;             ///< the largest cavity's cells (all outside when there is none)
    int cavities = 0;               ///< number of separate cavities (6-connected components)
    std::int64_t largestCells = 0;  ///< cells of the largest cavity
    std::int64_t cavityCells = 0;   ///< cells of all cavities together
    std::int64_t outsideCells = 0;  ///< empty cells connected to the border
};

/// Finds the cavities of `solid` (inside = wall) by a flood fill of the empty cells from the
/// grid's border through face neighbours; ties between equal cavities go to the first in index order.
CavitySearch findCavities(const InsideMask& solid);

/// The mesh moved into grid coordinates of `placement` (cell (i, j, k) spans [i, i + 1) ...),
/// as voxelize() places it.
TriangleMesh toGridSpace(const TriangleMesh& mesh, const VoxelPlacement& placement);

/// Every cell of a `size` grid that a triangle of the grid-space mesh touches (closed cell
/// boxes, separating-axis test), so a wall thinner than a cell still seals what it encloses.
InsideMask surfaceCells(const TriangleMesh& gridMesh, Int3 size);

/// The cells surfaceCells() marks, appended to `cells` as ascending indices (InsideMask's layout),
/// found on up to `threads` threads.
void appendSurfaceCells(const TriangleMesh& gridMesh, Int3 size, std::vector<std::uint32_t>& cells, int threads = 1);

} // namespace sandcore
