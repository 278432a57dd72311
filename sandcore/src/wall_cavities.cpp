// SPDX-License-Identifier: MIT
#include "wall_cavities.hpp"

#include <algorithm>
#include <array>
#include <numeric>

namespace sandcore {

namespace {

// The six face neighbours of a cell, as index offsets, with a test that each stays in the grid.
struct Neighbours {
    Int3 size;
    std::size_t row, layer;
    explicit Neighbours(Int3 s) : size(s), row(std::size_t(s.x)), layer(std::size_t(s.x) * std::size_t(s.z)) {}
    template <class Visit> void forEach(std::size_t n, Visit&& visit) const {
        const std::size_t x = n % row, z = (n / row) % std::size_t(size.z), y = n / layer;
        if (x > 0) visit(n - 1);
        if (x + 1 < row) visit(n + 1);
        if (z > 0) visit(n - row);
        if (z + 1 < std::size_t(size.z)) visit(n + row);
        if (y > 0) visit(n - layer);
        if (y + 1 < std::size_t(size.y)) visit(n + layer);
    }
};

// Calls visit(first cell) for every line of cells along `axis` (0 = x, 1 = y, 2 = z).
template <class Visit> void forEachLine(Int3 size, int axis, Visit&& visit) {
    const std::size_t row = std::size_t(size.x), layer = row * std::size_t(size.z);
    for (int y = 0; y < (axis == 1 ? 1 : size.y); ++y)
        for (int z = 0; z < (axis == 2 ? 1 : size.z); ++z)
            for (int x = 0; x < (axis == 0 ? 1 : size.x); ++x) visit(std::size_t(x) + row * std::size_t(z) + layer * std::size_t(y));
}

struct Groups {
    std::vector<std::int32_t> parent;
    std::int32_t add() {
        parent.push_back(std::int32_t(parent.size()));
        return parent.back();
    }
    std::int32_t root(std::int32_t g) {
        while (parent[std::size_t(g)] != g) g = parent[std::size_t(g)] = parent[std::size_t(parent[std::size_t(g)])];
        return g;
    }
    void join(std::int32_t a, std::int32_t b) {
        a = root(a);
        b = root(b);
        if (a != b) parent[std::size_t(std::max(a, b))] = std::min(a, b);
    }
};

constexpr std::int32_t kFree = -1, kWall = -2, kOutside = -3;

} // namespace

// Three passes of a running distance along x, y and z give the cube.
MaskCells grownBy(const MaskCells& walls, Int3 size, int radius) {
    MaskCells cells = walls;
    const int lengths[3] = {size.x, size.y, size.z};
    const std::size_t strides[3] = {1, std::size_t(size.x) * std::size_t(size.z), std::size_t(size.x)};
    for (int axis = 0; axis < 3; ++axis) {
        const std::size_t stride = strides[axis];
        const auto length = std::size_t(lengths[axis]);
        MaskCells out(cells.size(), 0);
        forEachLine(size, axis, [&](std::size_t start) {
            // Distance to the nearest wall before and after each cell of the line, capped.
            int sinceWall = radius + 1;
            for (std::size_t i = 0; i < length; ++i) {
                const std::size_t n = start + i * stride;
                sinceWall = cells[n] ? 0 : std::min(sinceWall + 1, radius + 1);
                if (sinceWall <= radius) out[n] = 1;
            }
            sinceWall = radius + 1;
            for (std::size_t i = length; i-- > 0;) {
                const std::size_t n = start + i * stride;
                sinceWall = cells[n] ? 0 : std::min(sinceWall + 1, radius + 1);
                if (sinceWall <= radius) out[n] = 1;
            }
        });
        cells = std::move(out);
    }
    return cells;
}

std::vector<CellList> enclosedRegions(const MaskCells& walls, const MaskCells& grownWalls, Int3 size, int closing) {
    const Neighbours around(size);
    std::vector<std::int32_t> label(walls.size(), kFree);
    for (std::size_t n = 0; n < walls.size(); ++n)
        if (grownWalls[n]) label[n] = kWall;
    std::vector<std::uint32_t> queue;
    auto flood = [&](std::size_t seed, std::int32_t mark) { fillRuns(label, size, seed, kFree, mark, queue); };
    // The outside: every free cell reachable from the grid's six faces.
    for (int axis = 0; axis < 3; ++axis) {
        const int lengths[3] = {size.x, size.y, size.z};
        const std::size_t strides[3] = {1, std::size_t(size.x) * std::size_t(size.z), std::size_t(size.x)};
        forEachLine(size, axis, [&](std::size_t start) {
            for (std::size_t end : {start, start + std::size_t(lengths[axis] - 1) * strides[axis]})
                if (label[end] == kFree) flood(end, kOutside);
        });
    }
    Groups groups;
    for (std::size_t n = 0; n < walls.size(); ++n)
        if (label[n] == kFree) flood(n, groups.add());
    if (closing > 0) {
        // Grow back into the cells the grown walls took from the free space, one ring a round.
        // The first frontier: the labelled cells beside the band the grown walls took.
        std::vector<std::uint32_t> frontier, next, grownBack;
        std::vector<std::uint8_t> takenThisRound(walls.size(), 0);
        for (std::size_t n = 0; n < walls.size(); ++n) {
            if (label[n] != kWall || walls[n]) continue;
            around.forEach(n, [&](std::size_t m) {
                if (label[m] != kWall && !takenThisRound[m]) {
                    takenThisRound[m] = 1;
                    frontier.push_back(std::uint32_t(m));
                }
            });
        }
        for (std::uint32_t m : frontier) takenThisRound[m] = 0;
        // Grown as a cube, the walls took every cell within `closing` steps along each axis: in
        // face steps that is up to three times as many.
        for (int round = 0; round < 3 * closing && !frontier.empty(); ++round) {
            next.clear();
            for (std::uint32_t n : frontier) {
                const std::int32_t from = label[n];
                around.forEach(n, [&](std::size_t m) {
                    if (walls[m]) return;
                    if (label[m] == kWall) {
                        label[m] = from;
                        takenThisRound[m] = 1;
                        next.push_back(std::uint32_t(m));
                    } else if (takenThisRound[m] && label[m] != from) {
                        // Reached from two sides in the same round: the outside wins; two cavities join.
                        if (from == kOutside || label[m] == kOutside) label[m] = kOutside;
                        else groups.join(label[m], from);
                    }
                });
            }
            for (std::uint32_t m : next) takenThisRound[m] = 0;
            grownBack.insert(grownBack.end(), next.begin(), next.end());
            frontier.swap(next);
        }
        // Cavities that touch once grown back are one space; before, the band kept them apart.
        for (std::uint32_t n : grownBack) {
            if (label[n] < 0) continue;
            around.forEach(n, [&](std::size_t m) {
                if (label[m] >= 0) groups.join(label[n], label[m]);
            });
        }
    }
    std::vector<std::int32_t> regionOf(groups.parent.size(), -1);
    std::vector<CellList> regions;
    for (std::size_t n = 0; n < walls.size(); ++n) {
        if (label[n] < 0) continue;
        const std::int32_t root = groups.root(label[n]);
        if (regionOf[std::size_t(root)] < 0) {
            regionOf[std::size_t(root)] = std::int32_t(regions.size());
            regions.emplace_back();
        }
        regions[std::size_t(regionOf[std::size_t(root)])].push_back(std::uint32_t(n));
    }
    return regions;
}

std::vector<CellList> componentsOf(const CellList& cells, Int3 size) {
    const Neighbours around(size);
    // Each listed cell's position in the list, by cell (-1: not listed).
    std::vector<std::int32_t> position(std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z), -1);
    for (std::size_t i = 0; i < cells.size(); ++i) position[cells[i]] = std::int32_t(i);
    std::vector<std::int32_t> component(cells.size(), -1);
    std::vector<CellList> out;
    std::vector<std::size_t> queue;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (component[i] >= 0) continue;
        const auto id = std::int32_t(out.size());
        out.emplace_back();
        component[i] = id;
        queue.assign(1, i);
        while (!queue.empty()) {
            const std::size_t at = queue.back();
            queue.pop_back();
            out.back().push_back(cells[at]);
            around.forEach(cells[at], [&](std::size_t m) {
                const std::int32_t p = position[m];
                if (p >= 0 && component[std::size_t(p)] < 0) {
                    component[std::size_t(p)] = id;
                    queue.push_back(std::size_t(p));
                }
            });
        }
        std::sort(out.back().begin(), out.back().end());
    }
    return out;
}

CellList laterallyEnclosed(const MaskCells& walls, Int3 size, int axis) {
    const int lengths[3] = {size.x, size.y, size.z};
    const std::size_t strides[3] = {1, std::size_t(size.x) * std::size_t(size.z), std::size_t(size.x)};
    std::vector<std::uint8_t> sides(walls.size(), 0);
    const std::size_t total = walls.size();
    for (int across = 0; across < 3; ++across) {
        if (across == axis) continue;
        const std::size_t stride = strides[across];
        const auto length = std::size_t(lengths[across]);
        for (std::size_t start = 0; start < total; ++start) {
            if ((start / stride) % length != 0) continue;
            bool seen = false;
            for (std::size_t i = 0; i < length; ++i) {
                const std::size_t n = start + i * stride;
                if (walls[n]) seen = true;
                else if (seen) ++sides[n];
            }
            seen = false;
            for (std::size_t i = length; i-- > 0;) {
                const std::size_t n = start + i * stride;
                if (walls[n]) seen = true;
                else if (seen) ++sides[n];
            }
        }
    }
    CellList out;
    for (std::size_t n = 0; n < total; ++n)
        if (sides[n] == 4) out.push_back(std::uint32_t(n));
    return out;
}

std::int64_t cellsTouching(const CellList& cells, const MaskCells& mask, Int3 size) {
    const Neighbours around(size);
    std::int64_t count = 0;
    for (std::uint32_t n : cells) {
        bool touches = false;
        around.forEach(n, [&](std::size_t m) { touches = touches || mask[m] != 0; });
        count += touches ? 1 : 0;
    }
    return count;
}

} // namespace sandcore
