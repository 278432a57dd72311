// SPDX-License-Identifier: MIT
#pragma once
// SPEC S2 at a model's walls: which wall cells beside a sand space belong to it. Private to sandcore.

#include "sandcore/triangle_mesh.hpp"
#include "space_grid.hpp"
#include "wall_cavities.hpp"

#include <vector>

namespace sandcore {

// S2 for a space the walls enclose: a cell is the space's when its centre is. The walls' cells
// next to the space whose centre no wall separates from a neighbour in the space join it (the
// cells the surface touches on its inner side), so a single-wall glass loses no layer of sand.
// The column cut through a neck (`joint`) is no reference: it lies outside the glass by design;
// nor are the cells the space grew back into a closed gap (`band`): they may lie beyond a rim.
void addCentresOnTheSpaceSide(CellList& space, const CellList& joint, const MaskCells& band, const MaskCells& walls,
                              const std::vector<TriangleMesh>& wallMeshes, const Grid& grid);

} // namespace sandcore
