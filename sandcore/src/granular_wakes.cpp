// SPDX-License-Identifier: MIT
#include "granular_wakes.hpp"

#include <bit>

namespace sandcore {

// In the emptied cell's own layer (layersAbove 0): a grain within 3 columns gains when one of its
// slides crosses (x, z) on a path EMPTY all along to an EMPTY cell of the layer below, deep enough
// for it (or the grain lies on the vessel). Any other grain gains nothing from (x, z) now, and
// whatever later opens such a slide (a cell of the path or the target emptying, the column below
// deepening) wakes it then. In the layers above: those whose sideways path towards (x, z)'s column
// is EMPTY at their level (the only one of their options that the emptied cell can widen) and
// whose slide looks as deep as the emptied cell (deepEnoughForSlidesInto); the column above it is
// EMPTY up to layer y (layersAbove). Each row's 7 bits are shifted into place and ANDed with the
// occupied bits, as AwakeCells::wakeSpan does, so EMPTY and INVALID cells stay asleep. In the
// layers above, this runs before their turn in the step; in the emptied cell's own layer, at the
// sweep's end (wakeAroundCellsLeft, granular_step.hpp), for the next step.
void GranularWakes::wakeSleepingGrainsAround(int x, int y, int z, int layersAbove, std::uint64_t woken) const {
    if (layersAbove == 0) {
        // A slide that needs its column two cells deep also needs the cell under its target EMPTY,
        // unless the grain lies on the vessel, where one cell is enough. Such slides end in the
        // 5x5 columns around (x, z): target by target, the grains whose path to it is open
        // (GranularRules::grainsWithOpenSlideAcrossCentreTo), over the EMPTY targets into which
        // some of the grains slide across (x, z) only. Outside the grid the windows read as
        // taken; under layer 1 the column is never deep enough.
        constexpr int across = GranularRules::kAcrossReach;
        auto targets = std::uint32_t(empty.window<across>(x, y - 1, z)) & rules.targetsAcrossCentreOf(woken);
        if (!targets) return;
        const std::uint64_t here = empty.window<kGranularReach>(x, y, z);
        std::uint64_t deepTargets = ~std::uint64_t{0}; // the EMPTY cells under the targets, read when first needed
        std::uint64_t gaining = 0;
        for (; targets; targets &= targets - 1) {
            const int t = std::countr_zero(targets);
            const std::uint64_t open = rules.grainsWithOpenSlideAcrossCentreTo(t, woken & ~gaining, here);
            if (!open) continue;
            if (deepTargets == ~std::uint64_t{0}) deepTargets = empty.window<across>(x, y - 2, z);
            if (deepTargets >> t & 1) {
                gaining |= open;
                continue;
            }
            for (std::uint64_t grains = open; grains; grains &= grains - 1) {
                const int bit = std::countr_zero(grains);
                const int dx = bit % kWindow - kReach, dz = bit / kWindow - kReach;
                const std::uint32_t from = grid.index(x + dx, y, z + dz);
                const int slide = GranularRules::offsetIndex(t % (2 * across + 1) - across - dx, t / (2 * across + 1) - across - dz);
                if (liesOnVessel(from) || !rules.needsDepth(dither, x + dx, z + dz, slide, 2)) gaining |= std::uint64_t{1} << bit;
            }
        }
        woken = gaining;
    } else {
        // In the layers above, a grain gains only when its sideways path towards the column is
        // EMPTY, and only if its slide into the column looks as deep as (x, y - layersAbove, z).
        woken &= rules.grainsWithOpenPathTowardsCentre(empty.window<kGranularReach>(x, y, z));
        if (woken) woken = deepEnoughForSlidesInto(woken, x, y, z, layersAbove);
    }
    if (woken) wakeWindow(x, y, z, woken);
}

// Near a side (windowColumnsAround), or across two words; rows outside the grid are skipped.
std::uint64_t GranularWakes::sleepingGrainsAroundSide(int x, int y, int z) const {
    const std::size_t stride = std::size_t(awake.rowWords());
    const int x0 = x - kReach, offset = x0 & 63;
    if (x0 >= 0 && (x0 >> 6) + 1 < awake.rowWords() && z >= kReach && z + kReach < awake.size().z) {
        // Across two words, away from the sides: spelled out as in sleepingGrainsAround, the next
        // word's low bits following on.
        const AwakeCells::Word* row = awake.rowWords(awake.rowOf(y, z - kReach)) + std::size_t(x0 >> 6);
        return [&]<std::size_t... r>(std::index_sequence<r...>) {
            return ((((row[r * stride].sleeping() >> offset | row[r * stride + 1].sleeping() << (64 - offset)) & kRowMask)
                     << (r * kWindow)) |
                    ...);
        }(std::make_index_sequence<kWindow>{});
    }
    std::uint64_t grains = 0;
    const WindowColumns at = windowColumnsAround(x);
    const int z0 = std::max(z - kReach, 0), z1 = std::min(z + kReach, awake.size().z - 1);
    for (int zz = z0; zz <= z1; ++zz) {
        const AwakeCells::Word* row = awake.rowWords(awake.rowOf(y, zz)) + std::size_t(at.word);
        std::uint64_t bits = row[0].sleeping() >> at.offset;
        if (at.spills) bits |= row[1].sleeping() << (64 - at.offset);
        grains |= ((bits << at.dropped) & kRowMask) << ((zz - z + kReach) * kWindow);
    }
    return grains;
}

// Sets the awake bits of the cells `woken` (window bits around (x, z) of layer y, as
// sleepingGrainsAround gives them, so each lies inside the grid) and their rows' flags.
void GranularWakes::wakeWindow(int x, int y, int z, std::uint64_t woken) const {
    const WindowColumns at = windowColumnsAround(x);
    const std::size_t layerRow = awake.rowOf(y, 0);
    while (woken) {
        const int r = std::countr_zero(woken) / kWindow; // the next row with a grain to wake
        const std::uint64_t rowBits = ((woken >> (r * kWindow)) & kRowMask) >> at.dropped;
        woken &= ~(kRowMask << (r * kWindow));
        const std::size_t row = layerRow + std::size_t(z - kReach + r);
        AwakeCells::Word* words = awake.rowWords(row) + std::size_t(at.word);
        words[0].awake |= rowBits << at.offset;
        if (at.spills) words[1].awake |= rowBits >> (64 - at.offset);
        awake.rowFlags()[row] = 1;
    }
}

// Of the grains `woken` (window bits around (x, z) in layer y) whose slide into (x, z)'s column
// is open at their level, those that (x, y - layersAbove, z) emptying can let go. The slide's
// need (how deep the column must be) is fixed per grain and slide (granular_rules.hpp), so only
// a grain whose need reaches that deep gains (one that needs less had the slide before, or lacks
// it for a cell above), and while the cell under the emptied one is taken, only one whose need
// ends there; a grain on the vessel needs one cell, so only the target (layersAbove 1) matters to
// it. The rest may gain and stay woken; what opens their slide later (the cell under the emptied
// one emptying, a layer further down for them) wakes them then.
std::uint64_t GranularWakes::deepEnoughForSlidesInto(std::uint64_t woken, int x, int y, int z, int layersAbove) const {
    // Under the emptied cell: when EMPTY too, a grain that needs more may gain as well.
    const int under = y - layersAbove - 1;
    const bool deeperEmpty = under >= 0 && empty.isEmpty(x, under, z);
    if (layersAbove == 1 && deeperEmpty) return woken;
    // By the whole cells w of each grain's threshold for its slide into the column (its need is w,
    // or w + 1 where its dither carries; GranularRules::needsDepth): it gains when its need
    // reaches the emptied cell and, unless the cell under that is EMPTY, ends there. Only the
    // grains whose need the dither decides, or which may lie on the vessel, are looked at one by one.
    std::uint64_t gaining, ifCarried = 0, unlessCarried = 0, ifOnVessel = 0;
    if (layersAbove >= 2) {
        gaining = deeperEmpty ? woken & rules.towardsCentreWithWholeAtLeast(layersAbove) : 0;
        if (!deeperEmpty) unlessCarried = woken & rules.towardsCentreWithWhole(layersAbove);
        ifCarried = woken & rules.towardsCentreWithWhole(layersAbove - 1);
    } else { // the emptied cell is the target, the one under it taken
        gaining = woken & rules.towardsCentreWithWhole(0);
        unlessCarried = woken & rules.towardsCentreWithWhole(1);
        ifOnVessel = woken & rules.towardsCentreWithWholeAtLeast(2);
    }
    auto eachGrain = [&](std::uint64_t grains, auto&& gains) {
        for (; grains; grains &= grains - 1) {
            const int bit = std::countr_zero(grains);
            const int dx = bit % kWindow - kReach, dz = bit / kWindow - kReach; // the grain, from (x, z)
            if (gains(x + dx, z + dz, GranularRules::offsetIndex(-dx, -dz))) gaining |= std::uint64_t{1} << bit;
        }
    };
    eachGrain(ifCarried, [&](int gx, int gz, int slide) { return rules.carries(dither, gx, gz, slide); });
    eachGrain(unlessCarried, [&](int gx, int gz, int slide) {
        return (layersAbove == 1 && liesOnVessel(grid.index(gx, y, gz))) || !rules.carries(dither, gx, gz, slide);
    });
    eachGrain(ifOnVessel, [&](int gx, int gz, int) { return liesOnVessel(grid.index(gx, y, gz)); });
    return gaining;
}

} // namespace sandcore
