// SPDX-License-Identifier: MIT
#pragma once
// R12: surface normals for lighting. The thesis's column method (§3.8) compares column heights;
// the occupancy gradient also works on vessel walls and under overhangs, where columns are wrong.

#include "sandcore/cell_grid.hpp"
#include "sandcore/scene.hpp"
#include "sandcore/vec3.hpp"

#include <span>
#include <vector>

namespace sandcore {

/// Which estimate of R12 to use.
enum class NormalMethod : std::uint8_t {
    ColumnHeights,      ///< thesis §3.8: one normal per column from its 8 neighbours' heights
    OccupancyGradient,  ///< normalised negative gradient of sand occupancy over the 3x3x3 neighbourhood
};

/// Height of every column (x, z) of a grid: 1 + the y of its topmost grain, 0 for none;
/// indexed x + sizeX * z.
std::vector<int> columnHeights(const CellGrid& grid);

/// The thesis's normal of column (x, z): each of the 8 neighbour columns gives the table's face
/// normal for higher / equal / lower; their unit-length average.
Vec3 columnNormal(const std::vector<int>& heights, Int3 gridSize, int x, int z);

/// Unit normal at a cell from the occupancy of its 26 neighbours (INVALID and outside count as
/// empty); (0, 1, 0) where the neighbourhood is balanced.
Vec3 gradientNormal(const CellGrid& grid, std::uint32_t cell);

/// The sums (gx, gy, gz) of the offsets of the grains among a cell's 26 neighbours (each in
/// -9..9; INVALID and outside count as empty): what gradientNormal reads.
Int3 occupancyGradientSums(const CellGrid& grid, std::uint32_t cell);

/// How many of a cell's 26 neighbours hold a grain (INVALID and outside count as empty): the
/// occupancy ambient occlusion darkens by.
int occupiedNeighbours(const CellGrid& grid, std::uint32_t cell);

/// Ambient occlusion in kOcclusionLevels steps: (occupied neighbours + 2) / 4, so 0..7. Eight
/// steps fit the 3 bits a gradient key leaves free in 16 (SurfaceUpkeep::kSurfaceKeys).
inline constexpr int kOcclusionLevels = 8;
constexpr int occlusionLevel(int occupiedNeighbours) { return (occupiedNeighbours + 2) / 4; }

/// The normal gradientNormal gives for the sums (gx, gy, gz) of the offsets of the grains
/// around a cell (each in -9..9): the unit vector of (-gx, -gy, -gz), or (0, 1, 0) for none.
Vec3 occupancyGradientNormal(int gx, int gy, int gz);

/// A normal for every grain of a scene, written to out (out.size() >= grainCount()).
void estimateGrainNormals(const Scene& scene, NormalMethod method, std::span<Vec3> out);

} // namespace sandcore
