// SPDX-License-Identifier: MIT
// LayoutBits (a layout as a bit per cell) and the huge-page allocation of big grids.
#include "large_blocks.hpp"
#include "layout_bits.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <cstdint>

using namespace sandcore;

TEST_CASE("LayoutBits gives back the layout it was made from, cell for cell") {
    CellGrid layout({67, 5, 3}, kEmpty); // rows that do not fill whole 64-bit words
    for (std::uint32_t n = 0; n < layout.cellCount(); ++n)
        if (n % 3 == 0 || n % 7 == 1) layout[n] = kInvalid;
    const LayoutBits bits(layout);
    CHECK(bits.size() == layout.size());
    const CellGrid back = bits.grid();
    std::int64_t open = 0, bottomOpen = 0;
    for (std::uint32_t n = 0; n < layout.cellCount(); ++n) {
        REQUIRE(back[n] == layout[n]);
        CHECK(bits.open(n) == (layout[n] == kEmpty));
        open += bits.open(n) ? 1 : 0;
        if (n < layout.layerSize() && layout[n] == kEmpty) ++bottomOpen;
    }
    CHECK(open > 0);
    CHECK(open < std::int64_t(layout.cellCount()));
    CHECK(bits.openCellsOfBottomLayer() == bottomOpen);
}

TEST_CASE("a scene's layout survives reset, obstacles and a flip") {
    Scene scene = makeHourglassScene(makeHourglassMask({24, 1.5f, 0.0f}), {}, {});
    const CellGrid upper = scene.layout(GridLevel::Upper), lower = scene.layout(GridLevel::Lower);
    scene.addObstacle(GridLevel::Lower, {{2, 2, 2}, {6, 4, 6}});
    for (int i = 0; i < 40; ++i) scene.step();
    scene.clearObstacles(GridLevel::Lower);
    REQUIRE(scene.flip());
    REQUIRE(scene.flip());
    scene.reset();
    for (GridLevel level : {GridLevel::Upper, GridLevel::Lower}) {
        const CellGrid& before = level == GridLevel::Upper ? upper : lower;
        const CellGrid now = scene.layout(level);
        REQUIRE(now.size() == before.size());
        for (std::uint32_t n = 0; n < now.cellCount(); ++n) REQUIRE(now[n] == before[n]);
        for (std::uint32_t n = 0; n < now.cellCount(); ++n)
            if (before[n] == kInvalid) REQUIRE(scene.grid(level)[n] == kInvalid);
    }
}

TEST_CASE("a grid of several MiB lies on a 2 MiB boundary, for huge pages") {
    const CellGrid big({256, 16, 256}); // 4 MiB of cells
    CHECK(reinterpret_cast<std::uintptr_t>(big.cells().data()) % kLargePageBytes == 0);
    CellGrid copy = big;
    copy[5] = kInvalid;
    CHECK(big[5] == kEmpty);
    CHECK(copy.countGrains() == 0);
}
