// SPDX-License-Identifier: MIT
#pragma once
// Granular: the grains whose options a cell that became EMPTY can widen (R5), and only those.
// granular_rules.hpp says what a grain reads: in the emptied cell's layer, the grains within 3
// columns whose sideways path may cross it; above it, the grain right above, which may now fall;
// and in each layer up to maxDrop above, those whose slide may now end in this column or reach
// further down it. Private to sandcore.

#include "awake_cells.hpp"
#include "empty_cells.hpp"
#include "granular_rules.hpp"
#include "sandcore/cell_grid.hpp"
#include "layout_bits.hpp"
#include "threshold_dither.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace sandcore {

/// The wakes of one grid under the granular rules, over the bits the sweep keeps of it.
struct GranularWakes {
    const GranularRules& rules;
    const ThresholdDither& dither; ///< the grid's under the seed, as the visits read it
    const EmptyCellBits& empty;    ///< the grid's EMPTY cells
    const LayoutBits& layout;      ///< the grid's INVALID cells (the vessel and obstacles)
    const CellGrid& grid;
    AwakeCells& awake;

    /// (x, y, z) became EMPTY: wakes the grains around it and above it that may gain.
    void aroundEmptied(int x, int y, int z) const {
        if (y > 0) grainsAround(x, y, z, 0); // layer 0 only falls or transitions
        layersAbove(x, y, z);
    }
    /// The wakes above layer y of aroundEmptied. Inline: the visit that emptied the cell calls it
    /// for every move.
    [[gnu::always_inline]] inline void layersAbove(int x, int y, int z) const;
    /// Wakes the grains of layer y at the cells of GranularRules::wakeMask(layersAbove) around
    /// (x, z) that may gain from (x, y - layersAbove, z) being EMPTY.
    void grainsAround(int x, int y, int z, int layersAbove) const {
        // The grains in the window not yet awake: waking an awake one changes nothing. Often
        // every grain around is awake already, or none is there (in the layers well above the
        // emptied cell the mask holds only the window's outer rows and columns): inline, those
        // calls cost no call, and the rest is out of line.
        const std::uint64_t sleeping = rules.wakeMask(layersAbove) & sleepingGrainsAround(x, y, z);
        if (sleeping) wakeSleepingGrainsAround(x, y, z, layersAbove, sleeping);
    }

private:
    static constexpr int kReach = kGranularReach, kWindow = 2 * kGranularReach + 1;
    static constexpr std::uint64_t kRowMask = (std::uint64_t{1} << kWindow) - 1;
    /// The 8 cells around a window's centre, window bits.
    static constexpr std::uint64_t kNextTo = (std::uint64_t{0x1c} << 14) | (std::uint64_t{0x14} << 21) | (std::uint64_t{0x1c} << 28);

    /// Wakes the grains next to (x, y, z), whose dives under its grain may have opened.
    void divesUnder(int x, int y, int z) const {
        if (const std::uint64_t sleeping = kNextTo & sleepingGrainsAround(x, y, z)) wakeWindow(x, y, z, sleeping);
    }

    void wakeSleepingGrainsAround(int x, int y, int z, int layersAbove, std::uint64_t sleeping) const;
    std::uint64_t deepEnoughForSlidesInto(std::uint64_t woken, int x, int y, int z, int layersAbove) const;
    /// The cell under cell `from` (not in layer 0) is INVALID, read from the kept bits.
    bool liesOnVessel(std::uint32_t from) const { return !layout.open(from - grid.layerSize()); }

    /// Where a window's 7 columns around x lie in a row's words of bits: columns left of 0 are
    /// dropped (shifted out), those right of the grid meet occupied bits that are never set.
    struct WindowColumns {
        int word, offset, dropped; // first word, the bit the window starts at in it, columns left of 0
        bool spills;               // the window runs on into the next word
    };
    WindowColumns windowColumnsAround(int x) const {
        const int first = std::max(x - kReach, 0), dropped = first - (x - kReach);
        const int word = first >> 6, offset = first & 63;
        return {word, offset, dropped, offset + kWindow - dropped > 64 && word + 1 < awake.rowWords()};
    }
    inline std::uint64_t sleepingGrainsAround(int x, int y, int z) const;
    std::uint64_t sleepingGrainsAroundSide(int x, int y, int z) const;
    void wakeWindow(int x, int y, int z, std::uint64_t woken) const;
};

// A slide's path at the grain's own level includes the cell above its target, and its look down
// the column needs every cell between EMPTY: so while the column above (x, y, z) is EMPTY each
// layer's window is woken, and the first cell of it that is not EMPTY ends the search (only the
// grain in it, when it lies right above (x, y, z), can gain: it may fall).
inline void GranularWakes::layersAbove(int x, int y, int z) const {
    const int top = std::min(y + rules.maxDrop(), awake.size().y - 1);
    for (int layer = y + 1; layer <= top; ++layer) {
        if (!empty.isEmpty(x, layer, z)) { // the kept bits: a column's cells lie a layer apart
            // A grain right above may fall. The cell holds a grain or the vessel, and its occupied
            // bit tells which without reading it: never clear under a grain (but in a column asleep
            // in its fall, whose woken grain wakes the one above it itself), never set on the
            // vessel but where an edit left it stale (a cell woken so is visited and left).
            if (layer == y + 1) awake.wakeIfOccupied(x, layer, z);
            // A grain there lies over EMPTY cells down to (x, y, z): the grains next to it may
            // dive under it (GranularRules::slide), the deeper the column the more of them.
            if (layout.open(grid.index(x, layer, z))) divesUnder(x, layer, z);
            break;
        }
        grainsAround(x, layer, z, layer - y);
    }
}

// The 7x7 cells around (x, z) of layer y (bit (dz + 3) * 7 + (dx + 3)) that hold a grain and are
// not awake. Away from the grid's sides, where the 7 cells of a row lie in one word, a row is a
// load and two shifts.
inline std::uint64_t GranularWakes::sleepingGrainsAround(int x, int y, int z) const {
    const int x0 = x - kReach, offset = x0 & 63;
    const std::size_t stride = std::size_t(awake.rowWords());
    if (x0 >= 0 && offset + kWindow <= 64 && z >= kReach && z + kReach < awake.size().z) {
        const AwakeCells::Word* row = awake.rowWords(awake.rowOf(y, z - kReach)) + std::size_t(x0 >> 6);
        // Spelled out row by row: each row's place in the window is then a constant.
        return [&]<std::size_t... r>(std::index_sequence<r...>) {
            return (((row[r * stride].sleeping() >> offset & kRowMask) << (r * kWindow)) | ...);
        }(std::make_index_sequence<kWindow>{});
    }
    return sleepingGrainsAroundSide(x, y, z);
}

} // namespace sandcore
