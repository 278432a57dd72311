// SPDX-License-Identifier: MIT
// R13: inner grains.
#include "support/scene_fixtures.hpp"

#include "sandcore/inner_grains.hpp"

#include <doctest/doctest.h>

using namespace sandcore;

TEST_CASE("in a solid 5x5x5 block of sand only the 3x3x3 core is inner") {
    Scene scene = fixtures::boxScene({9, 9, 9});
    for (int y = 2; y < 7; ++y)
        for (int z = 2; z < 7; ++z)
            for (int x = 2; x < 7; ++x) fixtures::putLower(scene, x, y, z);
    std::vector<std::uint8_t> inner(std::size_t(scene.grainCount()));
    CHECK(flagInnerGrains(scene, inner) == 27);
    const CellGrid& grid = scene.grid(GridLevel::Lower);
    CHECK(isInnerCell(grid, grid.index(4, 4, 4)));
    CHECK(!isInnerCell(grid, grid.index(2, 4, 4)));
    CHECK(!isInnerCell(grid, grid.index(6, 6, 6)));
}

TEST_CASE("grid edges and INVALID cells hide a face, and EMPTY cells expose it") {
    // A 3x1x3 layer of grains on the floor of a 3x3x3 box: the centre grain's only open face is up.
    Scene scene = fixtures::boxScene({3, 3, 3}, 1, {{1, 2, 1}});
    for (int z = 0; z < 3; ++z)
        for (int x = 0; x < 3; ++x) fixtures::putLower(scene, x, 0, z);
    const CellGrid& grid = scene.grid(GridLevel::Lower);
    CHECK(!isInnerCell(grid, grid.index(1, 0, 1))); // (1,1,1) above it is EMPTY
    fixtures::putLower(scene, 1, 1, 1);              // covered by a grain; (1,2,1) above that is INVALID
    CHECK(isInnerCell(grid, grid.index(1, 0, 1)));
}

TEST_CASE("at the seam of the two grids a grain is seen through the other grid") {
    // A column of grains in the lower grid's top row, with nothing above it in the upper grid.
    Scene scene = fixtures::boxScene({3, 3, 3}, 3);
    for (int y = 0; y < 3; ++y)
        for (int z = 0; z < 3; ++z)
            for (int x = 0; x < 3; ++x) fixtures::putLower(scene, x, y, z);
    const CellGrid& lower = scene.grid(GridLevel::Lower);
    const std::uint32_t topCentre = lower.index(1, 2, 1);
    CHECK(isInnerCell(lower, topCentre));                       // within its own grid: the edge hides it
    CHECK(!isInnerGrain(scene, GridLevel::Lower, topCentre));   // but the upper grid above it is EMPTY
    const CellGrid& upper = scene.grid(GridLevel::Upper);
    scene.addGrain(GridLevel::Upper, upper.index(1, 1, 1));
    CHECK(isInnerGrain(scene, GridLevel::Lower, topCentre));    // now covered from above
    CHECK(isInnerGrain(scene, GridLevel::Lower, lower.index(1, 1, 1)));
}
