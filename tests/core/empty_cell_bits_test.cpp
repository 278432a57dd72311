// SPDX-License-Identifier: MIT
// EmptyCellBits (sandcore/src/empty_cells.hpp): the EMPTY cells a granular sweep keeps as bits,
// read back as windows, against the cells themselves.
#include "empty_cells.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <random>

using namespace sandcore;

namespace {

// Bit i for cell (x0 + i, y, z), i < width: set when the cell lies in the grid and is EMPTY.
unsigned emptyRowOfCells(const CellGrid& grid, int x0, int y, int z, int width) {
    const Int3 size = grid.size();
    unsigned bits = 0;
    for (int i = 0; i < width; ++i) {
        const int x = x0 + i;
        if (x >= 0 && x < size.x && y >= 0 && y < size.y && z >= 0 && z < size.z && grid.at(x, y, z) == kEmpty)
            bits |= 1u << i;
    }
    return bits;
}

// A grid 150 cells long, its cells EMPTY, INVALID or a grain at random. With the bits' margin of
// 16 cells before x = 0 its rows are three 64-bit words, the last one partly used: windows around
// x = 48 and x = 112 cross from one word into the next.
CellGrid randomGrid(std::mt19937& random) {
    CellGrid grid({150, 4, 11}, kEmpty);
    for (std::uint32_t n = 0; n < grid.cellCount(); ++n) {
        const unsigned pick = random() % 3;
        grid[n] = pick == 0 ? kEmpty : pick == 1 ? kInvalid : CellValue(n);
    }
    return grid;
}

} // namespace

TEST_CASE("EmptyCellBits reads a grid's EMPTY cells, and windows read them back across word boundaries and "
          "the grid's sides") {
    std::mt19937 random(7);
    CellGrid grid = randomGrid(random);
    EmptyCellBits bits;
    bits.resize(grid.size());
    CHECK_FALSE(bits.matches(grid)); // resized: every cell taken
    bits.read(grid);
    REQUIRE(bits.matches(grid));
    const Int3 size = grid.size();
    for (int y = -EmptyCellBits::kMarginBelow; y < size.y; ++y)
        for (int z = 0; z < size.z; ++z)
            for (int x = 0; x < size.x; ++x) {
                std::uint64_t window7 = 0, window5 = 0;
                for (int r = 0; r < 7; ++r) window7 |= std::uint64_t(emptyRowOfCells(grid, x - 3, y, z - 3 + r, 7)) << (7 * r);
                for (int r = 0; r < 5; ++r) window5 |= std::uint64_t(emptyRowOfCells(grid, x - 2, y, z - 2 + r, 5)) << (5 * r);
                if (bits.window<3>(x, y, z) != window7) FAIL("window<3>(" << x << ", " << y << ", " << z << ")");
                if (bits.window<2>(x, y, z) != window5) FAIL("window<2>(" << x << ", " << y << ", " << z << ")");
            }
}

TEST_CASE("EmptyCellBits follows each change it is told of, and tells a change it was not told of") {
    std::mt19937 random(11);
    CellGrid grid = randomGrid(random);
    EmptyCellBits bits;
    bits.resize(grid.size());
    bits.read(grid);
    for (int change = 0; change < 2000; ++change) {
        const Int3 c{int(random() % 150), int(random() % 4), int(random() % 11)};
        const bool empty = random() % 2 == 0;
        grid[grid.index(c.x, c.y, c.z)] = empty ? kEmpty : CellValue(change);
        bits.setEmpty(c.x, c.y, c.z, empty);
        CHECK(bits.isEmpty(c.x, c.y, c.z) == empty);
    }
    CHECK(bits.matches(grid));
    grid[grid.index(149, 3, 10)] = grid.at(149, 3, 10) == kEmpty ? kInvalid : kEmpty; // untold
    CHECK_FALSE(bits.matches(grid));
}
