// SPDX-License-Identifier: MIT
// Procedural masks, S3 clean-up and the S4 neck split.
#include "hourglass_split.hpp"
#include "sandcore/mask_cleanup.hpp"
#include "sandcore/procedural_shapes.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace sandcore;

TEST_CASE("the procedural sphere and cube have the expected volumes") {
    const InsideMask sphere = makeSphereMask(64);
    const double exact = 4.0 / 3.0 * M_PI * 32.0 * 32.0 * 32.0;
    CHECK(std::abs(double(sphere.countInside()) - exact) / exact < 0.01);
    CHECK(makeCubeMask(10).countInside() == 8 * 8 * 8);
}

TEST_CASE("an empty mask is all outside, even in a reused block that held inside flags") {
    // MaskCells leaves flags unset when sized without a value; empty() must clear them.
    const Int3 size{128, 160, 128}; // 2.5 MiB: a large block, kept once freed
    const std::size_t cells = std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z);
    { const MaskCells dirty(cells, std::uint8_t{1}); }
    const InsideMask mask = InsideMask::empty(size);
    REQUIRE(mask.inside.size() == cells);
    CHECK(std::count(mask.inside.begin(), mask.inside.end(), std::uint8_t{0}) == std::ptrdiff_t(cells));
    CHECK(mask.countInside() == 0);
}

TEST_CASE("the procedural hourglass narrows to its neck in the middle layer") {
    const InsideMask mask = makeHourglassMask({64, 2.0f, 0.0f});
    CHECK(mask.size.y == 64);
    const int neck = findNeckLayer(mask);
    CHECK(std::abs(neck - 32) <= 1);
    CHECK(hasNeck(mask, neck));
    CHECK(mask.countInsideLayer(neck) < mask.countInsideLayer(16) / 10);
    CHECK_THROWS(makeHourglassMask({64, 40.0f, 10.0f}));
    CHECK_THROWS(makeHourglassMask({4, 1.0f, 0.0f}));
}

TEST_CASE("a plain vessel has no neck") {
    const InsideMask cube = makeCubeMask(16);
    CHECK(!hasNeck(cube, findNeckLayer(cube)));
}

TEST_CASE("removeNoise removes isolated cells and thin spikes, repeated until nothing changes") {
    InsideMask mask = makeCubeMask(8); // solid 6x6x6 at 1..6
    mask.set(0, 0, 0, true);           // an isolated cell: 0 neighbours
    // A spike of two cells sticking out of the top face at (3, 7, 3) and above... the box ends at 7,
    // so use a sideways spike along -x from (1, 3, 3): cells (0, 3, 3) only has 1 neighbour.
    mask.set(0, 3, 3, true);
    const std::int64_t before = mask.countInside();
    CHECK(removeNoise(mask, 1) == 2);
    CHECK(mask.countInside() == before - 2);
    CHECK(!mask.at(0, 0, 0));
    CHECK(!mask.at(0, 3, 3));
    // A correct solid is not eroded: corners of the cube have 3 inside neighbours.
    CHECK(removeNoise(mask, 2) == 0);
    CHECK(mask.countInside() == 216);
}

TEST_CASE("removeNoise reaches a fixpoint: a one-cell line is removed from both ends inwards") {
    InsideMask mask = InsideMask::empty({7, 1, 1});
    for (int x = 0; x < 7; ++x) mask.set(x, 0, 0, true);
    CHECK(removeNoise(mask, 2) == 7); // every cell has at most 2 neighbours
    CHECK(mask.countInside() == 0);
}

TEST_CASE("removeSharpEdges carves a flat shelf into a funnel that drains") {
    // A 7-wide flat-bottomed box over a one-cell outlet at (3, 0, 3).
    InsideMask mask = InsideMask::empty({7, 5, 7});
    mask.set(3, 0, 3, true);
    for (int y = 1; y < 5; ++y)
        for (int z = 0; z < 7; ++z)
            for (int x = 0; x < 7; ++x) mask.set(x, y, z, true);
    const std::int64_t removed = removeSharpEdges(mask, 0, 4);
    // Layer y keeps the cells within Chebyshev distance y of the outlet column.
    for (int y = 1; y < 5; ++y)
        for (int z = 0; z < 7; ++z)
            for (int x = 0; x < 7; ++x) {
                const bool expected = std::max(std::abs(x - 3), std::abs(z - 3)) <= y;
                REQUIRE_MESSAGE(mask.at(x, y, z) == expected, "cell " << x << "," << y << "," << z);
            }
    CHECK(removed == (49 - 9) + (49 - 25) + 0 + 0);
    CHECK(mask.at(3, 0, 3)); // the outlet stays
    CHECK(removeSharpEdges(mask, 0, 4) == 0);
}

TEST_CASE("removeSharpEdges leaves a funnel that already drains untouched") {
    InsideMask mask = makeHourglassMask({48, 2.0f, 0.0f});
    const int neck = findNeckLayer(mask);
    InsideMask upper = sliceLayers(mask, neck, mask.size.y - 1);
    const InsideMask before = upper;
    removeSharpEdges(upper, 0, upper.size.y - 1);
    // Only the rounded cap at the very top may lose cells; the funnel near the neck stays whole.
    for (int y = 0; y < upper.size.y / 2; ++y) CHECK(upper.countInsideLayer(y) == before.countInsideLayer(y));
}

TEST_CASE("sliceLayers copies layers and renumbers them from 0") {
    const InsideMask mask = makeSphereMask(10);
    const InsideMask slice = sliceLayers(mask, 3, 6);
    CHECK(slice.size == Int3{10, 4, 10});
    for (int y = 0; y < 4; ++y) CHECK(slice.countInsideLayer(y) == mask.countInsideLayer(y + 3));
    CHECK_THROWS(sliceLayers(mask, 5, 10));
}
