// SPDX-License-Identifier: MIT
#pragma once
// SPEC W2: the spaces a model's walls enclose, with gaps of a few cells closed. Private to sandcore.

#include "sandcore/inside_mask.hpp"
#include "sandcore/triangle_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sandcore {

/// Cells as indices into a grid (InsideMask's layout), ascending.
using CellList = std::vector<std::uint32_t>;

/// Marks with `mark` every cell 6-connected to `seed` through cells holding `from` (the seed holds
/// it), in a grid of `size` (InsideMask's layout); returns how many. A scanline fill: each popped
/// cell grows to its whole run along x, and the run queues one cell per run it touches in the
/// four rows beside it, so the queue holds a few entries per run, not six per cell.
template <class Cells, class Label>
std::int64_t fillRuns(Cells& cells, Int3 size, std::size_t seed, Label from, Label mark, std::vector<std::uint32_t>& queue) {
    const std::size_t width = std::size_t(size.x), layer = width * std::size_t(size.z);
    std::int64_t count = 0;
    queue.assign(1, std::uint32_t(seed));
    while (!queue.empty()) {
        const std::size_t n = queue.back();
        queue.pop_back();
        if (cells[n] != from) continue; // filled since it was queued
        const std::size_t rowStart = n - n % width;
        std::size_t low = n, high = n; // the run is [low, high]
        while (low > rowStart && cells[low - 1] == from) --low;
        while (high + 1 < rowStart + width && cells[high + 1] == from) ++high;
        std::fill(cells.begin() + std::ptrdiff_t(low), cells.begin() + std::ptrdiff_t(high + 1), mark);
        count += std::int64_t(high - low + 1);
        const std::size_t row = rowStart / width; // z + size.z * y
        const std::size_t z = row % std::size_t(size.z), y = row / std::size_t(size.z);
        auto queueRuns = [&](bool inGrid, std::size_t offsetLow) {
            if (!inGrid) return;
            for (std::size_t m = offsetLow; m <= offsetLow + (high - low); ++m)
                if (cells[m] == from && (m == offsetLow || cells[m - 1] != from)) queue.push_back(std::uint32_t(m));
        };
        queueRuns(z > 0, low - width);
        queueRuns(z + 1 < std::size_t(size.z), low + width);
        queueRuns(y > 0, low - layer);
        queueRuns(y + 1 < std::size_t(size.y), low + layer);
    }
    return count;
}

/// Does the triangle (corners relative to a cell's centre, cell units) touch the closed cell box?
/// Akenine-Moeller's separating-axis test; touching counts, so a wall on a cell face marks both cells.
bool triangleTouchesCell(const std::array<std::array<double, 3>, 3>& corners);

/// Calls visit(triangle index, cell index) for every cell each triangle of the grid-space mesh
/// touches (closed cell boxes), as surfaceCells() decides it; only triangles [first, last) when given.
template <class Visit>
void forEachTouchedCell(const TriangleMesh& gridMesh, Int3 size, Visit&& visit, std::size_t first = 0,
                        std::size_t last = SIZE_MAX) {
    const int limits[3] = {size.x, size.y, size.z};
    for (std::size_t n = first; n < std::min(last, gridMesh.triangles.size()); ++n) {
        std::array<std::array<double, 3>, 3> corner;
        for (std::size_t i = 0; i < 3; ++i) {
            const Vec3 v = gridMesh.vertices[gridMesh.triangles[n][i]];
            corner[i] = {double(v.x), double(v.y), double(v.z)};
        }
        int lo[3], hi[3], spanned = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            const double mn = std::min({corner[0][a], corner[1][a], corner[2][a]});
            const double mx = std::max({corner[0][a], corner[1][a], corner[2][a]});
            lo[a] = std::max(0, int(std::floor(mn)) - (std::floor(mn) == mn ? 1 : 0));
            hi[a] = std::min(limits[a] - 1, int(std::floor(mx)));
            spanned += hi[a] > lo[a] ? 1 : 0;
        }
        // Within one layer of cells on two axes, the triangle touches every cell its bounds cover:
        // it is connected, so it meets every slab of the third axis between its lowest and highest
        // corner, and there it lies inside the one cell of the other two.
        const bool everyCell = spanned <= 1;
        for (int y = lo[1]; y <= hi[1]; ++y)
            for (int z = lo[2]; z <= hi[2]; ++z)
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    if (!everyCell) {
                        const double centre[3] = {x + 0.5, y + 0.5, z + 0.5};
                        std::array<std::array<double, 3>, 3> relative;
                        for (std::size_t i = 0; i < 3; ++i)
                            for (std::size_t a = 0; a < 3; ++a) relative[i][a] = corner[i][a] - centre[a];
                        if (!triangleTouchesCell(relative)) continue;
                    }
                    visit(n, std::uint32_t(std::size_t(x) + std::size_t(size.x) * (std::size_t(z) + std::size_t(size.z) * std::size_t(y))));
                }
    }
}

/// `cells` (1 = set) grown by `radius` cells in every direction: a cube of side 2 * radius + 1.
MaskCells grownBy(const MaskCells& cells, Int3 size, int radius);

/// The regions that `walls` (1 = wall) enclose once every gap of up to 2 * closing cells is
/// closed: the walls are grown by `closing` cells (a cube), the grown walls' cavities found, and
/// each cavity grown back, face step by face step, into the free cells it had lost, a cell going
/// to whichever side reaches it first (the outside on a tie, so the grown walls' gaps are shared
/// with the outside and never leave a cavity). Cavities that meet while growing back are one
/// region: a neck the grown walls closed opens again. Regions come in order of their first cell.
/// `grownWalls` is grownBy(walls, size, closing), `walls` itself for closing 0.
std::vector<CellList> enclosedRegions(const MaskCells& walls, const MaskCells& grownWalls, Int3 size, int closing);

/// The 6-connected components of `cells` (ascending indices into a `size` grid), each ascending,
/// in order of their first cell.
std::vector<CellList> componentsOf(const CellList& cells, Int3 size);

/// Free cells that a wall bounds on all four sides across `axis` (0 = x, 1 = y, 2 = z): the
/// inside of a vessel open along that axis, such as a funnel.
CellList laterallyEnclosed(const MaskCells& walls, Int3 size, int axis);

/// How many cells of `cells` have a 6-neighbour in `mask`.
std::int64_t cellsTouching(const CellList& cells, const MaskCells& mask, Int3 size);

} // namespace sandcore
