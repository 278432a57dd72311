#pragma once
// The thesis's rules (§3.2, Abb. 13 and 16), private to sandcore: a grain falls to its direct
// successor when that cell is empty; otherwise it slips to one of its empty successors, chosen
// uniformly at random; INVALID cells are never entered.

#include "sandcore/cell_grid.hpp"
#include "sandcore/counter_random.hpp"

#include <optional>

namespace sandcore {

/// Column (x, z) in the layer below that a grain moves to.
struct MoveTarget {
    int x;
    int z;
};

/// Where the grain at (x, y, z), y >= 1, goes this step, or nothing if every successor is full.
/// random() is called only for a slip.
template <class RandomSource>
std::optional<MoveTarget> chooseMove(const CellGrid& grid, int x, int y, int z, RandomSource&& random) {
    const Int3 size = grid.size();
    if (grid.at(x, y - 1, z) == kEmpty) return MoveTarget{x, z}; // fall

    MoveTarget empty[8];
    std::uint32_t count = 0;
    for (int dz = -1; dz <= 1; ++dz) {
        const int zz = z + dz;
        if (zz < 0 || zz >= size.z) continue;
        for (int dx = -1; dx <= 1; ++dx) {
            const int xx = x + dx;
            if (xx < 0 || xx >= size.x || (dx == 0 && dz == 0)) continue;
            if (grid.at(xx, y - 1, zz) == kEmpty) empty[count++] = {xx, zz};
        }
    }
    if (count == 0) return std::nullopt;
    return empty[pickBelow(random(), count)]; // slip
}

} // namespace sandcore
