// SPDX-License-Identifier: MIT
#include "sandcore/cavity.hpp"

#include "wall_cavities.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace sandcore {

namespace {

using Vec = std::array<double, 3>;

Vec minus(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Akenine-Moeller's separating-axis test: does the triangle (already relative to the box's
// centre) touch the box of half size h? Touching counts, so a wall on a cell face marks both cells.
bool triangleTouchesBox(const Vec& a, const Vec& b, const Vec& c, double h) {
    const Vec edges[3] = {minus(b, a), minus(c, b), minus(a, c)};
    const Vec axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    auto separated = [&](const Vec& axis) {
        const double pa = dot(a, axis), pb = dot(b, axis), pc = dot(c, axis);
        const double r = h * (std::abs(axis[0]) + std::abs(axis[1]) + std::abs(axis[2]));
        return std::min({pa, pb, pc}) > r || std::max({pa, pb, pc}) < -r;
    };
    for (const Vec& e : edges)
        for (const Vec& u : axes)
            if (separated(cross(u, e))) return false;
    for (const Vec& u : axes)
        if (separated(u)) return false;
    return !separated(cross(edges[0], edges[1]));
}

} // namespace

CavitySearch findCavities(const InsideMask& solid) {
    const Int3 s = solid.size;
    // One byte per cell (wall 1, outside 2, a cavity 3): a label per cavity would cost four.
    constexpr std::uint8_t kUnvisited = 0, kOutside = 2, kCavity = 3;
    MaskCells state = solid.inside;
    std::vector<std::uint32_t> queue;
    // Marks every cell holding `from` that is 6-connected to seed with `mark`; returns how many.
    auto fill = [&](std::size_t seed, std::uint8_t mark, std::uint8_t from, MaskCells& cells) {
        return fillRuns(cells, s, seed, from, mark, queue);
    };
    CavitySearch result;
    // The fills from the border cells (only those: the order of the seeds changes nothing).
    auto fromBorder = [&](int x, int y, int z) {
        const std::size_t n = solid.indexOf(x, y, z);
        if (state[n] == kUnvisited) result.outsideCells += fill(n, kOutside, kUnvisited, state);
    };
    for (int y = 0; y < s.y; ++y)
        for (int z = 0; z < s.z; ++z) {
            if (y == 0 || y == s.y - 1 || z == 0 || z == s.z - 1) {
                for (int x = 0; x < s.x; ++x) fromBorder(x, y, z);
            } else {
                fromBorder(0, y, z);
                fromBorder(s.x - 1, y, z);
            }
        }
    std::size_t largestSeed = state.size();
    for (std::size_t n = 0; n < state.size(); ++n) {
        if (state[n] != kUnvisited) continue;
        const std::int64_t cells = fill(n, kCavity, kUnvisited, state);
        ++result.cavities;
        result.cavityCells += cells;
        if (cells > result.largestCells) {
            result.largestCells = cells;
            largestSeed = n;
        }
    }
    result.largest = InsideMask::empty(s);
    // The largest cavity once more, from its seed, into the result (walls and outside stay 0).
    if (largestSeed < state.size()) {
        for (std::size_t n = 0; n < state.size(); ++n) result.largest.inside[n] = state[n] == kCavity ? 0 : 1;
        fill(largestSeed, 2, 0, result.largest.inside);
        for (std::uint8_t& cell : result.largest.inside) cell = cell == 2 ? 1 : 0;
    }
    return result;
}

TriangleMesh toGridSpace(const TriangleMesh& mesh, const VoxelPlacement& p) {
    TriangleMesh grid = mesh;
    for (Vec3& v : grid.vertices) {
        const double model[3] = {double(v.x), double(v.y), double(v.z)};
        double cell[3];
        for (std::size_t a = 0; a < 3; ++a) cell[a] = (model[a] - p.modelMin[a]) * p.scale[a] + p.padding[a];
        v = {decltype(v.x)(cell[0]), decltype(v.y)(cell[1]), decltype(v.z)(cell[2])};
    }
    return grid;
}

void forEachTouchedCell(const TriangleMesh& gridMesh, Int3 size,
                        const std::function<void(std::size_t triangle, std::uint32_t cell)>& visit) {
    const int limits[3] = {size.x, size.y, size.z};
    for (std::size_t n = 0; n < gridMesh.triangles.size(); ++n) {
        const auto& t = gridMesh.triangles[n];
        Vec corner[3];
        for (int i = 0; i < 3; ++i) {
            const Vec3 v = gridMesh.vertices[t[std::size_t(i)]];
            corner[i] = {double(v.x), double(v.y), double(v.z)};
        }
        int lo[3], hi[3];
        for (std::size_t a = 0; a < 3; ++a) {
            const double mn = std::min({corner[0][a], corner[1][a], corner[2][a]});
            const double mx = std::max({corner[0][a], corner[1][a], corner[2][a]});
            lo[a] = std::max(0, int(std::floor(mn)) - (std::floor(mn) == mn ? 1 : 0));
            hi[a] = std::min(limits[a] - 1, int(std::floor(mx)));
        }
        for (int y = lo[1]; y <= hi[1]; ++y)
            for (int z = lo[2]; z <= hi[2]; ++z)
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    const Vec centre{x + 0.5, y + 0.5, z + 0.5};
                    if (triangleTouchesBox(minus(corner[0], centre), minus(corner[1], centre), minus(corner[2], centre), 0.5))
                        visit(n, std::uint32_t(std::size_t(x) + std::size_t(size.x) * (std::size_t(z) + std::size_t(size.z) * std::size_t(y))));
                }
    }
}

void appendSurfaceCells(const TriangleMesh& gridMesh, Int3 size, std::vector<std::uint32_t>& cells) {
    const std::size_t first = cells.size();
    forEachTouchedCell(gridMesh, size, [&](std::size_t, std::uint32_t cell) { cells.push_back(cell); });
    std::sort(cells.begin() + std::ptrdiff_t(first), cells.end());
    cells.erase(std::unique(cells.begin() + std::ptrdiff_t(first), cells.end()), cells.end());
}

InsideMask surfaceCells(const TriangleMesh& gridMesh, Int3 size) {
    InsideMask mask = InsideMask::empty(size);
    std::vector<std::uint32_t> cells;
    appendSurfaceCells(gridMesh, size, cells);
    for (std::uint32_t n : cells) mask.inside[n] = 1;
    return mask;
}

} // namespace sandcore
