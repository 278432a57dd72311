// SPDX-License-Identifier: MIT
#include "sandcore/normals.hpp"

#include "layer_neighbourhood.hpp"

#include <cmath>

namespace sandcore {

namespace {
Vec3 normalised(float x, float y, float z) {
    const float length = std::sqrt(x * x + y * y + z * z);
    if (length == 0.0f) return {0.0f, 1.0f, 0.0f};
    return {x / length, y / length, z / length};
}
} // namespace

std::vector<int> columnHeights(const CellGrid& grid) {
    const Int3 s = grid.size();
    std::vector<int> heights(std::size_t(s.x) * std::size_t(s.z), 0);
    for (int z = 0; z < s.z; ++z)
        for (int x = 0; x < s.x; ++x)
            for (int y = s.y - 1; y >= 0; --y)
                if (grid.at(x, y, z) >= 0) {
                    heights[std::size_t(x) + std::size_t(s.x) * std::size_t(z)] = y + 1;
                    break;
                }
    return heights;
}

namespace {

// thesis §3.8 (Abb. 33 and its table): a neighbour column that is higher tilts the face normal
// away from it, one that is lower tilts it towards it, and an equal one gives (0, 1, 0).
Vec3 columnNormalFromNeighbours(const std::vector<int>& heights, Int3 gridSize, int x, int z) {
    const int here = heights[std::size_t(x) + std::size_t(gridSize.x) * std::size_t(z)];
    float sx = 0, sy = 0, sz = 0;
    int faces = 0;
    const LayerNeighbourhood around(x, z, gridSize.x, gridSize.z);
    around.forEachAround([&](int dx, int dz) {
        const int there = heights[std::size_t(around.column(dx, dz))];
        const float side = there > here ? -1.0f : there < here ? 1.0f : 0.0f;
        const Vec3 face = normalised(side * float(dx), 1.0f, side * float(dz));
        sx += face.x;
        sy += face.y;
        sz += face.z;
        ++faces;
    });
    if (faces == 0) return {0.0f, 1.0f, 0.0f};
    return normalised(sx, sy, sz);
}

// The 8 columns around an inner column; digit i of a table index is neighbour i's side.
constexpr int kAroundX[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr int kAroundZ[8] = {-1, -1, -1, 0, 0, 1, 1, 1};
constexpr int kSideCombinations = 6561; // 3^8

// Away from the grid's sides a column's normal depends only on whether each of its 8 neighbours
// is lower, equal or higher: every one of the 3^8 answers, each computed by the function above on
// a 3x3 patch of such heights, so a lookup gives the very same floats without 9 square roots
// (the surface upkeep recomputes thousands of column normals a step).
class ColumnNormalTable {
public:
    ColumnNormalTable() {
        std::vector<int> patch(9);
        for (int combination = 0; combination < kSideCombinations; ++combination) {
            patch[4] = 1;
            for (int i = 0, rest = combination; i < 8; ++i, rest /= 3)
                patch[std::size_t(kAroundX[i] + 1 + 3 * (kAroundZ[i] + 1))] = rest % 3; // 0 lower, 1 equal, 2 higher
            normals_[std::size_t(combination)] = columnNormalFromNeighbours(patch, {3, 1, 3}, 1, 1);
        }
    }
    const Vec3& operator[](int combination) const { return normals_[std::size_t(combination)]; }

private:
    Vec3 normals_[kSideCombinations];
};

} // namespace

Vec3 columnNormal(const std::vector<int>& heights, Int3 gridSize, int x, int z) {
    if (x < 1 || z < 1 || x + 1 >= gridSize.x || z + 1 >= gridSize.z) return columnNormalFromNeighbours(heights, gridSize, x, z);
    static const ColumnNormalTable table;
    const std::size_t centre = std::size_t(x) + std::size_t(gridSize.x) * std::size_t(z);
    const int here = heights[centre];
    int combination = 0;
    for (int i = 7; i >= 0; --i) {
        const int there = heights[centre + std::size_t(std::ptrdiff_t(kAroundX[i]) + std::ptrdiff_t(gridSize.x) * kAroundZ[i])];
        combination = 3 * combination + (there > here ? 2 : there < here ? 0 : 1);
    }
    return table[combination];
}

Int3 occupancyGradientSums(const CellGrid& grid, std::uint32_t cell) {
    const Int3 c = grid.coordinate(cell);
    const CellNeighbourhood around(grid, c.x, c.y, c.z);
    int gx = 0, gy = 0, gz = 0;
    for (int dy = -1; dy <= 1; ++dy) {
        if (!around.hasLayer(dy)) continue;
        around.forEachWithCentre([&](int dx, int dz) {
            if (around.at(dx, dy, dz) < 0) return;
            gx += dx;
            gy += dy;
            gz += dz;
        });
    }
    return {gx, gy, gz};
}

int occupiedNeighbours(const CellGrid& grid, std::uint32_t cell) {
    const Int3 c = grid.coordinate(cell);
    const CellNeighbourhood around(grid, c.x, c.y, c.z);
    int count = 0;
    for (int dy = -1; dy <= 1; ++dy) {
        if (!around.hasLayer(dy)) continue;
        around.forEachWithCentre([&](int dx, int dz) {
            if ((dx != 0 || dy != 0 || dz != 0) && around.at(dx, dy, dz) >= 0) ++count;
        });
    }
    return count;
}

Vec3 gradientNormal(const CellGrid& grid, std::uint32_t cell) {
    const Int3 g = occupancyGradientSums(grid, cell);
    return occupancyGradientNormal(g.x, g.y, g.z);
}

// Sand lies where the gradient points; the surface faces the other way.
Vec3 occupancyGradientNormal(int gx, int gy, int gz) { return normalised(float(-gx), float(-gy), float(-gz)); }

void estimateGrainNormals(const Scene& scene, NormalMethod method, std::span<Vec3> out) {
    const GrainStore& grains = scene.grains();
    if (method == NormalMethod::OccupancyGradient) {
        for (std::uint32_t id = 0; id < grains.size(); ++id)
            out[id] = gradientNormal(scene.grid(grains.level[id]), grains.place[id].cell);
        return;
    }
    for (GridLevel level : {GridLevel::Lower, GridLevel::Upper}) {
        const CellGrid& grid = scene.grid(level);
        const Int3 s = grid.size();
        const std::vector<int> heights = columnHeights(grid);
        std::vector<Vec3> normals(heights.size());
        for (int z = 0; z < s.z; ++z)
            for (int x = 0; x < s.x; ++x)
                normals[std::size_t(x) + std::size_t(s.x) * std::size_t(z)] = columnNormal(heights, s, x, z);
        for (std::uint32_t id = 0; id < grains.size(); ++id) {
            if (grains.level[id] != level) continue;
            out[id] = normals[grains.place[id].cell % grid.layerSize()];
        }
    }
}

} // namespace sandcore
