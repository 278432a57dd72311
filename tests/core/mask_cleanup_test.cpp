// SPDX-License-Identifier: MIT
#include "hourglass_split.hpp"
#include "sandcore/mask_cleanup.hpp"
#include "sandcore/procedural_shapes.hpp"

#include <doctest/doctest.h>

#include <cstdlib>

using namespace sandcore;

namespace {
InsideMask boxMask(Int3 size, Int3 from, Int3 to) {
    InsideMask mask = InsideMask::empty(size);
    for (int y = from.y; y < to.y; ++y)
        for (int z = from.z; z < to.z; ++z)
            for (int x = from.x; x < to.x; ++x) mask.set(x, y, z, true);
    return mask;
}
} // namespace

TEST_CASE("noNoise removes a lone cell and a one-cell spike, to a fixpoint") {
    InsideMask mask = boxMask({7, 7, 7}, {1, 1, 1}, {4, 4, 4}); // 27 cells
    mask.set(6, 6, 6, true);                                     // lone cell: 0 neighbours
    mask.set(4, 2, 2, true);                                     // spike of two cells off the +x face
    mask.set(5, 2, 2, true);
    CHECK(removeNoise(mask, 1) == 3); // the spike's tip first, then its base
    CHECK(mask.countInside() == 27);
    CHECK_FALSE(mask.at(4, 2, 2));
}

TEST_CASE("noNoise with threshold 2 keeps a solid cube but removes a one-cell rod") {
    InsideMask cube = boxMask({6, 6, 6}, {1, 1, 1}, {5, 5, 5});
    CHECK(removeNoise(cube, 2) == 0); // corners have 3 inside neighbours
    CHECK(cube.countInside() == 64);
    InsideMask rod = boxMask({8, 3, 3}, {0, 1, 1}, {8, 2, 2});
    CHECK(removeNoise(rod, 2) == 8);
    CHECK(rod.countInside() == 0);
}

TEST_CASE("noSharpEdges carves a flat shelf into a 45 degree slope and keeps a funnel") {
    // Layer 0: a 1x1 outlet at x = 3; layers 1..3: a shelf 7 cells wide in x (1 deep in z).
    InsideMask shelf = InsideMask::empty({7, 4, 1});
    shelf.set(3, 0, 0, true);
    for (int y = 1; y < 4; ++y)
        for (int x = 0; x < 7; ++x) shelf.set(x, y, 0, true);
    CHECK(removeSharpEdges(shelf, 0, 3) == 6); // of 7 cells per layer, 3, 5 and 7 stay
    for (int y = 1; y < 4; ++y)
        for (int x = 0; x < 7; ++x) CHECK(shelf.at(x, y, 0) == (std::abs(x - 3) <= y));

    InsideMask funnel = InsideMask::empty({7, 4, 1});
    for (int y = 0; y < 4; ++y)
        for (int x = 3 - y; x <= 3 + y; ++x) funnel.set(x, y, 0, true);
    CHECK(removeSharpEdges(funnel, 0, 3) == 0);
}

TEST_CASE("the neck of a procedural hourglass is its middle layer and it splits there") {
    HourglassShape shape;
    shape.height = 32;
    const InsideMask mask = makeHourglassMask(shape);
    const int neck = findNeckLayer(mask);
    CHECK((neck == 15 || neck == 16));
    CHECK(hasNeck(mask, neck));
    CHECK_FALSE(hasNeck(makeCubeMask(16), findNeckLayer(makeCubeMask(16))));
}
