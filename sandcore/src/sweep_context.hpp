// SPDX-License-Identifier: MIT
#pragma once
// What one grid's sweep shares with its strips, and what each strip keeps of its own (R3, R6).
// Private to sandcore; grid_sweep.hpp tells the order the sweep visits cells in.

#include "move_feed.hpp"
#include "sandcore/cell_grid.hpp"
#include "sandcore/grain_store.hpp"

#include <cstdint>
#include <vector>

namespace sandcore {

/// Rows of a strip: the unit of work that threads share within a layer's turn.
inline constexpr int kStripRows = 8;

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
    /// threads share the phase's strips (a turn on one thread has a queue of its own), in
    /// visiting order. It has room for every cell of the strip and is filled from the front
    /// through a plain pointer, the count kept by the loop.
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
    /// Granular: grains visited while carried by the grain below (granular_step.hpp), since the
    /// strip loop that swept this strip last counted them.
    std::int64_t carried = 0;
};

struct SweepResult {
    std::int64_t moves = 0;   ///< grains moved
    std::int64_t visited = 0; ///< cells looked at

    SweepResult& operator+=(const SweepResult& other) {
        moves += other.moves;
        visited += other.visited;
        return *this;
    }
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
    /// When set (the two grids swept side by side), a move writes no grain record and lists no
    /// id: it is fed here for the thread that writes the records (move_feed.hpp).
    MoveFeed* feed;
    /// When set (a sweep on one thread that writes records at once), the moves are appended here
    /// directly instead of to the strips' logs.
    std::vector<GrainMove>* movedList;
};

/// A move's grain record: written and listed here, or fed to the thread that writes the records.
inline void recordMove(const SweepContext& context, StripLog& log, const GrainMove& move) {
    if (context.feed) {
        context.feed->push(move);
        return;
    }
    context.grains.recordMove(move.grain, move.cell, move.cameFrom, context.step);
    (context.movedList ? *context.movedList : log.moved).push_back(move);
}

} // namespace sandcore
