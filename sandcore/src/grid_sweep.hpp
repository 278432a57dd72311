// SPDX-License-Identifier: MIT
#pragma once
// The bottom-up sweep of one grid (R3) over its awake grains (R5), shared by threads (R6).
// Private to sandcore.
//
// Canonical visiting order, the same for every thread count: layers from the bottom up; within
// a layer, strips of kStripRows rows in two phases (even strips, then odd strips); within a strip,
// rows by ascending z and cells by ascending x (granular: z and x turned by bits 1 and 0 of the
// step number, so cones do not lean; sweepGranularStrips). A grain in row z only reads and writes
// rows z-1..z+1 of the layers next to it (granular: z-3..z+3, still less than a strip), so strips
// of one phase never touch each other's cells or bits and may run on different threads in any
// order.
// Under both rule sets a visit wakes no cell of its own layer for the same step: the classic
// rules read only the layer below, and the granular paths read their layer as it was when its
// turn began (granular_rules.hpp), so a layer's awake bits are final when its turn begins.
// A granular visit of a grain that stays where it is, moving, also visits the grains that ride
// on it in the column above (carryRiders), in the same strip's rows; their layers' turns then
// skip them.
// A granular grain falling through an EMPTY cell short of its next cell (a gatherer), and the
// column riding on it, sleep until the step its fall reaches that cell (a timer wakes them),
// their states stored as of the step they fell asleep (FallState::gatheringSince). Each visit
// skipped would only have added gravity to them, and nothing else they read can change: the
// cell below the gatherer stays EMPTY, since a grain falls into it only through the gatherer's
// cell and slides into it only along a path that ends at the gatherer's cell, taken since before
// the turn began (granular_rules.hpp); a rider's cell below holds the grain under it until the
// timer. What can change is a grain arriving on top (a fall, a slide, the neck) or an edit next
// to them: the grain on top wakes the one below it at its next visit, an edit at once
// (grainEntered, cellBlocked, wakeAroundEmptied), and whoever reads a state meanwhile (a grain
// landing on it, a save) reads it caught up (GranularRules::caughtUp). Their occupied bits are
// cleared while they sleep, so the wakes of cells emptied nearby pass them by.

#include "empty_cells.hpp"
#include "granular_rules.hpp"
#include "move_feed.hpp"
#include "sandcore/cell_grid.hpp"
#include "sandcore/grain_store.hpp"
#include "sandcore/layout_bits.hpp"
#include "sandcore/sweep_code.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace sandcore {

class WorkerPool;

inline constexpr int kStripRows = 8;
/// How many visits ahead the granular strip loop asks for a cell (and the one below it), and for
/// the fall state of the grain in it (measured over the million-grain drain: 4 to 12 cells
/// ahead did alike, 16 worse).
inline constexpr std::size_t kCellsAhead = 8, kStatesAhead = 4;

/// What one strip of a sweep keeps of its moves when its grain records are written at once: the
/// grains it moved and where to (threads that share a layer's strips each append to their own).
struct StripLog {
    std::vector<GrainMove> moved;
    /// Granular: the cells (their columns) its grains left in the current layer's turn, kept
    /// until the turn ends (granular_rules.hpp: a layer's paths see it as its turn began).
    struct Column {
        int x, z;
    };
    std::vector<Column> left;
    /// Granular: grains whose fall changed without a move in this sweep (SceneCounters).
    std::int64_t speedChanges = 0;
    /// Granular: the awake cells a sweep of this strip visits in the current layer's turn, where
    /// threads share the phase's strips (a turn on one thread: GridSweep::turnQueue_), in visiting
    /// order: room for every cell of the strip, filled from the front through a plain pointer (a
    /// push_back's end pointer, stored and read back each time, chained the pushes), the count
    /// kept by the loop.
    struct Cell {
        std::uint32_t x : 31;
        /// Its in-motion bit as the queue was made: a layer's in-motion bits change in its turn
        /// only by the visit of their own cell, so the visit and its look ahead read it here.
        std::uint32_t inMotion : 1;
        std::uint32_t z;
    };
    std::vector<Cell> awake;
    /// Granular: where a gatherer or rider sleeps, as the awake bits find it (row: y * sizeZ + z).
    struct SleeperCell {
        std::uint32_t row, x;
    };
    /// Granular: gatherers and riders that fell asleep in this sweep, and the step each one's
    /// timer wakes it.
    struct Sleeper {
        SleeperCell cell;
        std::uint64_t wakeStep;
    };
    std::vector<Sleeper> sleepers;
    /// Granular: the sleeping gatherers and riders this sweep visited or carried (they wake so).
    std::int64_t sleepsEnded = 0;
    /// Granular: grains visited while carried by the grain below (carryRiders), since the
    /// strip loop that swept this strip last counted them.
    std::int64_t carried = 0;
};

struct SweepResult {
    std::int64_t moves = 0;   ///< grains moved
    std::int64_t visited = 0; ///< cells looked at
};

/// What one grid's sweep in one step shares with every cell it visits (like Box2D's
/// b2StepContext): set up once by Scene::step, unchanged while the sweep runs. Each strip
/// returns its own totals, so strips on different threads never write to a shared count.
struct SweepContext {
    CellGrid& grid;      ///< the grid being swept
    GrainStore& grains;  ///< the scene's grain records; a move updates its grain's
    std::uint64_t seed;  ///< StepSettings::seed: picks the slips (R3)
    std::uint64_t step;  ///< this step's number, 1 = the first after a reset: picks the slips, stamps movedAtStep
    GridLevel level;     ///< which grid: picks the slips, so the two grids draw differently
    bool sleeping;       ///< R5: visit awake cells only; false = every cell (same result)
    std::uint64_t stepKey; ///< counterRandomStepKey(seed, step), computed once per sweep
    /// When set (the two grids swept side by side), a classic move writes no grain record and
    /// lists no id: it is fed here for the thread that writes the records (move_feed.hpp).
    MoveFeed* feed;
    /// When set (a sweep on one thread that writes records at once), the moves are appended here
    /// directly instead of to the strips' logs.
    std::vector<GrainMove>* movedList;
    SweepCode code; ///< StepSettings::sweepCode: which build of the sweep runs
};

class GridSweep;

/// GridSweep::sweep as built for BMI1 and BMI2 (sweep_code.hpp), defined where sandcore is built
/// with SANDCORE_SWEEP_BMI2: grid_sweep.cpp and granular_rules.cpp are compiled a second time for
/// those CPUs, linked into one object, and every symbol of it but this one made local
/// (sandcore/CMakeLists.txt), so the inline functions of both builds never mix. Only
/// GridSweep::sweep calls it (runsBmi2Sweep).
extern "C" SweepResult sandcoreSweepBmi2(GridSweep& sweep, const SweepContext& context, WorkerPool* pool);
/// Counts one sweep of the BMI2 build (bmi2SweepsRun); sweep_code.cpp, so both builds share it.
void countBmi2Sweep();

class GridSweep {
public:
    /// Awake bits for a grid of this size. bottomIsOutlet: grains in layer 0 stay awake for the
    /// transition (the upper grid). The grid itself is passed to each sweep, so a Scene can move.
    GridSweep(Int3 gridSize, bool bottomIsOutlet);

    /// The rules to apply: the granular ones (PH1), or the thesis's when null. Not owned. Every
    /// grain counts as at rest afterwards (the scene zeroes the fall states when the rules change).
    void setGranular(const GranularRules* granular);
    /// The seed of the granular thresholds' dither (StepSettings::seed): the visits and wakes read it.
    void setSeed(std::uint64_t seed);
    /// Granular: the grain now in cell (x, y, z) may be in motion (its fall state is not zero).
    /// Whoever writes a fall state outside a sweep says so here; a cell whose bit is clear holds
    /// no grain in motion, so a visit need not read its state.
    void markInMotion(int x, int y, int z);

    /// Granular: reads which cells of grid are EMPTY and which INVALID (the rules' windows and the
    /// wakes read bits kept by the sweep). After the rules are set and after edits that bypass the
    /// calls below.
    void readEmptyCells(const CellGrid& grid);
    /// True when the kept EMPTY and INVALID cells are those of grid (always, under the classic rules).
    bool emptyCellsMatch(const CellGrid& grid) const;
    /// A grain entered the cell (x, y, z) from outside a sweep: it is woken there (as wakeAt; not
    /// on the floor, layer 0 of a grid without an outlet, which is never visited).
    void grainEntered(int x, int y, int z);
    void grainEntered(std::uint32_t cell); ///< as above, by index
    /// The EMPTY cell became INVALID (an obstacle).
    void cellBlocked(std::uint32_t cell);
    void wake(std::uint32_t cell);              ///< the cell is visited in its layer's next turn
    void wakeAt(int x, int y, int z);           ///< as wake, by coordinate
    void wakePredecessorsOf(int x, int y, int z); ///< the 9 cells above (x, y, z)
    /// A grain left (x, y, z) of grid: wakes every grain whose options that can widen (classic:
    /// the 9 cells above; granular: see wakeForGranular), and the outlet cell of the grid above
    /// when (x, y, z) lies in the top layer. Every way a cell empties goes through here (R5).
    void wakeAroundEmptied(const CellGrid& grid, int x, int y, int z);
    void wakeEveryGrain(const CellGrid& grid); ///< after edits that bypass the rules
    void clear();                               ///< nothing awake, no gatherer asleep
    /// Granular: a sleeping gatherer or rider (FallState::gatheringSince) left the grid from
    /// outside a step.
    void sleepingFallRemoved() { --fallsAsleep_; }

    /// When set, a cell of this grid's top layer that empties wakes the cell of `above`'s
    /// layer 0 at the same x and z (the lower grid wakes the upper grid's outlet row).
    void setGridAbove(GridSweep* above) { above_ = above; }
    /// While deferred, those wakes are kept until applyDeferredWakes(), so the grid above may
    /// be swept at the same time on another thread.
    void setDeferWakesAbove(bool defer) { deferWakesAbove_ = defer; }
    /// Applies the wakes kept while deferred.
    void applyDeferredWakes();
    /// The feed a side-by-side sweep of this grid fills (SweepContext::feed).
    MoveFeed& feed() { return feed_; }
    /// Appends the moves the last sweep logged to `moved` and empties the logs. Each grain is
    /// listed at most once: every move goes down at least a layer, and each layer is visited once.
    void takeLoggedMoves(std::vector<GrainMove>& moved);
    /// Granular: the grains whose fall the last sweep changed without moving them (a grain
    /// gathering its next cell, riding a moving grain, or stopping).
    std::int64_t speedChangesLastSweep() const { return speedChangesLastSweep_; }
    /// Rows (of all layers) that may hold awake cells: a cheap measure of the next sweep's work.
    std::int64_t awakeRowCount() const;

    /// Applies the rules to layers 1..top of context.grid, bottom-up; pool (may be null) shares
    /// busy layers' strips between threads.
    SweepResult sweep(const SweepContext& context, WorkerPool* pool);

    /// Calls visit(cell) for every cell of layer 0 that is awake (or every cell, when not
    /// sleeping), in index order, and puts them to sleep.
    template <class Visit> void forEachInBottomLayer(bool sleeping, Visit&& visit) {
        const int sizeX = size_.x;
        for (int z = 0; z < size_.z; ++z) {
            const std::uint32_t row = std::uint32_t(z);
            if (!sleeping) {
                clearRow(row);
                for (int x = 0; x < sizeX; ++x) visit(std::uint32_t(x) + std::uint32_t(sizeX) * std::uint32_t(z));
                continue;
            }
            if (!rowAwake_[row]) continue;
            rowAwake_[row] = 0;
            for (int w = 0; w < rowWords_; ++w) {
                std::uint64_t bits = words_[std::size_t(row) * rowWords_ + std::size_t(w)].awake;
                words_[std::size_t(row) * rowWords_ + std::size_t(w)].awake = 0;
                while (bits) {
                    const int x = w * 64 + __builtin_ctzll(bits);
                    bits &= bits - 1;
                    visit(std::uint32_t(x) + std::uint32_t(sizeX) * std::uint32_t(z));
                }
            }
        }
    }

private:
    friend SweepResult sandcoreSweepBmi2(GridSweep& sweep, const SweepContext& context, WorkerPool* pool);
    SweepResult sweepWithThisBuild(const SweepContext& context, WorkerPool* pool); // what sweep runs here
    template <bool Granular> SweepResult sweepBy(const SweepContext& context, WorkerPool* pool);
    SweepResult sweepStrip(const SweepContext& context, int y, int strip); // classic
    void listTurnStrips(int y, bool sleeping); // granular: turnStrips_ for layer y
    template <bool Granular> void wakeAroundEmptiedBy(const CellGrid& grid, int x, int y, int z);
    void wakeOutletAbove(int x, int y, int z); // a top-layer cell emptied: the grid above's outlet cell
    // Granular, at the end of layer y's turn: the cells left in it become EMPTY in the kept bits;
    // their own-layer wakes wait for the sweep's end (wakeAroundCellsLeftEarlier).
    void endGranularTurn(int y);
    void wakeAroundCellsLeftEarlier(const CellGrid& grid); // those own-layer wakes, of cells still EMPTY
    // classic rules; true when a grain moved
    bool visitCell(const SweepContext& context, StripLog& log, int x, int y, int z);
    struct GranularStrip;
    // What the visit did, as GranularOutcome::Kind, with Resting for a cell that holds no grain;
    // `stopped` tells whether a grain in motion came to rest. (Returning the whole outcome instead
    // cost 2.7% more instructions a granular step: the strip loop copied it out of every visit.)
    // mayBeMoving: the cell's in-motion bit.
    GranularOutcome::Kind visitGranular(const SweepContext& context, const GranularStrip& strip, StripLog& log, int x,
                                        int y, int z, std::uint32_t row, std::uint32_t rowStart, bool mayBeMoving, bool& stopped);
    void record(const SweepContext& context, StripLog& log, const GrainMove& move);
    std::uint64_t fallAsleepGathering(const SweepContext& context, const GranularStrip& strip, StripLog& log, int x,
                                      std::uint32_t row, std::uint32_t from);
    int carryRiders(const SweepContext& context, const GranularStrip& strip, StripLog& log, int x, int y, int z,
                    std::uint32_t from, std::uint32_t speed, std::uint64_t asleepUntil);
    SweepResult sweepGranularStrips(const SweepContext& context, int y, std::span<const int> strips);
    void clearRow(std::uint32_t row);
    Int3 coordinateOf(std::uint32_t cell) const; // as CellGrid::coordinate, for this sweep's grid
    void prefetchFirstAwake(const CellGrid& grid, int y, int z) const;
    std::uint64_t wholeWord(int w) const; // bits of every cell of a row in word w
    void wakeSpan(std::size_t row, int x0, int x1);
    void wakeIfOccupied(int x, int y, int z); // wakeAt, but only when the cell's occupied bit is set
    void wakeGrainsAround(const CellGrid& grid, int x, int y, int z, int layersAbove);
    void wakeSleepingGrainsAround(const CellGrid& grid, int x, int y, int z, int layersAbove, std::uint64_t sleeping); // its rest
    // Where a granular window's 7 columns around x lie in a row's words of bits.
    struct WindowColumns {
        int word, offset, dropped; // first word, the bit the window starts at in it, columns left of 0
        bool spills;               // the window runs on into the next word
    };
    WindowColumns windowColumnsAround(int x) const;
    std::uint64_t sleepingGrainsAround(int x, int y, int z) const;
    std::uint64_t sleepingGrainsAroundSide(int x, int y, int z) const; // near the grid's sides
    void wakeWindow(int x, int y, int z, std::uint64_t woken);
    // Granular: the cell under cell `from` (not in layer 0) is INVALID, read from the kept bits.
    bool liesOnVessel(const CellGrid& grid, std::uint32_t from) const { return !layout_.open(from - grid.layerSize()); }
    std::uint64_t deepEnoughForSlidesInto(const CellGrid& grid, std::uint64_t woken, int x, int y, int z, int layersAbove) const;
    void wakeForGranular(const CellGrid& grid, int x, int y, int z);
    void wakeLayersAbove(const CellGrid& grid, int x, int y, int z); // wakeForGranular above layer y
    int awakeRowsInLayer(int y) const;
    bool anyRowAwake(int y, int z0, int z1) const;
    // The grid's stream of random draws (SweepContext::level): the upper grid is the one with an outlet.
    std::uint64_t stream() const { return std::uint64_t(bottomIsOutlet_ ? GridLevel::Upper : GridLevel::Lower); }

    Int3 size_;
    bool bottomIsOutlet_;
    GridSweep* above_ = nullptr;
    const GranularRules* granular_ = nullptr;
    ThresholdDither dither_; // the granular thresholds' under the seed (seed 0 until setSeed)
    bool deferWakesAbove_ = false;
    std::vector<std::uint32_t> deferredWakesAbove_; // x + sizeX * z of the outlet cells to wake
    int rowWords_;                       // 64-bit words per row of awake bits
    // Per 64 cells of a row: the awake bits, and the cells that may hold a grain (set by every
    // wakeAt: each grain that enters a cell is woken there; cleared when a classic move or a visit
    // finds the cell EMPTY). Waking the cells above an emptied cell ANDs with the second, so EMPTY
    // and INVALID cells stay asleep. Side by side, a visit or a wake that reads one word finds
    // the other in the same cache line (two arrays cost a second miss per visit and per wake).
    struct RowWord {
        std::uint64_t awake = 0;
        std::uint64_t occupied = 0;
        std::uint64_t sleeping() const { return occupied & ~awake; } ///< cells that hold a grain, not awake
    };
    std::vector<RowWord, LargePageAllocator<RowWord>> words_; // row = y * sizeZ + z, padded to whole words
    // Granular only, per 64 cells of a row as words_: the cells whose grain may be in motion
    // (markInMotion; a visit reads a grain's fall state by id, a cache miss, and most visited
    // grains are at rest), and the grains visited in this step before their layer's turn
    // (carryRiders; the turn skips them and leaves them awake for the next step). Side by side,
    // the turn's queue takes the second and finds the first in the same cache line for its look
    // ahead and the visits, and a carried grain sets both in one line (two arrays: 1.4% slower).
    struct MotionWord {
        std::uint64_t inMotion = 0;
        std::uint64_t carriedEarly = 0;
    };
    std::vector<MotionWord, LargePageAllocator<MotionWord>> motion_;
    // Granular only: which cells are EMPTY, kept with every change of a cell (moves here, the
    // scene's edits through the calls above), so slides and wakes read bits instead of cells.
    EmptyCellBits empty_;
    // Granular only: which cells are INVALID (the vessel and obstacles), kept with every change as
    // empty_, so a wake asks whether a grain lies on the vessel without reading the cell under it
    // (a cache miss: the bits of a grid at res 248 take a megabyte, the cells 30).
    LayoutBits layout_;
    std::vector<StripLog> logs_;                // per strip: the moves of the current sweep
    std::vector<int> turnStrips_;    // granular: the strips of the current layer's turn, even ones first
    std::size_t oddStripsBegin_ = 0; // where the odd ones (the second phase) begin in turnStrips_
    std::vector<StripLog::Cell> turnQueue_;  // granular: the awake cells of a turn one thread sweeps (StripLog::awake)
    // Granular: the cells left in this sweep's turns whose own-layer wakes wait for the sweep's
    // end, when most of them are taken again (the grain above fell in) and wake nobody.
    std::vector<Int3> leftEarlier_;
    std::int64_t speedChangesLastSweep_ = 0;
    MoveFeed feed_;
    std::vector<std::uint8_t> rowAwake_; // 1 when a row may hold awake bits
    // Granular: the timers of the sleeping gatherers and riders, the cells to wake at step s in
    // [s % kTimerSlots], woken as the sweep of step s begins, before any visit; and how many
    // sleep, each of whose fall changes every step (speedChangesLastSweep). A sleep lasts at most
    // 44 steps (a fall from rest at the smallest gravity, 0.001); stepsOnlyGathering stops at
    // kLongestSleep all the same, so the ring could not wrap under a longer one.
    static constexpr int kTimerSlots = 64, kLongestSleep = kTimerSlots - 1;
    std::array<std::vector<StripLog::SleeperCell>, kTimerSlots> timers_;
    std::int64_t fallsAsleep_ = 0;
    void forgetSleepingFalls();
    void wakeIfInMotion(int x, int y, int z); // an edit next to a grain that may sleep in its fall
};

} // namespace sandcore
