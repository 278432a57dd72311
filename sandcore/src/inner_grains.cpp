// SPDX-License-Identifier: MIT
#include "sandcore/inner_grains.hpp"

namespace sandcore {

namespace {
// A face neighbour that is EMPTY lets the grain be seen; grains, INVALID and the edge hide it.
bool hidesAt(const CellGrid& grid, int x, int y, int z) {
    return !grid.contains(x, y, z) || grid.at(x, y, z) != kEmpty;
}
} // namespace

bool isInnerCell(const CellGrid& grid, std::uint32_t cell) {
    const Int3 c = grid.coordinate(cell);
    return hidesAt(grid, c.x - 1, c.y, c.z) && hidesAt(grid, c.x + 1, c.y, c.z) && hidesAt(grid, c.x, c.y - 1, c.z) &&
           hidesAt(grid, c.x, c.y + 1, c.z) && hidesAt(grid, c.x, c.y, c.z - 1) && hidesAt(grid, c.x, c.y, c.z + 1);
}

bool isInnerGrain(const Scene& scene, GridLevel level, std::uint32_t cell) {
    const CellGrid& grid = scene.grid(level);
    const Int3 c = grid.coordinate(cell);
    const bool sideways = hidesAt(grid, c.x - 1, c.y, c.z) && hidesAt(grid, c.x + 1, c.y, c.z) &&
                          hidesAt(grid, c.x, c.y, c.z - 1) && hidesAt(grid, c.x, c.y, c.z + 1);
    if (!sideways) return false;
    const CellGrid& upper = scene.grid(GridLevel::Upper);
    const CellGrid& lower = scene.grid(GridLevel::Lower);
    const int lowerTop = lower.size().y - 1;
    bool above = hidesAt(grid, c.x, c.y + 1, c.z), below = hidesAt(grid, c.x, c.y - 1, c.z);
    if (level == GridLevel::Lower && c.y == lowerTop) above = hidesAt(upper, c.x, 1, c.z);
    if (level == GridLevel::Upper && c.y == 0) below = hidesAt(lower, c.x, lowerTop - 1, c.z);
    return above && below;
}

std::int64_t flagInnerGrains(const Scene& scene, std::span<std::uint8_t> out) {
    const GrainStore& grains = scene.grains();
    std::int64_t inner = 0;
    for (std::uint32_t id = 0; id < grains.size(); ++id) {
        const bool hidden = isInnerGrain(scene, grains.level[id], grains.place[id].cell);
        out[id] = hidden ? 1 : 0;
        inner += hidden ? 1 : 0;
    }
    return inner;
}

} // namespace sandcore
