#include "sandcore/inner_grains.hpp"

namespace sandcore {

bool isInnerCell(const CellGrid& grid, std::uint32_t cell) {
    const Int3 c = grid.coordinate(cell);
    // A face neighbour that is EMPTY lets the grain be seen; grains, INVALID and the grid's edge hide it.
    auto hides = [&](int x, int y, int z) { return !grid.contains(x, y, z) || grid.at(x, y, z) != kEmpty; };
    return hides(c.x - 1, c.y, c.z) && hides(c.x + 1, c.y, c.z) && hides(c.x, c.y - 1, c.z) &&
           hides(c.x, c.y + 1, c.z) && hides(c.x, c.y, c.z - 1) && hides(c.x, c.y, c.z + 1);
}

std::int64_t flagInnerGrains(const Scene& scene, std::span<std::uint8_t> out) {
    const GrainStore& grains = scene.grains();
    std::int64_t inner = 0;
    for (std::uint32_t id = 0; id < grains.size(); ++id) {
        const bool hidden = isInnerCell(scene.grid(grains.level[id]), grains.cell[id]);
        out[id] = hidden ? 1 : 0;
        inner += hidden ? 1 : 0;
    }
    return inner;
}

} // namespace sandcore
