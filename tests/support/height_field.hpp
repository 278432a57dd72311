// SPDX-License-Identifier: MIT
#pragma once
// A grid filled with sand below a height field: the known slopes and piles several tests measure.

#include "sandcore/cell_grid.hpp"

namespace support {

/// A grid of `size` with a grain in every cell (x, y, z) where y < height(x, z).
template <class Height> sandcore::CellGrid heightField(sandcore::Int3 size, Height height) {
    sandcore::CellGrid grid(size);
    sandcore::CellValue id = 0;
    for (int y = 0; y < size.y; ++y)
        for (int z = 0; z < size.z; ++z)
            for (int x = 0; x < size.x; ++x)
                if (y < height(x, z)) grid[grid.index(x, y, z)] = id++;
    return grid;
}

} // namespace support
