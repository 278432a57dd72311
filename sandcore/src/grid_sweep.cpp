// SPDX-License-Identifier: MIT
#include "grid_sweep.hpp"

#include "empty_cells.hpp"
#include "granular_rules.hpp"
#include "sand_rules.hpp"
#include "sandcore/worker_pool.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cstring>
#include <span>
#include <utility>

namespace sandcore {

namespace {
// Below this many awake rows in a layer, handing strips to other threads costs more than it saves.
constexpr int kMinAwakeRowsForThreads = 24;

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

GridSweep::GridSweep(Int3 gridSize, bool bottomIsOutlet)
    : size_(gridSize), bottomIsOutlet_(bottomIsOutlet), dither_(0, stream()), rowWords_((gridSize.x + 63) / 64) {
    const std::size_t rows = std::size_t(gridSize.y) * std::size_t(gridSize.z);
    words_.assign(rows * std::size_t(rowWords_), RowWord{});
    rowAwake_.assign(rows, 0);
    logs_.resize(std::size_t((gridSize.z + kStripRows - 1) / kStripRows));
}

void GridSweep::setGranular(const GranularRules* granular) {
    granular_ = granular;
    forgetSleepingFalls(); // the scene stops every fall when the rules change
    motion_.assign(granular ? words_.size() : 0, MotionWord{});
    if (granular) empty_.resize(size_); // every cell taken until readEmptyCells
    layout_ = granular ? LayoutBits(size_) : LayoutBits();
}

void GridSweep::setSeed(std::uint64_t seed) { dither_ = ThresholdDither(seed, stream()); }

void GridSweep::readEmptyCells(const CellGrid& grid) {
    if (!granular_) return;
    empty_.read(grid);
    layout_ = LayoutBits(grid);
}

bool GridSweep::emptyCellsMatch(const CellGrid& grid) const {
    return !granular_ || (empty_.matches(grid) && layout_.matches(grid));
}

void GridSweep::grainEntered(int x, int y, int z) {
    if (granular_) {
        empty_.setEmpty(x, y, z, false);
        // A gatherer or rider asleep below now carries it; a gatherer asleep above has lost its
        // EMPTY cell below.
        if (y - 1 >= 1) wakeIfInMotion(x, y - 1, z);
        if (y + 1 < size_.y) wakeIfInMotion(x, y + 1, z);
    }
    if (y > 0 || bottomIsOutlet_) wakeAt(x, y, z);
}

// A grain in motion that is not awake sleeps in its fall (grid_sweep.hpp) or rides a moving grain
// that wakes it when its speed changes. Waking either is exact (R5), and an edit next to a
// sleeping gatherer or rider must: what its skipped visits would read has changed.
void GridSweep::wakeIfInMotion(int x, int y, int z) {
    const std::size_t row = std::size_t(y) * std::size_t(size_.z) + std::size_t(z);
    if (motion_[row * std::size_t(rowWords_) + std::size_t(x >> 6)].inMotion >> (x & 63) & 1) wakeAt(x, y, z);
}

void GridSweep::forgetSleepingFalls() {
    for (std::vector<StripLog::SleeperCell>& cells : timers_) cells.clear();
    for (StripLog& log : logs_) {
        log.sleepers.clear();
        log.sleepsEnded = 0;
    }
    fallsAsleep_ = 0;
}

Int3 GridSweep::coordinateOf(std::uint32_t cell) const {
    const std::uint32_t x = cell % std::uint32_t(size_.x), rest = cell / std::uint32_t(size_.x);
    return {int(x), int(rest / std::uint32_t(size_.z)), int(rest % std::uint32_t(size_.z))};
}

void GridSweep::grainEntered(std::uint32_t cell) {
    const Int3 c = coordinateOf(cell);
    grainEntered(c.x, c.y, c.z);
}

void GridSweep::cellBlocked(std::uint32_t cell) {
    if (!granular_) return;
    const Int3 c = coordinateOf(cell);
    empty_.setEmpty(c.x, c.y, c.z, false);
    layout_.setOpen(cell, false);
    if (c.y + 1 < size_.y) wakeIfInMotion(c.x, c.y + 1, c.z); // its EMPTY cell below is gone
}

void GridSweep::markInMotion(int x, int y, int z) {
    const std::size_t row = std::size_t(y) * std::size_t(size_.z) + std::size_t(z);
    motion_[row * std::size_t(rowWords_) + std::size_t(x >> 6)].inMotion |= std::uint64_t{1} << (x & 63);
}

void GridSweep::wakeAt(int x, int y, int z) {
    const std::size_t row = std::size_t(y) * std::size_t(size_.z) + std::size_t(z);
    const std::size_t word = row * std::size_t(rowWords_) + std::size_t(x >> 6);
    const std::uint64_t bit = std::uint64_t{1} << (x & 63);
    words_[word].awake |= bit;
    words_[word].occupied |= bit; // every grain that enters a cell is woken there
    rowAwake_[row] = 1;
}

inline void GridSweep::wakeIfOccupied(int x, int y, int z) {
    const std::size_t row = std::size_t(y) * std::size_t(size_.z) + std::size_t(z);
    RowWord& word = words_[row * std::size_t(rowWords_) + std::size_t(x >> 6)];
    const std::uint64_t bit = word.occupied & std::uint64_t{1} << (x & 63);
    word.awake |= bit;
    if (bit) rowAwake_[row] = 1;
}

void GridSweep::wake(std::uint32_t cell) {
    const Int3 c = coordinateOf(cell);
    if (c.y == 0 && !bottomIsOutlet_) return; // the floor has nothing below it: never visited
    wakeAt(c.x, c.y, c.z);
}

// Sets the awake bits x0..x1 (at most 63 apart) of one row that may hold a grain, with one or
// two word operations. EMPTY and INVALID cells stay asleep: that is exact, as in
// wakeGrainsAround, since a grain that enters one of them later is woken by its move.
inline void GridSweep::wakeSpan(std::size_t row, int x0, int x1) {
    RowWord* words = words_.data() + row * std::size_t(rowWords_);
    const int first = x0 >> 6, last = x1 >> 6;
    std::uint64_t woken;
    if (first == last) {
        woken = (((std::uint64_t{2} << (x1 - x0)) - 1) << (x0 & 63)) & words[first].occupied;
        words[first].awake |= woken;
    } else {
        const std::uint64_t low = (~std::uint64_t{0} << (x0 & 63)) & words[first].occupied;
        const std::uint64_t high = ((std::uint64_t{2} << (x1 & 63)) - 1) & words[last].occupied;
        words[first].awake |= low;
        words[last].awake |= high;
        woken = low | high;
    }
    if (woken) rowAwake_[row] = 1;
}

inline void GridSweep::wakePredecessorsOf(int x, int y, int z) {
    const Int3 size = size_;
    if (y + 1 >= size.y) return;
    const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, size.x - 1);
    const int z0 = std::max(z - 1, 0), z1 = std::min(z + 1, size.z - 1);
    const std::size_t layerRow = std::size_t(y + 1) * std::size_t(size.z);
    for (int zz = z0; zz <= z1; ++zz) wakeSpan(layerRow + std::size_t(zz), x0, x1);
}

// Strips of one phase run on threads side by side. A granular visit reads and writes cells and
// bits up to kGranularReach rows from its own (the 7x7 windows of its slides and wakes); a word of
// bits holds 64 cells of one row, so two strips must never come within that of each other's rows.
static_assert(kStripRows >= 2 * kGranularReach + 1, "strips of one phase would share rows");

namespace {
constexpr int kGranularWindow = 2 * kGranularReach + 1;

} // namespace

// Wakes the grains of layer y at the cells of `mask` (GranularRules::wakeMask) around (x, z) that
// may gain. In the emptied cell's own layer (layersAbove 0): a grain within 3 columns when one of
// its slides crosses (x, z) on a path EMPTY all along to an EMPTY cell of the layer below, deep
// enough for it (or the grain lies on the vessel). Any other grain gains nothing from (x, z) now,
// and whatever later opens such a slide (a cell of the path or the target emptying, the column
// below deepening) wakes it then. In the layers above,
// those whose sideways path towards (x, z)'s column is EMPTY at their level (the only one of their
// options that the emptied cell can widen) and whose slide looks as deep as the emptied cell
// (deepEnoughForSlidesInto); the column above it is EMPTY up to layer y (wakeForGranular). Each
// row's 7 bits are shifted into place and ANDed with the occupied bits, as wakeSpan does, so EMPTY
// and INVALID cells stay asleep. That is exact: a grain that enters one of those cells later is
// woken by its move. In the layers above, this runs before their turn in the step; in the
// emptied cell's own layer, at the sweep's end (wakeAroundCellsLeftEarlier), for the next step.
inline void GridSweep::wakeGrainsAround(const CellGrid& grid, int x, int y, int z, int layersAbove) {
    // The grains in the window not yet awake: waking an awake one changes nothing.
    const std::uint64_t sleeping = granular_->wakeMask(layersAbove) & sleepingGrainsAround(x, y, z);
    // Every grain around is awake already, or none is there: a third of the calls in the
    // million-grain drain, most of them 3 or 4 layers above the emptied cell, where (at the
    // default angle) the mask holds only cells of the window's outer rows and columns. Inline,
    // with the rest out of line, those calls cost no call (2% of the granular step).
    if (sleeping) wakeSleepingGrainsAround(grid, x, y, z, layersAbove, sleeping);
}

void GridSweep::wakeSleepingGrainsAround(const CellGrid& grid, int x, int y, int z, int layersAbove, std::uint64_t woken) {
    if (layersAbove == 0) {
        // In (x, z)'s layer a grain gains only through a slide whose path crosses (x, z), is EMPTY
        // all along and ends over an EMPTY cell of the layer below; a slide that needs its column
        // two cells deep also needs the cell under its target EMPTY, unless the grain lies on the
        // vessel, where one cell is enough. Whatever opens such a slide later (a cell of the path
        // or the target emptying, the column deepening) wakes the grain then. Such slides end in
        // the 5x5 columns around (x, z): target by target, the grains whose path to it is open
        // (GranularRules::grainsWithOpenSlideAcrossCentreTo), over the EMPTY targets into which
        // some of the grains slide across (x, z) (skipping the others took about 2% off the
        // granular step). Outside the grid the windows read as taken; under layer 1 the column is
        // never deep enough.
        constexpr int across = GranularRules::kAcrossReach;
        auto targets = std::uint32_t(empty_.window<across>(x, y - 1, z)) & granular_->targetsAcrossCentreOf(woken);
        if (!targets) return;
        const std::uint64_t here = empty_.window<kGranularReach>(x, y, z);
        std::uint64_t deepTargets = ~std::uint64_t{0}; // the EMPTY cells under the targets, read when first needed
        std::uint64_t gaining = 0;
        for (; targets; targets &= targets - 1) {
            const int t = __builtin_ctz(targets);
            const std::uint64_t open = granular_->grainsWithOpenSlideAcrossCentreTo(t, woken & ~gaining, here);
            if (!open) continue;
            if (deepTargets == ~std::uint64_t{0}) deepTargets = empty_.window<across>(x, y - 2, z);
            if (deepTargets >> t & 1) {
                gaining |= open;
                continue;
            }
            for (std::uint64_t grains = open; grains; grains &= grains - 1) {
                const int bit = __builtin_ctzll(grains);
                const int dx = bit % kGranularWindow - kGranularReach, dz = bit / kGranularWindow - kGranularReach;
                const std::uint32_t from = grid.index(x + dx, y, z + dz);
                const int slide = GranularRules::offsetIndex(t % (2 * across + 1) - across - dx, t / (2 * across + 1) - across - dz);
                if (liesOnVessel(grid, from) || !granular_->needsDepth(dither_, x + dx, z + dz, slide, 2))
                    gaining |= std::uint64_t{1} << bit;
            }
        }
        woken = gaining;
    } else {
        // In the layers above, a grain gains only when its sideways path towards the column is
        // EMPTY, and only if its slide into the column looks as deep as (x, y - layersAbove, z).
        woken &= granular_->grainsWithOpenPathTowardsCentre(empty_.window<kGranularReach>(x, y, z));
        if (woken) woken = deepEnoughForSlidesInto(grid, woken, x, y, z, layersAbove);
    }
    if (woken) wakeWindow(x, y, z, woken);
}

// Where the 7 cells x - 3 .. x + 3 of a row lie in its words of bits: columns left of 0 are
// dropped (shifted out), those right of the grid meet occupied bits that are never set.
GridSweep::WindowColumns GridSweep::windowColumnsAround(int x) const {
    const int first = std::max(x - kGranularReach, 0), dropped = first - (x - kGranularReach);
    const int word = first >> 6, offset = first & 63;
    return {word, offset, dropped, offset + kGranularWindow - dropped > 64 && word + 1 < rowWords_};
}

// The 7x7 cells around (x, z) of layer y (bit (dz + 3) * 7 + (dx + 3)) that hold a grain and are
// not awake. Away from the grid's sides, where the 7 cells of a row lie in one word, a row is a
// load and two shifts.
inline std::uint64_t GridSweep::sleepingGrainsAround(int x, int y, int z) const {
    constexpr int reach = kGranularReach, window = kGranularWindow;
    constexpr std::uint64_t rowMask = (std::uint64_t{1} << window) - 1;
    const int x0 = x - reach, offset = x0 & 63;
    const std::size_t stride = std::size_t(rowWords_);
    if (x0 >= 0 && offset + window <= 64 && z >= reach && z + reach < size_.z) {
        const RowWord* row = words_.data() + (std::size_t(y) * std::size_t(size_.z) + std::size_t(z - reach)) * stride +
                             std::size_t(x0 >> 6);
        // Spelled out row by row: each row's place in the window is then a constant.
        return [&]<std::size_t... r>(std::index_sequence<r...>) {
            return (((row[r * stride].sleeping() >> offset & rowMask) << (r * window)) | ...);
        }(std::make_index_sequence<window>{});
    }
    return sleepingGrainsAroundSide(x, y, z);
}

// Near a side (windowColumnsAround), or across two words; rows outside the grid are skipped.
std::uint64_t GridSweep::sleepingGrainsAroundSide(int x, int y, int z) const {
    constexpr int reach = kGranularReach, window = kGranularWindow;
    constexpr std::uint64_t rowMask = (std::uint64_t{1} << window) - 1;
    const std::size_t stride = std::size_t(rowWords_);
    const int x0 = x - reach, offset = x0 & 63;
    if (x0 >= 0 && (x0 >> 6) + 1 < rowWords_ && z >= reach && z + reach < size_.z) {
        // Across two words, away from the sides (one window in ten): spelled out as above, the
        // next word's low bits following on.
        const RowWord* row = words_.data() + (std::size_t(y) * std::size_t(size_.z) + std::size_t(z - reach)) * stride +
                             std::size_t(x0 >> 6);
        return [&]<std::size_t... r>(std::index_sequence<r...>) {
            return ((((row[r * stride].sleeping() >> offset | row[r * stride + 1].sleeping() << (64 - offset)) & rowMask)
                     << (r * window)) |
                    ...);
        }(std::make_index_sequence<window>{});
    }
    std::uint64_t grains = 0;
    const WindowColumns at = windowColumnsAround(x);
    const int z0 = std::max(z - reach, 0), z1 = std::min(z + reach, size_.z - 1);
    for (int zz = z0; zz <= z1; ++zz) {
        const RowWord* row = words_.data() + (std::size_t(y) * std::size_t(size_.z) + std::size_t(zz)) * stride + std::size_t(at.word);
        std::uint64_t bits = row[0].sleeping() >> at.offset;
        if (at.spills) bits |= row[1].sleeping() << (64 - at.offset);
        grains |= ((bits << at.dropped) & rowMask) << ((zz - z + reach) * window);
    }
    return grains;
}

// Sets the awake bits of the cells `woken` (window bits around (x, z) of layer y, as
// sleepingGrainsAround gives them, so each lies inside the grid) and their rows' flags.
void GridSweep::wakeWindow(int x, int y, int z, std::uint64_t woken) {
    constexpr int reach = kGranularReach, window = kGranularWindow;
    constexpr std::uint64_t rowMask = (std::uint64_t{1} << window) - 1;
    const WindowColumns at = windowColumnsAround(x);
    const std::size_t layerRow = std::size_t(y) * std::size_t(size_.z);
    while (woken) {
        const int r = __builtin_ctzll(woken) / window; // the next row with a grain to wake
        const std::uint64_t rowBits = ((woken >> (r * window)) & rowMask) >> at.dropped;
        woken &= ~(rowMask << (r * window));
        const std::size_t row = layerRow + std::size_t(z - reach + r);
        RowWord* words = words_.data() + row * std::size_t(rowWords_) + std::size_t(at.word);
        words[0].awake |= rowBits << at.offset;
        if (at.spills) words[1].awake |= rowBits >> (64 - at.offset);
        rowAwake_[row] = 1;
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
std::uint64_t GridSweep::deepEnoughForSlidesInto(const CellGrid& grid, std::uint64_t woken, int x, int y, int z,
                                                 int layersAbove) const {
    // Under the emptied cell: when EMPTY too, a grain that needs more may gain as well.
    const int under = y - layersAbove - 1;
    const bool deeperEmpty = under >= 0 && empty_.isEmpty(x, under, z);
    if (layersAbove == 1 && deeperEmpty) return woken;
    // By the whole cells w of each grain's threshold for its slide into the column (its need is w,
    // or w + 1 where its dither carries; GranularRules::needsDepth): it gains when its need
    // reaches the emptied cell and, unless the cell under that is EMPTY, ends there; on the vessel
    // a grain needs one cell, so only the target (layersAbove 1) can matter to it. Only the grains
    // whose need the dither decides, or which may lie on the vessel, are looked at one by one.
    const GranularRules& rules = *granular_;
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
    constexpr int reach = kGranularReach;
    auto eachGrain = [&](std::uint64_t grains, auto&& gains) {
        for (; grains; grains &= grains - 1) {
            const int bit = __builtin_ctzll(grains);
            const int dx = bit % kGranularWindow - reach, dz = bit / kGranularWindow - reach; // the grain, from (x, z)
            if (gains(x + dx, z + dz, GranularRules::offsetIndex(-dx, -dz))) gaining |= std::uint64_t{1} << bit;
        }
    };
    eachGrain(ifCarried, [&](int gx, int gz, int slide) { return rules.carries(dither_, gx, gz, slide); });
    eachGrain(unlessCarried, [&](int gx, int gz, int slide) {
        return (layersAbove == 1 && liesOnVessel(grid, grid.index(gx, y, gz))) || !rules.carries(dither_, gx, gz, slide);
    });
    eachGrain(ifOnVessel, [&](int gx, int gz, int) { return liesOnVessel(grid, grid.index(gx, y, gz)); });
    return gaining;
}

// The grains whose granular options an EMPTY (x, y, z) can widen (granular_rules.hpp says what a
// grain reads): in layer y, those within 3 columns whose sideways path may cross it; above it,
// the grain right above, which may now fall; and in each layer up to maxDrop above, those whose
// slide may now end in this column or reach further down it. A slide's path at the grain's own
// level includes the cell above its target, and its look down the column needs every cell
// between EMPTY: so while the column above (x, y, z) is EMPTY each layer's window is woken, and
// the first cell of it that is not EMPTY ends the search (only the grain in it, when it lies right
// above (x, y, z), can gain: it may fall).
void GridSweep::wakeForGranular(const CellGrid& grid, int x, int y, int z) {
    if (y > 0) wakeGrainsAround(grid, x, y, z, 0); // layer 0 only falls or transitions
    wakeLayersAbove(grid, x, y, z);
}

// Inlined into the visit that emptied the cell: called for every move (about 1% of the granular step).
[[gnu::always_inline]] inline void GridSweep::wakeLayersAbove(const CellGrid& grid, int x, int y, int z) {
    const int top = std::min(y + granular_->maxDrop(), size_.y - 1);
    for (int layer = y + 1; layer <= top; ++layer) {
        if (!empty_.isEmpty(x, layer, z)) { // the kept bits: a column's cells lie a layer apart
            // A grain right above may fall. The cell holds a grain or the vessel, and its occupied
            // bit tells which without reading it: never clear under a grain (but in a column asleep
            // in its fall, whose woken grain wakes the one above it itself), never set on the
            // vessel but where an edit left it stale (a cell woken so is visited and left).
            if (layer == y + 1) wakeIfOccupied(x, layer, z);
            break;
        }
        wakeGrainsAround(grid, x, layer, z, layer - y);
    }
}

void GridSweep::wakeAroundEmptied(const CellGrid& grid, int x, int y, int z) {
    if (granular_) {
        wakeAroundEmptiedBy<true>(grid, x, y, z);
        if (y + 1 < size_.y) wakeIfInMotion(x, y + 1, z); // a rider asleep there lost its support
    } else {
        wakeAroundEmptiedBy<false>(grid, x, y, z);
    }
}

template <bool Granular> inline void GridSweep::wakeAroundEmptiedBy(const CellGrid& grid, int x, int y, int z) {
    if constexpr (Granular) {
        empty_.setEmpty(x, y, z, true);
        layout_.setOpen(grid.index(x, y, z), true); // an obstacle's cell may open so (Scene::clearObstacles)
        wakeForGranular(grid, x, y, z);
    } else {
        wakePredecessorsOf(x, y, z);
    }
    wakeOutletAbove(x, y, z);
}

inline void GridSweep::wakeOutletAbove(int x, int y, int z) {
    if (!above_ || y != size_.y - 1) return;
    if (deferWakesAbove_)
        deferredWakesAbove_.push_back(std::uint32_t(x) + std::uint32_t(size_.x) * std::uint32_t(z));
    else
        above_->wakeAt(x, 0, z);
}

// A layer's paths see it as its turn began (granular_rules.hpp), so the cells its grains leave
// become EMPTY in the kept bits only when the turn ends, for the layers above and the next step.
// Their own-layer wakes (the grains of the layer that may slide across them) matter only for the
// next step, and only if the cell is still EMPTY then; after a layer's turn its cells and those
// below can only fill (grains of later turns land there), never empty. So they wait until the
// grid's sweep ends (wakeAroundCellsLeftEarlier): a cell EMPTY then is woken around as
// wakeForGranular does, reading the windows as the step leaves them (what the next step's turns
// below empty before this layer's turn wakes this layer itself); one filled again wakes nobody,
// as nobody can gain from it (two in three are filled by the end of the next turn).
// Done together at the end rather than after the next turn, the same wakes took about 1% off the
// granular step of the million-grain drain.
void GridSweep::endGranularTurn(int y) {
    for (const int strip : turnStrips_) {
        StripLog& log = logs_[std::size_t(strip)];
        for (const StripLog::Column column : log.left) {
            empty_.setEmpty(column.x, y, column.z, true);
            leftEarlier_.push_back({column.x, y, column.z});
        }
        log.left.clear();
    }
}

void GridSweep::wakeAroundCellsLeftEarlier(const CellGrid& grid) {
    for (const Int3& c : leftEarlier_)
        if (empty_.isEmpty(c.x, c.y, c.z)) wakeGrainsAround(grid, c.x, c.y, c.z, 0);
    leftEarlier_.clear();
}

void GridSweep::applyDeferredWakes() {
    for (std::uint32_t column : deferredWakesAbove_)
        above_->wakeAt(int(column % std::uint32_t(size_.x)), 0, int(column / std::uint32_t(size_.x)));
    deferredWakesAbove_.clear();
}

void GridSweep::takeLoggedMoves(std::vector<GrainMove>& moved) {
    for (StripLog& log : logs_) {
        moved.insert(moved.end(), log.moved.begin(), log.moved.end());
        log.moved.clear();
    }
}

std::int64_t GridSweep::awakeRowCount() const {
    // The flags are 0 or 1: eight at a time, a multiply sums a word's bytes into its top byte
    // (std::count takes a byte at a time, about 9 microseconds a step in the million-grain drain).
    const std::size_t rows = rowAwake_.size(), whole = rows / 8 * 8;
    std::int64_t count = 0;
    for (std::size_t at = 0; at < whole; at += 8) {
        std::uint64_t flags;
        std::memcpy(&flags, rowAwake_.data() + at, 8);
        count += std::int64_t((flags * 0x0101010101010101ull) >> 56);
    }
    return count + std::count(rowAwake_.begin() + std::ptrdiff_t(whole), rowAwake_.end(), std::uint8_t{1});
}

void GridSweep::wakeEveryGrain(const CellGrid& grid) {
    const auto cells = grid.cells();
    for (std::uint32_t n = 0; n < cells.size(); ++n)
        if (cells[n] >= 0) wake(n);
}

void GridSweep::clear() {
    std::fill(words_.begin(), words_.end(), RowWord{});
    std::fill(motion_.begin(), motion_.end(), MotionWord{});
    for (StripLog& log : logs_) {
        log.moved.clear();
        log.carried = 0;
    }
    std::fill(rowAwake_.begin(), rowAwake_.end(), 0);
    forgetSleepingFalls(); // the caller sets every fall state (restore, reset)
}

std::uint64_t GridSweep::wholeWord(int w) const {
    const int cellsInWord = std::min(size_.x - w * 64, 64);
    return cellsInWord == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << cellsInWord) - 1;
}

void GridSweep::clearRow(std::uint32_t row) {
    if (!rowAwake_[row]) return;
    RowWord* words = words_.data() + std::size_t(row) * std::size_t(rowWords_);
    for (int w = 0; w < rowWords_; ++w) words[w].awake = 0;
    rowAwake_[row] = 0;
}

int GridSweep::awakeRowsInLayer(int y) const {
    const auto first = rowAwake_.begin() + std::ptrdiff_t(std::size_t(y) * std::size_t(size_.z));
    return int(std::count(first, first + size_.z, std::uint8_t{1}));
}

// The hot path: `inline` keeps it inside the strip loop, which the compiler otherwise declines
// at -O3 (a call per visited cell costs about a tenth of a step). The thesis's rules only: the
// granular ones go through visitGranular, chosen once per sweep, so classic pays no test per grain.
// Away from the grid's sides the 8 successors are read with no bounds tests and the slip is
// picked from a mask of the empty ones without branches; at the sides chooseMove does it. Both
// make the same choice. The grain's record is written here or fed (SweepContext::feed).
inline bool GridSweep::visitCell(const SweepContext& context, StripLog& log, int x, int y, int z) {
    CellValue* cells = context.grid.cells().data();
    const auto sizeX = std::uint32_t(size_.x);
    const std::uint32_t layer = context.grid.layerSize();
    const std::uint32_t from = context.grid.index(x, y, z);
    const CellValue grain = cells[from];
    const std::size_t word = (std::size_t(y) * std::size_t(size_.z) + std::size_t(z)) * std::size_t(rowWords_) + std::size_t(x >> 6);
    const std::uint64_t bit = std::uint64_t{1} << (x & 63);
    if (grain < 0) {
        words_[word].occupied &= ~bit;
        return false;
    }
    const std::uint32_t straightBelow = from - layer;
    auto random = [&] { return counterRandomFromKey(context.stepKey, std::uint64_t(context.level), from); };
    int dx = 0, dz = 0;
    if (cells[straightBelow] == kEmpty) {
        // fall
    } else if (x > 0 && x + 1 < size_.x && z > 0 && z + 1 < size_.z) {
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
        const CellNeighbourhood here(context.grid, x, y, z);
        const auto target = chooseMove(here, random);
        if (!target) return false;
        dx = target->dx;
        dz = target->dz;
    }

    const std::uint32_t to = straightBelow + std::uint32_t(std::int64_t(dz) * sizeX + dx);
    cells[to] = grain;
    cells[from] = kEmpty;
    words_[word].occupied &= ~bit;
    record(context, log, {std::uint32_t(grain), to, packMove(-dx, 1, -dz), context.level});

    if (y - 1 > 0 || bottomIsOutlet_) wakeAt(x + dx, y - 1, z + dz); // it may move on next step
    wakeAroundEmptiedBy<false>(context.grid, x, y, z);             // the cell it left is free
    return true;
}

// A move's grain record: written and listed here, or fed to the thread that writes the records.
inline void GridSweep::record(const SweepContext& context, StripLog& log, const GrainMove& move) {
    if (context.feed) {
        context.feed->push(move);
        return;
    }
    context.grains.recordMove(move.grain, move.cell, move.cameFrom, context.step);
    (context.movedList ? *context.movedList : log.moved).push_back(move);
}

// What every granular visit of a strip reads, read once per strip: held in locals, the values
// stay in registers, where members and the context would be loaded again after each store.
struct GridSweep::GranularStrip {
    CellGrid& grid;
    CellValue* cells;
    std::span<FallState> falls;
    const ThresholdDither& dither; // GridSweep::dither_
    std::uint64_t stepKey, stream; // SweepContext::stepKey
    std::size_t layerWords; // words of awake and in-motion bits per layer
    RowWord* words;
    MotionWord* motion;
    std::uint8_t* rowAwake;
    int sizeY, sizeZ;
};

// row: y * sizeZ + z; rowStart: the index of cell (0, y, z). The strip loop has both.
inline GranularOutcome::Kind GridSweep::visitGranular(const SweepContext& context, const GranularStrip& strip, StripLog& log,
                                                      int x, int y, int z, std::uint32_t row, std::uint32_t rowStart,
                                                      bool mayBeMoving, bool& stopped) {
    // The occupied bits are kept as the classic visit keeps them, so the granular wakes can AND
    // with them instead of reading cells.
    const std::size_t word = std::size_t(row) * std::size_t(rowWords_) + std::size_t(x >> 6);
    const std::uint64_t bit = std::uint64_t{1} << (x & 63);
    const std::uint32_t from = rowStart + std::uint32_t(x);
    const CellValue* cells = strip.cells;
    RowWord* words = strip.words;
    MotionWord* motion = strip.motion;
    if (cells[from] < 0) {
        words[word].occupied &= ~bit;
        return GranularOutcome::Resting;
    }
    // A sleeping gatherer or rider wakes: its state as after the step before this one. Whatever
    // it does, the column that slept on it (whose occupied bits are clear) must follow.
    bool wasAsleep = false;
    if (mayBeMoving) {
        FallState& own = strip.falls[std::size_t(cells[from])];
        if (own.gatheringSince) {
            wasAsleep = true;
            own = granular_->caughtUp(own, context.step - 1);
            ++log.sleepsEnded;
        }
    }
    // The grain's own bit comes with the queue (StripLog::Cell); the grain below is in the same
    // column of the layer below: the same bit, one layer's words back.
    const MotionHints hints{mayBeMoving, (motion[word - strip.layerWords].inMotion & bit) != 0};
    // A grain that came to rest on a sleeping gatherer or rider (in the last step; in this one it
    // rides it, reading its state caught up) wakes it for the next step, as the grain carrying
    // the column must carry this one too. The layer below has had its turn. (Woken here, where
    // the state below is read anyway, rather than by every move, which would read the cell under
    // the one it entered.)
    if (hints.below) {
        const CellValue below = cells[from - strip.grid.layerSize()];
        if (below >= 0 && strip.falls[std::size_t(below)].gatheringSince) {
            words[word - strip.layerWords].awake |= bit;
            words[word - strip.layerWords].occupied |= bit;
            strip.rowAwake[row - std::uint32_t(strip.sizeZ)] = 1;
        }
    }
    const GranularOutcome outcome = granular_->visit(strip.grid, empty_, strip.falls, strip.dither, strip.stepKey, strip.stream,
                                                     bottomIsOutlet_, x, y, z, from, context.step, hints);
    // The bit follows the grain's state: cleared where it was, set where it is when in motion.
    if (outcome.kind == GranularOutcome::Moved) {
        if (hints.grain) motion[word].inMotion &= ~bit;
        if (outcome.inMotion) markInMotion(outcome.to.x, outcome.to.y, outcome.to.z);
    } else if (outcome.inMotion != hints.grain) {
        motion[word].inMotion ^= bit;
    }
    if (outcome.kind == GranularOutcome::Waiting || outcome.stopped) {
        std::uint64_t asleepUntil = 0; // the step its timer wakes it, when it sleeps
        if (outcome.kind == GranularOutcome::Waiting) { // in motion: visited again next step, or asleep
            asleepUntil = fallAsleepGathering(context, strip, log, x, row, from);
            if (asleepUntil) {
                // The wakes of cells emptied nearby pass it by: nothing they change is read by
                // its visit. Its timer, or a grain arriving on it, sets the bit again.
                words[word].occupied &= ~bit;
            } else {
                words[word].occupied |= bit;
                words[word].awake |= bit;
                strip.rowAwake[row] = 1;
            }
        }
        // A grain that rests on this one follows it while it moves (granular_rules.hpp): its
        // speed changed without a cell emptying, so the grain above must look again. While this
        // one moves, the grains resting on it ride (carryRiders); when it stops (or gathers at a
        // speed of 0, without gravity), the grain above is woken. The occupied bit says whether
        // the cell above may hold one: it is never clear under a grain (but in a column that
        // slept in its fall, hence the look above whenever this grain slept), and reading it
        // spares a cache miss on the cell (an EMPTY cell woken is visited and left; 7 in 10
        // grains in motion, most in the stream, carry none: asking the bit before walking the
        // column took 2.5% off the granular step).
        if (y + 1 < strip.sizeY && ((words[word + strip.layerWords].occupied & bit) || wasAsleep)) {
            const std::uint32_t speed =
                outcome.kind == GranularOutcome::Waiting ? strip.falls[std::size_t(cells[from])].speed : 0;
            if (speed > 0) {
                const int carried = carryRiders(context, strip, log, x, y, z, from, speed, asleepUntil);
                log.carried += carried;
                log.speedChanges += carried; // each one's speed or fraction changed
            } else {
                words[word + strip.layerWords].awake |= bit;
                words[word + strip.layerWords].occupied |= bit; // a rider that slept had it cleared
                strip.rowAwake[row + std::uint32_t(strip.sizeZ)] = 1;
            }
        }
    }
    stopped = outcome.stopped;
    if (outcome.kind != GranularOutcome::Moved) return outcome.kind;
    words[word].occupied &= ~bit; // every move goes down at least a layer: the cell it left is EMPTY
    const Int3 to = outcome.to;
    const std::uint32_t toCell = strip.grid.index(to.x, to.y, to.z);
    empty_.setEmpty(to.x, to.y, to.z, false); // the cell it entered; the one it left: at the turn's end
    record(context, log, {std::uint32_t(cells[toCell]), toCell, outcome.cameFrom, context.level});
    if (to.y > 0 || bottomIsOutlet_) wakeAt(to.x, to.y, to.z); // it may move on next step
    // The cell it left is free: the layers above may use it in this step; its own layer in the
    // next (endGranularTurn).
    log.left.push_back({x, z});
    if (wasAsleep && y + 1 < strip.sizeY) wakeAt(x, y + 1, z); // a rider that slept on it, unseen by the wakes
    wakeLayersAbove(strip.grid, x, y, z);
    wakeOutletAbove(x, y, z);
    return GranularOutcome::Moved;
}

// After a visit in which the grain in cell `from` (x, y, z) fell without reaching its next cell:
// puts it to sleep until the step its fall reaches that cell, when the cell below is EMPTY (the
// header says why nothing else can change meanwhile). The column resting on it sleeps with it
// (carryRiders). Not in a full sweep, which visits every cell. Returns the step its timer wakes
// it, or 0 when it stays awake.
inline std::uint64_t GridSweep::fallAsleepGathering(const SweepContext& context, const GranularStrip& strip, StripLog& log,
                                                    int x, std::uint32_t row, std::uint32_t from) {
    if (!context.sleeping) return 0;
    if (strip.cells[from - strip.grid.layerSize()] != kEmpty) return 0; // rides a moving grain
    FallState& own = strip.falls[std::size_t(strip.cells[from])];
    const int gathering = granular_->stepsOnlyGathering(own, kLongestSleep);
    if (gathering == 0) return 0; // it moves in the next step
    own.gatheringSince = std::uint16_t(kGatheringAsleep | (context.step & kAsleepStepMask));
    const std::uint64_t wakeStep = context.step + std::uint64_t(gathering) + 1;
    log.sleepers.push_back({{row, std::uint32_t(x)}, wakeStep});
    return wakeStep;
}

// The grains resting one on another above the grain in cell `from` of (x, y, z), which stays
// there moving at `speed` (> 0) after its visit in this step, visited now rather than in their
// layers' turns: each one's visit would only ride the grain below it (GranularRules::ride), and
// nothing it reads can change before its turn (the cell below it stays taken, the speed of the
// grain in it is final for the step). Visiting a column at once spares each grain the queue and
// the reads of the cell and the state below it. A grain that rode is marked (MotionWord::carriedEarly):
// its layer's turn skips it and keeps it awake for the next step, as its own visit would have.
// The column ends at the first cell without a grain, or at a grain whose ride changed nothing
// (it sleeps, as after its own visit). Returns the grains visited.
// asleepUntil: the grain below them sleeps until that step (fallAsleepGathering), and they sleep
// with it: each is marked (kRidingAsleep) and gets a timer for that step instead of staying
// awake, since then the grain below moves on and they follow in their own turns. Gravity is never
// 0 (validatePhysics), so every rider's speed changes every step and the whole column rides.
int GridSweep::carryRiders(const SweepContext& context, const GranularStrip& strip, StripLog& log, int x, int y, int z,
                           std::uint32_t from, std::uint32_t speed, std::uint64_t asleepUntil) {
    const std::uint32_t layer = strip.grid.layerSize();
    const std::uint64_t bit = std::uint64_t{1} << (x & 63);
    // The column is read a batch of cells at a time and each rider's fall state asked for before
    // the first ride: a state is found by the id in the cell, so read one after another each
    // cell's state waits on its cell and the next rider on both (a state load stalled 72% of
    // this function's samples; batched: 2% off the granular step of the million-grain drain).
    constexpr int kBatch = 16;
    std::array<CellValue, kBatch> riders;
    int carried = 0;
    std::uint32_t cell = from;
    for (int above = y + 1; above < strip.sizeY;) {
        int count = 0;
        for (; count < kBatch && above + count < strip.sizeY; ++count) {
            const CellValue rider = strip.cells[cell + std::uint32_t(count + 1) * layer];
            if (rider < 0) break;
            __builtin_prefetch(strip.falls.data() + rider);
            riders[std::size_t(count)] = rider;
        }
        for (int i = 0; i < count; ++i, ++above) {
            const std::uint32_t row = std::uint32_t(above) * std::uint32_t(strip.sizeZ) + std::uint32_t(z);
            const std::size_t word = std::size_t(row) * std::size_t(rowWords_) + std::size_t(x >> 6);
            MotionWord& motion = strip.motion[word];
            const bool mayBeMoving = (motion.inMotion & bit) != 0;
            FallState& state = strip.falls[std::size_t(riders[std::size_t(i)])];
            const bool wasAsleep = mayBeMoving && state.gatheringSince != 0;
            if (wasAsleep) { // it slept with the grain below: brought up to the step before
                state = granular_->caughtUp(state, context.step - 1);
                ++log.sleepsEnded;
            }
            if (granular_->ride(state, speed, mayBeMoving, above > 1 || !bottomIsOutlet_) == GranularOutcome::Riding)
                return carried; // it sleeps, as after its own visit
            motion.inMotion |= bit;
            if (asleepUntil) {
                state.gatheringSince = std::uint16_t(kGatheringAsleep | kRidingAsleep | (context.step & kAsleepStepMask));
                strip.words[word].awake &= ~bit; // not kept awake: its timer wakes it
                strip.words[word].occupied &= ~bit;
                log.sleepers.push_back({{row, std::uint32_t(x)}, asleepUntil});
            } else {
                motion.carriedEarly |= bit;
                strip.rowAwake[row] = 1;
                if (wasAsleep) strip.words[word].occupied |= bit;
            }
            ++carried;
        }
        if (count < kBatch) break; // the column ends at a cell without a grain (or the grid's top)
        cell += std::uint32_t(kBatch) * layer;
    }
    return carried;
}

// The granular strip loop: the strips `strips` one after another (one strip where threads share a
// phase's strips, else all the strips of the turn that listTurnStrips found awake). A grain
// visited later finds the cells of the layer below taken by one visited earlier, so a fixed order
// would let grains run one way more easily than the other and cones would lean (PH2). The order
// therefore turns with the step: x ascending or descending by bit 0 of the step number, z by bit
// 1 within each strip, so over four steps every mirror of the grid is swept alike. No visit wakes
// a cell of its own layer for this step (the header), so all the strips' awake bits are taken at
// once, before the first visit.
SweepResult GridSweep::sweepGranularStrips(const SweepContext& context, int y, std::span<const int> strips) {
    SweepResult totals;
    if (strips.empty()) return totals;
    const GranularStrip strip{context.grid,
                              context.grid.cells().data(),
                              context.grains.fall[std::size_t(context.level)],
                              dither_, // the wakes' too: one source for both
                              context.stepKey,
                              std::uint64_t(context.level),
                              std::size_t(size_.z) * std::size_t(rowWords_),
                              words_.data(),
                              motion_.data(),
                              rowAwake_.data(),
                              size_.y,
                              size_.z};
    const bool xDown = (context.step & 1) != 0, zDown = (context.step & 2) != 0;
    // The grains these strips' visits carried up their columns count as visited (carryRiders).
    auto addCarried = [&] {
        for (const int index : strips) {
            totals.visited += logs_[std::size_t(index)].carried;
            logs_[std::size_t(index)].carried = 0;
        }
    };
    // Calls f(z) for the rows of the strips in visiting order.
    auto forEachRow = [&](auto&& f) {
        for (const int index : strips) {
            const int zBegin = index * kStripRows, zEnd = std::min(zBegin + kStripRows, size_.z);
            for (int i = zBegin; i < zEnd; ++i) f(zDown ? zBegin + zEnd - 1 - i : i);
        }
    };
    // Calls f(x) for the cells `bits` of word w of a row, in visiting order.
    auto forEachBit = [&](int w, std::uint64_t bits, auto&& f) {
        while (bits) {
            const int bit = xDown ? 63 - __builtin_clzll(bits) : __builtin_ctzll(bits);
            bits &= ~(std::uint64_t{1} << bit);
            f(w * 64 + bit);
        }
    };
    auto visit = [&](int x, int z, bool mayBeMoving) {
        const std::uint32_t row = std::uint32_t(y) * std::uint32_t(size_.z) + std::uint32_t(z);
        StripLog& log = logs_[std::size_t(z / kStripRows)]; // each strip's moves and cells left in its own log
        ++totals.visited;
        bool stopped = false;
        const GranularOutcome::Kind kind = visitGranular(context, strip, log, x, y, z, row, row * std::uint32_t(size_.x), mayBeMoving, stopped);
        totals.moves += kind == GranularOutcome::Moved ? 1 : 0;
        log.speedChanges += kind == GranularOutcome::Waiting || stopped ? 1 : 0;
    };
    if (!context.sleeping) { // every cell of every row, as if awake
        forEachRow([&](int z) {
            const std::uint32_t row = std::uint32_t(y) * std::uint32_t(size_.z) + std::uint32_t(z);
            rowAwake_[row] = 0;
            RowWord* words = words_.data() + std::size_t(row) * std::size_t(rowWords_);
            MotionWord* motion = motion_.data() + std::size_t(row) * std::size_t(rowWords_);
            for (int j = 0; j < rowWords_; ++j) {
                const int w = xDown ? rowWords_ - 1 - j : j;
                words[w].awake = 0; // a full sweep keeps no awake bits: turning sleeping on wakes every grain
                const std::uint64_t visitedEarly = motion[w].carriedEarly; // visited in this step already
                motion[w].carriedEarly = 0;
                const std::uint64_t moving = motion[w].inMotion;
                forEachBit(w, wholeWord(w) & ~visitedEarly, [&](int x) { visit(x, z, (moving >> (x & 63)) & 1); });
            }
            if (context.feed) context.feed->publishSome();
        });
        addCarried();
        return totals;
    }
    // The awake cells, in visiting order. A visit waits on its cell, the cell below and, for a
    // grain in motion, its fall state, which only the cell's grain id locates: so each visit asks
    // for the cells kCellsAhead visits on, and for the fall state kStatesAhead visits on, by when
    // that grain's cell has arrived. The loads of several visits are then in flight together
    // instead of one after another (12% off the granular step of the million-grain drain, and 3%
    // more with one queue for all strips of a phase where one thread sweeps them; one for the
    // whole turn, both phases, spares a call and a queue per layer). Each entry
    // carries its cell's in-motion bit, read with the carried-early word of the same cells, so
    // neither the look ahead nor the visit loads it again (about 1%). The classic loop keeps its
    // row-ahead hint: the same queue made its step 14-20% slower.
    // One strip (threads sharing a phase) in that strip's queue, a turn on one thread in the
    // sweep's: each has room for every cell it may hold, made once.
    std::vector<StripLog::Cell>& queue = strips.size() == 1 ? logs_[std::size_t(strips.front())].awake : turnQueue_;
    const std::size_t most = strips.size() * std::size_t(kStripRows) * std::size_t(size_.x);
    if (queue.size() < most) queue.resize(most);
    StripLog::Cell* const queued = queue.data();
    std::size_t count = 0;
    forEachRow([&](int z) {
        const std::uint32_t row = std::uint32_t(y) * std::uint32_t(size_.z) + std::uint32_t(z);
        if (!rowAwake_[row]) return;
        RowWord* words = words_.data() + std::size_t(row) * std::size_t(rowWords_);
        MotionWord* motion = motion_.data() + std::size_t(row) * std::size_t(rowWords_);
        __builtin_prefetch(motion - strip.layerWords); // the visits read the in-motion bits under the row
        std::uint64_t stillAwake = 0;
        for (int j = 0; j < rowWords_; ++j) {
            const int w = xDown ? rowWords_ - 1 - j : j;
            // The grains carried early were visited in this step: awake for the next one only.
            const std::uint64_t visitedEarly = motion[w].carriedEarly;
            motion[w].carriedEarly = 0;
            const std::uint64_t bits = words[w].awake & ~visitedEarly;
            words[w].awake = visitedEarly;
            stillAwake |= visitedEarly;
            const std::uint64_t moving = motion[w].inMotion;
            forEachBit(w, bits, [&](int x) {
                assert(count < most); // awake bits lie only on cells of the strips' rows
                queued[count++] = {std::uint32_t(x), std::uint32_t((moving >> (x & 63)) & 1), std::uint32_t(z)};
            });
        }
        rowAwake_[row] = stillAwake != 0;
    });
    const std::uint32_t layerRowStart = std::uint32_t(y) * std::uint32_t(size_.z);
    const auto rowOf = [&](const StripLog::Cell& c) { return layerRowStart + c.z; };
    const auto cellOf = [&](const StripLog::Cell& c) { return rowOf(c) * std::uint32_t(size_.x) + c.x; };
    for (std::size_t n = 0; n < count; ++n) {
        if (n + kCellsAhead < count) {
            const CellValue* cell = strip.cells + cellOf(queued[n + kCellsAhead]);
            __builtin_prefetch(cell);
            __builtin_prefetch(cell - strip.grid.layerSize());
        }
        if (n + kStatesAhead < count) {
            const StripLog::Cell ahead = queued[n + kStatesAhead];
            if (ahead.inMotion) {
                const CellValue grain = strip.cells[cellOf(ahead)];
                if (grain >= 0) __builtin_prefetch(strip.falls.data() + grain);
            }
        }
        const StripLog::Cell at = queued[n];
        if (context.feed && n > 0 && at.z != queued[n - 1].z) context.feed->publishSome(); // a row done
        visit(int(at.x), int(at.z), at.inMotion);
    }
    if (context.feed) context.feed->publishSome();
    addCarried();
    return totals;
}

// The first awake cell of row z of layer y, and the cell below it, are usually not in the cache
// yet (a visit reads the layer below, not the next row of its own): asking for them one row
// ahead overlaps those misses with this row's visits. A hint only; classic moves never wake
// cells of their own layer, so the row's awake bits are already final.
void GridSweep::prefetchFirstAwake(const CellGrid& grid, int y, int z) const {
    const RowWord* words = words_.data() + (std::size_t(y) * std::size_t(size_.z) + std::size_t(z)) * std::size_t(rowWords_);
    for (int w = 0; w < rowWords_; ++w) {
        if (!words[w].awake) continue;
        const CellValue* cell = grid.cells().data() + grid.index(w * 64 + __builtin_ctzll(words[w].awake), y, z);
        __builtin_prefetch(cell);
        __builtin_prefetch(cell - grid.layerSize());
        return;
    }
}

// Whether a row z0..z1-1 of layer y may hold awake cells. A strip none of whose rows is awake when
// its turn comes has nothing to visit, and while it would run nothing else can wake its rows (the
// strips running beside it keep apart, the layers below are done, and a strip of the other phase
// runs before or after it), so it is skipped whole: most strips of a busy layer are idle.
inline bool GridSweep::anyRowAwake(int y, int z0, int z1) const {
    // Eight flags a load (a whole strip's in one; a layer's rows need not start aligned).
    const std::uint8_t* flag = rowAwake_.data() + std::size_t(y) * std::size_t(size_.z) + std::size_t(z0);
    const std::uint8_t* const end = flag + (z1 - z0);
    for (; end - flag >= 8; flag += 8) {
        std::uint64_t flags;
        std::memcpy(&flags, flag, sizeof flags);
        if (flags) return true;
    }
    return std::any_of(flag, end, [](std::uint8_t f) { return f != 0; });
}

// The strips of layer y's turn, even ones first: those holding awake rows (all of them in a full sweep).
// A strip without any has nothing to visit in the turn, and nothing can wake its rows before the
// turn ends (anyRowAwake). Listed once, the phases, the carried counts and the turn's end go over
// those only, where each went over every strip (1.7% of the granular step of the million-grain
// drain).
void GridSweep::listTurnStrips(int y, bool sleeping) {
    const int strips = int(logs_.size()); // one log per strip
    turnStrips_.clear();
    for (int phase = 0; phase < 2; ++phase) {
        if (phase == 1) oddStripsBegin_ = turnStrips_.size();
        for (int strip = phase; strip < strips; strip += 2)
            if (!sleeping || anyRowAwake(y, strip * kStripRows, std::min((strip + 1) * kStripRows, size_.z)))
                turnStrips_.push_back(strip);
    }
}

// The classic strip loop (the granular one is sweepGranularStrips): each word's awake bits taken at
// once, with no test of the rule set per word or per grain.
SweepResult GridSweep::sweepStrip(const SweepContext& context, int y, int strip) {
    SweepResult totals;
    const Int3 size = size_;
    const int zEnd = std::min((strip + 1) * kStripRows, size.z);
    StripLog& log = logs_[std::size_t(strip)];
    if (context.sleeping && !anyRowAwake(y, strip * kStripRows, zEnd)) return totals;
    for (int z = strip * kStripRows; z < zEnd; ++z) {
        const std::uint32_t row = std::uint32_t(y) * std::uint32_t(size.z) + std::uint32_t(z);
        if (context.sleeping && !rowAwake_[row]) continue;
        rowAwake_[row] = 0;
        // Classic moves only wake cells in the layers above and below, never in this row: take its
        // bits first. Without sleeping, every cell of the row is visited as if awake.
        RowWord* words = words_.data() + std::size_t(row) * std::size_t(rowWords_);
        if (context.sleeping && z + 1 < zEnd && rowAwake_[row + 1]) prefetchFirstAwake(context.grid, y, z + 1);
        for (int w = 0; w < rowWords_; ++w) {
            std::uint64_t bits = context.sleeping ? words[w].awake : wholeWord(w);
            words[w].awake = 0;
            while (bits) {
                const int x = w * 64 + __builtin_ctzll(bits);
                bits &= bits - 1;
                ++totals.visited;
                totals.moves += visitCell(context, log, x, y, z) ? 1 : 0;
            }
        }
        if (context.feed) context.feed->publishSome();
    }
    return totals;
}

SweepResult GridSweep::sweep(const SweepContext& context, WorkerPool* pool) {
#if defined(SANDCORE_SWEEP_BMI2) && !defined(SANDCORE_SWEEP_BUILDING_BMI2)
    if (runsBmi2Sweep(granular_ ? PhysicsLevel::Granular : PhysicsLevel::Classic, context.code))
        return sandcoreSweepBmi2(*this, context, pool);
#endif
    return sweepWithThisBuild(context, pool);
}

SweepResult GridSweep::sweepWithThisBuild(const SweepContext& context, WorkerPool* pool) {
    return granular_ ? sweepBy<true>(context, pool) : sweepBy<false>(context, pool);
}

#ifdef SANDCORE_SWEEP_BUILDING_BMI2
extern "C" SweepResult sandcoreSweepBmi2(GridSweep& sweep, const SweepContext& context, WorkerPool* pool) {
    countBmi2Sweep();
    return sweep.sweepWithThisBuild(context, pool);
}
#endif

template <bool Granular> SweepResult GridSweep::sweepBy(const SweepContext& context, WorkerPool* pool) {
    SweepResult result;
    const Int3 size = size_;
    const int strips = (size.z + kStripRows - 1) / kStripRows;
    const bool threaded = pool && pool->threadCount() > 1 && strips > 1;
    std::vector<SweepResult> stripTotals(threaded ? std::size_t(strips) : 0);
    auto add = [&result](const SweepResult& t) {
        result.moves += t.moves;
        result.visited += t.visited;
    };
    [[maybe_unused]] const std::int64_t asleepBefore = fallsAsleep_;
    if constexpr (Granular) {
        // The sleepers whose fall reaches a cell in this step (or whose longest sleep ends), woken
        // before any visit: a column that falls asleep again in this step puts its riders back to
        // sleep after this.
        std::vector<StripLog::SleeperCell>& due = timers_[std::size_t(context.step % kTimerSlots)];
        for (const StripLog::SleeperCell& cell : due) {
            RowWord& word = words_[std::size_t(cell.row) * std::size_t(rowWords_) + std::size_t(cell.x >> 6)];
            word.awake |= std::uint64_t{1} << (cell.x & 63);
            word.occupied |= std::uint64_t{1} << (cell.x & 63);
            rowAwake_[cell.row] = 1;
        }
        due.clear();
    }
    for (int y = 1; y < size.y; ++y) {
        // The count of awake rows only decides whether threads share the layer's strips; on one
        // thread, the granular turn finds an idle layer as it lists the strips.
        const int awakeRows = !context.sleeping ? size.z
                              : threaded        ? awakeRowsInLayer(y)
                              : Granular        ? 1
                                                : int(anyRowAwake(y, 0, size.z));
        if (awakeRows == 0) continue;
        const bool parallel = threaded && awakeRows >= kMinAwakeRowsForThreads;
        auto addStrip = [&](int strip, const SweepResult& t) {
            stripTotals[std::size_t(strip)].moves += t.moves;
            stripTotals[std::size_t(strip)].visited += t.visited;
        };
        if constexpr (Granular) {
            listTurnStrips(y, context.sleeping);
            if (turnStrips_.empty()) continue; // nothing awake in the layer
            const std::span<const int> turn(turnStrips_);
            if (!parallel) {
                // One thread: one queue for the whole turn, even strips then odd, so its visits
                // ask ahead across strips and phases (no visit wakes a cell of its own layer).
                add(sweepGranularStrips(context, y, turn));
            } else {
                for (const std::span<const int> phase : {turn.first(oddStripsBegin_), turn.subspan(oddStripsBegin_)})
                    pool->parallelFor(int(phase.size()), [&](int i) {
                        addStrip(phase[std::size_t(i)], sweepGranularStrips(context, y, phase.subspan(std::size_t(i), 1)));
                    });
            }
            endGranularTurn(y);
            continue;
        }
        for (int phase = 0; phase < 2; ++phase) {
            if (!parallel) {
                for (int strip = phase; strip < strips; strip += 2) add(sweepStrip(context, y, strip));
                continue;
            }
            const int count = (strips - phase + 1) / 2;
            pool->parallelFor(count, [&](int i) {
                const int strip = phase + 2 * i;
                addStrip(strip, sweepStrip(context, y, strip));
            });
        }
    }
    if constexpr (Granular) {
        wakeAroundCellsLeftEarlier(context.grid);
        // Each gatherer or rider that slept through this step changed its fall without a visit.
        std::int64_t ended = 0;
        speedChangesLastSweep_ = 0;
        for (StripLog& log : logs_) {
            speedChangesLastSweep_ += log.speedChanges;
            log.speedChanges = 0;
            ended += log.sleepsEnded;
            log.sleepsEnded = 0;
            for (const StripLog::Sleeper& sleeper : log.sleepers)
                timers_[std::size_t(sleeper.wakeStep % kTimerSlots)].push_back(sleeper.cell);
            fallsAsleep_ += std::int64_t(log.sleepers.size());
            log.sleepers.clear();
        }
        speedChangesLastSweep_ += asleepBefore - ended;
        fallsAsleep_ -= ended;
    }
    for (const SweepResult& t : stripTotals) add(t);
    return result;
}

} // namespace sandcore
