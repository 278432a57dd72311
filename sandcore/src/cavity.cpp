// SPDX-License-Identifier: MIT
#include "sandcore/cavity.hpp"

#include "wall_cavities.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <iterator>
#include <vector>

namespace sandcore {

namespace {

using Vec = std::array<double, 3>;

// Fewer triangles than this per thread are not worth a thread of their own.
constexpr std::size_t kTrianglesPerThread = 100'000;

Vec minus(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

} // namespace

bool triangleTouchesCell(const std::array<Vec, 3>& corners) {
    const Vec& a = corners[0];
    const Vec& b = corners[1];
    const Vec& c = corners[2];
    constexpr double h = 0.5;
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

void appendSurfaceCells(const TriangleMesh& gridMesh, Int3 size, std::vector<std::uint32_t>& cells, int threads) {
    // Each thread lists the cells of its share of the triangles; the lists are merged in order.
    const std::size_t triangles = gridMesh.triangles.size();
    const auto parts = std::size_t(std::clamp<std::size_t>(triangles / kTrianglesPerThread, 1, std::size_t(std::max(1, threads))));
    std::vector<std::future<std::vector<std::uint32_t>>> lists;
    for (std::size_t part = 0; part < parts; ++part)
        lists.push_back(std::async(part + 1 < parts ? std::launch::async : std::launch::deferred, [&, part] {
            std::vector<std::uint32_t> touched;
            forEachTouchedCell(gridMesh, size, [&](std::size_t, std::uint32_t cell) { touched.push_back(cell); },
                               triangles * part / parts, triangles * (part + 1) / parts);
            std::sort(touched.begin(), touched.end());
            touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
            return touched;
        }));
    std::vector<std::uint32_t> all;
    for (auto& list : lists) {
        std::vector<std::uint32_t> part = list.get();
        std::vector<std::uint32_t> merged;
        merged.reserve(all.size() + part.size());
        std::set_union(all.begin(), all.end(), part.begin(), part.end(), std::back_inserter(merged));
        all = std::move(merged);
    }
    cells.insert(cells.end(), all.begin(), all.end());
}

InsideMask surfaceCells(const TriangleMesh& gridMesh, Int3 size) {
    InsideMask mask = InsideMask::empty(size);
    std::vector<std::uint32_t> cells;
    appendSurfaceCells(gridMesh, size, cells);
    for (std::uint32_t n : cells) mask.inside[n] = 1;
    return mask;
}

} // namespace sandcore
