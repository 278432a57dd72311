// SPDX-License-Identifier: MIT
#pragma once
// The bottom-up sweep of one grid (R3) over its awake grains (R5), shared by threads (R6).
// Private to sandcore.
//
// Canonical visiting order, the same for every thread count: layers from the bottom up; within
// a layer, strips of kStripRows rows in two phases (even strips, then odd strips); within a strip,
// rows by ascending z and cells by ascending x (granular: z and x turned by bits 1 and 0 of the
// step number, so cones do not lean; granular_step.cpp). A grain in row z only reads and writes
// rows z-1..z+1 of the layers next to it (granular: z-3..z+3, still less than a strip), so strips
// of one phase never touch each other's cells or bits and may run on different threads in any
// order (strip_phases.hpp).
// Under both rule sets a visit wakes no cell of its own layer for the same step: the classic
// rules read only the layer below, and the granular paths read their layer as it was when its
// turn began (granular_rules.hpp), so a layer's awake bits are final when its turn begins.
// A granular visit of a grain that stays where it is, moving, also visits the grains that ride
// on it in the column above (GranularStep::carryRiders), in the same strip's rows; their layers' turns then
// skip them.
// A granular grain falling through an EMPTY cell short of its next cell (a gatherer), and the
// column riding on it, sleep until the step its fall reaches that cell (a timer wakes them;
// sleeping_falls.hpp),
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
//
// The jobs lie in files of their own: the classic visits (classic_step.hpp), the granular ones
// (granular_step.hpp) and whom a granular move wakes (granular_wakes.hpp), the awake bits
// (awake_cells.hpp) and the sleepers' timers (sleeping_falls.hpp), the strips that threads share
// (strip_phases.hpp). GridSweep owns what they keep and runs the layers' turns.

#include "awake_cells.hpp"
#include "empty_cells.hpp"
#include "granular_rules.hpp"
#include "move_feed.hpp"
#include "sleeping_falls.hpp"
#include "strip_phases.hpp"
#include "sweep_context.hpp"
#include "threshold_dither.hpp"
#include "sandcore/cell_grid.hpp"
#include "sandcore/large_pages.hpp"
#include "layout_bits.hpp"

#include <cstdint>
#include <vector>

namespace sandcore {

class WorkerPool;
struct GranularSweepState;
struct GranularWakes;

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
    void wake(std::uint32_t cell);                                     ///< the cell is visited in its layer's next turn
    void wakeAt(int x, int y, int z) { awake_.wakeAt(x, y, z); }       ///< as wake, by coordinate
    void wakePredecessorsOf(int x, int y, int z) { awake_.wakePredecessorsOf(x, y, z); } ///< the 9 cells above (x, y, z)
    /// A grain left (x, y, z) of grid: wakes every grain whose options that can widen (classic:
    /// the 9 cells above; granular: granular_wakes.hpp), and the outlet cell of the grid above
    /// when (x, y, z) lies in the top layer. Every way a cell empties goes through here (R5).
    void wakeAroundEmptied(const CellGrid& grid, int x, int y, int z);
    void wakeEveryGrain(const CellGrid& grid); ///< after edits that bypass the rules
    void clear();                               ///< nothing awake, no gatherer asleep
    /// Granular: a sleeping gatherer or rider (FallState::gatheringSince) left the grid from
    /// outside a step.
    void sleepingFallRemoved() { timers_.sleeperRemoved(); }

    /// When set, a cell of this grid's top layer that empties wakes the cell of `above`'s
    /// layer 0 at the same x and z (the lower grid wakes the upper grid's outlet row).
    void setGridAbove(GridSweep* above) { outlet_.setAbove(above ? &above->awake_ : nullptr, size_); }
    /// While deferred, those wakes are kept until applyDeferredWakes(), so the grid above may
    /// be swept at the same time on another thread.
    void setDeferWakesAbove(bool defer) { outlet_.setDeferred(defer); }
    /// Applies the wakes kept while deferred.
    void applyDeferredWakes() { outlet_.applyDeferred(); }
    /// The feed a side-by-side sweep of this grid fills (SweepContext::feed).
    MoveFeed& feed() { return feed_; }
    /// Appends the moves the last sweep logged to `moved` and empties the logs. Each grain is
    /// listed at most once: every move goes down at least a layer, and each layer is visited once.
    void takeLoggedMoves(std::vector<GrainMove>& moved);
    /// Granular: the grains whose fall the last sweep changed without moving them (a grain
    /// gathering its next cell, riding a moving grain, or stopping).
    std::int64_t speedChangesLastSweep() const { return speedChangesLastSweep_; }
    /// Rows (of all layers) that may hold awake cells: a cheap measure of the next sweep's work.
    std::int64_t awakeRowCount() const { return awake_.awakeRowCount(); }

    /// Applies the rules to layers 1..top of context.grid, bottom-up; pool (may be null) shares
    /// busy layers' strips between threads.
    SweepResult sweep(const SweepContext& context, WorkerPool* pool);

    /// Calls visit(cell) for every cell of layer 0 that is awake (or every cell, when not
    /// sleeping), in index order, and puts them to sleep.
    template <class Visit> void forEachInBottomLayer(bool sleeping, Visit&& visit) {
        awake_.forEachInBottomLayer(sleeping, visit);
    }

private:
    SweepResult sweepClassic(const SweepContext& context, WorkerPool* pool);
    SweepResult sweepGranular(const SweepContext& context, WorkerPool* pool);
    GranularSweepState granularState();
    GranularWakes granularWakes(const CellGrid& grid);
    Int3 coordinateOf(std::uint32_t cell) const; // as CellGrid::coordinate, for this sweep's grid
    void wakeIfInMotion(int x, int y, int z);    // an edit next to a grain that may sleep in its fall
    // The grid's stream of random draws (SweepContext::level): the upper grid is the one with an outlet.
    std::uint64_t stream() const { return std::uint64_t(bottomIsOutlet_ ? GridLevel::Upper : GridLevel::Lower); }

    Int3 size_;
    bool bottomIsOutlet_;
    const GranularRules* granular_ = nullptr;
    ThresholdDither dither_; // the granular thresholds' under the seed (seed 0 until setSeed)
    AwakeCells awake_;
    OutletWakes outlet_;
    std::vector<StripLog> logs_; // per strip: the moves of the current sweep
    MoveFeed feed_;
    // Granular only: which grains may be in motion, per word of awake_ (sleeping_falls.hpp).
    std::vector<MotionWord, LargePageAllocator<MotionWord>> motion_;
    // Granular only: which cells are EMPTY, kept with every change of a cell (moves, the scene's
    // edits through the calls above), so slides and wakes read bits instead of cells.
    EmptyCellBits empty_;
    // Granular only: which cells are INVALID (the vessel and obstacles), kept with every change as
    // empty_, so a wake asks whether a grain lies on the vessel without reading the cell under it
    // (the bits take a thirty-second of the cells' memory, so they stay in the cache).
    LayoutBits layout_;
    TurnStrips turn_;                          // granular: the strips of the current layer's turn
    std::vector<StripLog::Cell> turnQueue_;    // granular: the awake cells of a turn one thread sweeps (StripLog::awake)
    // Granular: the cells left in this sweep's turns whose own-layer wakes wait for the sweep's
    // end, when most of them are taken again (the grain above fell in) and wake nobody.
    std::vector<Int3> leftEarlier_;
    FallTimers timers_;
    std::int64_t speedChangesLastSweep_ = 0;
};

} // namespace sandcore
