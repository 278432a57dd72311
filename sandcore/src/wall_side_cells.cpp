// SPDX-License-Identifier: MIT
#include "wall_side_cells.hpp"

#include <algorithm>
#include <array>
#include <iterator>

namespace sandcore {

namespace {

// Does the segment from p to p + step (one cell along an axis) cross the triangle? Touching counts:
// a centre on the surface is not on the space's side.
bool segmentCrosses(const std::array<double, 3>& p, int axis, int step, const TriangleMesh& mesh,
                    const std::array<std::uint32_t, 3>& t) {
    std::array<std::array<double, 3>, 3> v;
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec3 c = mesh.vertices[t[i]];
        v[i] = {double(c.x) - p[0], double(c.y) - p[1], double(c.z) - p[2]};
    }
    // The triangle's plane must separate or touch 0 and the step's end; then the crossing point,
    // projected along the axis, must lie in the triangle (signed areas of one sign, zero allowed).
    const std::array<double, 3> e1{v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
    const std::array<double, 3> e2{v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
    const std::array<double, 3> normal{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double atStart = -(normal[0] * v[0][0] + normal[1] * v[0][1] + normal[2] * v[0][2]);
    const double atEnd = atStart + normal[std::size_t(axis)] * step;
    if ((atStart > 0 && atEnd > 0) || (atStart < 0 && atEnd < 0)) return false;
    if (normal[std::size_t(axis)] == 0.0) return atStart == 0.0; // in the plane: count it
    const double t01 = atStart / (atStart - atEnd);
    std::array<double, 3> hit{0, 0, 0};
    hit[std::size_t(axis)] = t01 * step;
    const int u = axis == 0 ? 1 : 0, w = axis == 2 ? 1 : 2;
    auto area = [&](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return (a[std::size_t(u)] - hit[std::size_t(u)]) * (b[std::size_t(w)] - hit[std::size_t(w)]) -
               (a[std::size_t(w)] - hit[std::size_t(w)]) * (b[std::size_t(u)] - hit[std::size_t(u)]);
    };
    const double a0 = area(v[0], v[1]), a1 = area(v[1], v[2]), a2 = area(v[2], v[0]);
    return (a0 >= 0 && a1 >= 0 && a2 >= 0) || (a0 <= 0 && a1 <= 0 && a2 <= 0);
}

} // namespace

// S2 for a space the walls enclose: a cell is the space's when its centre is. The walls' cells
// next to the space whose centre no wall separates from a neighbour in the space join it (the
// cells the surface touches on its inner side), so a single-wall glass loses no layer of sand.
// The column cut through a neck (`joint`) is no reference: it lies outside the glass by design;
// nor are the cells the space grew back into a closed gap (`band`): they may lie beyond a rim.
void addCentresOnTheSpaceSide(CellList& space, const CellList& joint, const MaskCells& band, const MaskCells& walls,
                              const std::vector<TriangleMesh>& wallMeshes, const Grid& grid) {
    MaskCells inSpace(grid.cells(), 0);
    // References are free cells of the space only: no triangle touches them.
    for (std::uint32_t n : space) inSpace[n] = !walls[n] && (band.empty() || !band[n]) ? 1 : 0;
    for (std::uint32_t n : joint) inSpace[n] = 0;
    // For each wall cell beside the space: the directions (bits 0..5: -x +x -y +y -z +z) to the
    // space, and those a triangle crosses.
    std::vector<std::uint8_t> towards(grid.cells(), 0), crossed(grid.cells(), 0);
    const std::array<std::array<int, 3>, 6> steps{{{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}}};
    for (std::size_t n = 0; n < grid.cells(); ++n) {
        if (!walls[n] || inSpace[n]) continue; // a wall cell added by an earlier pass is space already
        const std::array<int, 3> c = grid.coordinates(std::uint32_t(n));
        for (std::size_t d = 0; d < 6; ++d) {
            std::array<int, 3> m = c;
            bool inGrid = true;
            for (std::size_t a = 0; a < 3; ++a) {
                m[a] += steps[d][a];
                inGrid = inGrid && m[a] >= 0 && m[a] < grid.length(int(a));
            }
            if (inGrid && inSpace[grid.index(m)]) towards[n] |= std::uint8_t(1u << d);
        }
    }
    // A triangle that crosses the step from a cell to its neighbour in the space touches the cell:
    // the neighbour is free, no triangle touches it.
    for (const TriangleMesh& mesh : wallMeshes)
        forEachTouchedCell(mesh, grid.size, [&](std::size_t triangle, std::uint32_t cell) {
            if (!towards[cell]) return;
            const std::array<int, 3> c = grid.coordinates(cell);
            const std::array<double, 3> centre{c[0] + 0.5, c[1] + 0.5, c[2] + 0.5};
            for (std::size_t d = 0; d < 6; ++d) {
                if (!(towards[cell] & (1u << d)) || (crossed[cell] & (1u << d))) continue;
                const int axis = int(d / 2), step = d % 2 ? 1 : -1;
                if (segmentCrosses(centre, axis, step, mesh, mesh.triangles[triangle])) crossed[cell] |= std::uint8_t(1u << d);
            }
        });
    CellList added;
    for (std::size_t n = 0; n < grid.cells(); ++n)
        if ((towards[n] & ~crossed[n]) && !std::binary_search(joint.begin(), joint.end(), std::uint32_t(n)))
            added.push_back(std::uint32_t(n));
    CellList merged;
    merged.reserve(space.size() + added.size());
    std::merge(space.begin(), space.end(), added.begin(), added.end(), std::back_inserter(merged));
    space = std::move(merged);
}

} // namespace sandcore
