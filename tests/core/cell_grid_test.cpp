// SPDX-License-Identifier: MIT
#include "sandcore/cell_grid.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

using namespace sandcore;

TEST_CASE("index layout is x fastest, then z, then y, and the cell above is one layer on") {
    const CellGrid grid({4, 3, 5});
    CHECK(grid.layerSize() == 20u);
    CHECK(grid.cellCount() == 60u);
    CHECK(grid.index(1, 0, 0) == 1u);
    CHECK(grid.index(0, 0, 1) == 4u);
    CHECK(grid.index(0, 1, 0) == 20u);
    CHECK(grid.index(3, 2, 4) == 59u);
    const std::uint32_t n = grid.index(2, 1, 3);
    CHECK(grid.index(2, 2, 3) == n + grid.layerSize());
    CHECK(grid.coordinate(n) == Int3{2, 1, 3});
}

TEST_CASE("an interior cell has 9 successors with the direct one first, 9 predecessors and 8 near cells") {
    const CellGrid grid({3, 3, 3});
    const std::uint32_t centre = grid.index(1, 1, 1);
    std::uint32_t out[9];
    REQUIRE(grid.successorsOf(centre, out) == 9);
    CHECK(out[0] == grid.index(1, 0, 1));
    std::set<std::uint32_t> below(out, out + 9);
    CHECK(below.size() == 9);
    for (std::uint32_t n : below) CHECK(grid.coordinate(n).y == 0);
    REQUIRE(grid.predecessorsOf(centre, out) == 9);
    CHECK(out[0] == grid.index(1, 2, 1));
    for (int i = 0; i < 9; ++i) CHECK(grid.coordinate(out[i]).y == 2);
    REQUIRE(grid.nearCellsOf(centre, out) == 8);
    for (int i = 0; i < 8; ++i) {
        CHECK(grid.coordinate(out[i]).y == 1);
        CHECK(out[i] != centre);
    }
}

TEST_CASE("cells outside the box are not neighbours") {
    const CellGrid grid({3, 3, 3});
    std::uint32_t out[9];
    CHECK(grid.successorsOf(grid.index(0, 1, 0), out) == 4);  // corner column
    CHECK(grid.successorsOf(grid.index(1, 1, 0), out) == 6);  // edge column
    CHECK(grid.successorsOf(grid.index(1, 0, 1), out) == 0);  // bottom layer
    CHECK(grid.predecessorsOf(grid.index(1, 2, 1), out) == 0); // top layer
    CHECK(grid.nearCellsOf(grid.index(2, 0, 2), out) == 3);
}

TEST_CASE("neighbours come in one fixed order: the direct one first, then z outer, x inner, clipped at the box") {
    const CellGrid grid({4, 3, 4});
    std::uint32_t out[9];
    REQUIRE(grid.successorsOf(grid.index(1, 1, 1), out) == 9);
    const Int3 interior[9] = {{1, 0, 1}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1},
                              {2, 0, 1}, {0, 0, 2}, {1, 0, 2}, {2, 0, 2}};
    for (int i = 0; i < 9; ++i) CHECK(grid.coordinate(out[i]) == interior[i]);
    // On the x = 3 edge at z = 0, the columns outside the box drop out and the order stays.
    REQUIRE(grid.nearCellsOf(grid.index(3, 2, 0), out) == 3);
    CHECK(grid.coordinate(out[0]) == Int3{2, 2, 0});
    CHECK(grid.coordinate(out[1]) == Int3{2, 2, 1});
    CHECK(grid.coordinate(out[2]) == Int3{3, 2, 1});
}

TEST_CASE("grid sizes are validated before allocating") {
    CHECK_THROWS_AS(CellGrid({0, 4, 4}), std::invalid_argument);
    CHECK_THROWS_AS(CellGrid({4, -1, 4}), std::invalid_argument);
    // 2048^3 = 2^33 cells: rejected with a message, without trying to allocate 32 GiB.
    try {
        CellGrid({2048, 2048, 2048});
        FAIL("a grid over 2^31 cells was accepted");
    } catch (const std::invalid_argument& e) {
        CHECK(std::string(e.what()).find("exceeds the limit of 2^31 cells") != std::string::npos);
    }
    CHECK_NOTHROW(validateGridSize({1290, 1290, 1290})); // 2,146,689,000 cells: just under 2^31
    CHECK_THROWS(validateGridSize({1291, 1291, 1291}));
    // The largest int on every axis is refused without the cell count overflowing (UBSan checks).
    const int most = std::numeric_limits<int>::max();
    CHECK_THROWS_WITH(validateGridSize({most, most, most}),
                      doctest::Contains("exceeds the limit of 2^31 cells"));
}
