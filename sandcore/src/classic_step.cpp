// SPDX-License-Identifier: MIT
#include "classic_step.hpp"

#include "sand_rules.hpp"
#include "sandcore/counter_random.hpp"

#include <algorithm>
#include <array>
#include <bit>

namespace sandcore {

namespace {

// The 8 slip successors of a cell away from the grid's sides, as bits 0..7 of a mask, in
// LayerNeighbourhood::forEachAround's order (dz outside, dx inside): the k-th empty one is the
// k-th set bit, exactly as chooseMove picks it.
constexpr int kSlipDx[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr int kSlipDz[8] = {-1, -1, -1, 0, 0, 1, 1, 1};

// kSetBits[mask]: number of set bits of an 8-bit mask (a table: std::popcount is a library call
// on CPUs the build does not assume to have POPCNT).
constexpr auto kSetBits = [] {
    std::array<std::uint8_t, 256> table{};
    for (int mask = 0; mask < 256; ++mask) table[std::size_t(mask)] = std::uint8_t(std::popcount(unsigned(mask)));
    return table;
}();

// kNthSetBit[mask][k]: position of the k-th set bit of mask (k < popcount(mask)).
constexpr auto kNthSetBit = [] {
    std::array<std::array<std::uint8_t, 8>, 256> table{};
    for (int mask = 0; mask < 256; ++mask) {
        int k = 0;
        for (int bit = 0; bit < 8; ++bit)
            if (mask >> bit & 1) table[std::size_t(mask)][std::size_t(k++)] = std::uint8_t(bit);
    }
    return table;
}();

} // namespace

// The hot path, kept inside the strip loop (the compiler declines to inline it unasked).
// Away from the grid's sides the 8 successors are read with no bounds tests and the slip is
// picked from a mask of the empty ones without branches; at the sides chooseMove does it. Both
// make the same choice. The grain's record is written here or fed (SweepContext::feed).
[[gnu::always_inline]] inline bool ClassicStep::visit(StripLog& log, const Row& row, int x) const {
    const int y = row.y, z = row.z;
    CellGrid& grid = context.grid;
    CellValue* cells = grid.cells().data();
    const Int3 size = awake.size();
    const auto sizeX = std::uint32_t(size.x);
    const std::uint32_t from = row.firstCell + std::uint32_t(x);
    const CellValue grain = cells[from];
    AwakeCells::Word& word = row.words[x >> 6];
    const std::uint64_t bit = std::uint64_t{1} << (x & 63);
    if (grain < 0) {
        word.occupied &= ~bit;
        return false;
    }
    const std::uint32_t straightBelow = from - grid.layerSize();
    auto random = [&] { return counterRandomFromKey(context.stepKey, std::uint64_t(context.level), from); };
    int dx = 0, dz = 0;
    if (cells[straightBelow] == kEmpty) {
        // fall
    } else if (x > 0 && x + 1 < size.x && z > 0 && z + 1 < size.z) {
        const CellValue* before = cells + (straightBelow - sizeX);
        const CellValue* middle = cells + straightBelow;
        const CellValue* behind = cells + (straightBelow + sizeX);
        const unsigned empty = unsigned(before[-1] == kEmpty) | unsigned(before[0] == kEmpty) << 1 |
                               unsigned(before[1] == kEmpty) << 2 | unsigned(middle[-1] == kEmpty) << 3 |
                               unsigned(middle[1] == kEmpty) << 4 | unsigned(behind[-1] == kEmpty) << 5 |
                               unsigned(behind[0] == kEmpty) << 6 | unsigned(behind[1] == kEmpty) << 7;
        if (!empty) return false; // cannot move: it sleeps until a cell below it empties
        const std::uint8_t pick = kNthSetBit[empty][pickBelow(random(), kSetBits[empty])];
        dx = kSlipDx[pick];
        dz = kSlipDz[pick];
    } else {
        const CellNeighbourhood here(grid, x, y, z);
        const auto target = chooseMove(here, random);
        if (!target) return false;
        dx = target->dx;
        dz = target->dz;
    }

    const std::uint32_t to = straightBelow + std::uint32_t(std::int64_t(dz) * sizeX + dx);
    cells[to] = grain;
    cells[from] = kEmpty;
    word.occupied &= ~bit;
    recordMove(context, log, {std::uint32_t(grain), to, packMove(-dx, 1, -dz), context.level});

    if (y - 1 > 0 || bottomIsOutlet) awake.wakeAt(x + dx, y - 1, z + dz); // it may move on next step
    // The cell it left is free: the grains that may fall or slip into it wake.
    awake.wakePredecessorsOf(x, y, z);
    outlet.emptied(x, y, z);
    return true;
}

// The first awake cell of row z of layer y, and the cell below it, are usually not in the cache
// yet (a visit reads the layer below, not the next row of its own): asking for them one row
// ahead overlaps those misses with this row's visits. A hint only; classic moves never wake
// cells of their own layer, so the row's awake bits are already final.
void ClassicStep::prefetchFirstAwake(int y, int z) const {
    const AwakeCells::Word* words = awake.rowWords(awake.rowOf(y, z));
    for (int w = 0; w < awake.rowWords(); ++w) {
        if (!words[w].awake) continue;
        const CellGrid& grid = context.grid;
        const CellValue* cell = grid.cells().data() + grid.index(w * 64 + std::countr_zero(words[w].awake), y, z);
        __builtin_prefetch(cell);
        __builtin_prefetch(cell - grid.layerSize());
        return;
    }
}

SweepResult ClassicStep::sweepStrip(int y, int strip, StripLog& log) const {
    // On a copy held in a local, the visits' references stay in registers, where those of *this
    // would be loaded again after each store of a byte (a row's flag may alias anything).
    const ClassicStep step = *this;
    return step.sweepRows(y, strip, log);
}

// Each word's awake bits are taken at once: classic moves only wake cells in the layers above
// and below, never in this row. A strip none of whose rows is awake is skipped whole.
[[gnu::always_inline]] inline SweepResult ClassicStep::sweepRows(int y, int strip, StripLog& log) const {
    SweepResult totals;
    const bool sleeping = context.sleeping;
    const int zEnd = std::min((strip + 1) * kStripRows, awake.size().z);
    if (sleeping && !awake.anyRowAwake(y, strip * kStripRows, zEnd)) return totals;
    std::uint8_t* rowAwake = awake.rowFlags();
    for (int z = strip * kStripRows; z < zEnd; ++z) {
        const std::size_t row = awake.rowOf(y, z);
        if (sleeping && !rowAwake[row]) continue;
        rowAwake[row] = 0;
        // Without sleeping, every cell of the row is visited as if awake.
        const Row at{y, z, context.grid.index(0, y, z), awake.rowWords(row)};
        if (sleeping && z + 1 < zEnd && rowAwake[row + 1]) prefetchFirstAwake(y, z + 1);
        for (int w = 0; w < awake.rowWords(); ++w) {
            std::uint64_t bits = sleeping ? at.words[w].awake : awake.wholeWord(w);
            at.words[w].awake = 0;
            for (; bits; bits &= bits - 1) {
                ++totals.visited;
                totals.moves += visit(log, at, w * 64 + std::countr_zero(bits)) ? 1 : 0;
            }
        }
        if (context.feed) context.feed->publishSome();
    }
    return totals;
}

} // namespace sandcore
