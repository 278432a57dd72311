// SPDX-License-Identifier: MIT
#include "grid_sweep.hpp"

#include "classic_step.hpp"
#include "granular_step.hpp"
#include "granular_wakes.hpp"
#include "worker_pool.hpp"

#include <algorithm>
#include <span>

namespace sandcore {

GridSweep::GridSweep(Int3 gridSize, bool bottomIsOutlet)
    : size_(gridSize), bottomIsOutlet_(bottomIsOutlet), dither_(0, stream()), awake_(gridSize) {
    logs_.resize(std::size_t((gridSize.z + kStripRows - 1) / kStripRows));
    outlet_.setAbove(nullptr, gridSize);
}

void GridSweep::setGranular(const GranularRules* granular) {
    granular_ = granular;
    timers_.forget(logs_); // the scene stops every fall when the rules change
    motion_.assign(granular ? awake_.wordCount() : 0, MotionWord{});
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

GranularSweepState GridSweep::granularState() {
    return {*granular_, dither_, empty_, layout_, awake_, motion_.data(), outlet_, logs_, bottomIsOutlet_};
}

GranularWakes GridSweep::granularWakes(const CellGrid& grid) { return {*granular_, dither_, empty_, layout_, grid, awake_}; }

void GridSweep::grainEntered(int x, int y, int z) {
    if (granular_) {
        empty_.setEmpty(x, y, z, false);
        // A gatherer or rider asleep below now carries it; a gatherer asleep above has lost its
        // EMPTY cell below.
        if (y - 1 >= 1) wakeIfInMotion(x, y - 1, z);
        if (y + 1 < size_.y) wakeIfInMotion(x, y + 1, z);
        wakeFallsAsleepAround(awake_, motion_.data(), x, y, z); // it may dive under one of them
    }
    if (y > 0 || bottomIsOutlet_) wakeAt(x, y, z);
}

// A grain in motion that is not awake sleeps in its fall (grid_sweep.hpp) or rides a moving grain
// that wakes it when its speed changes. Waking either is exact (R5), and an edit next to a
// sleeping gatherer or rider must: what its skipped visits would read has changed.
void GridSweep::wakeIfInMotion(int x, int y, int z) {
    if (motion_[awake_.wordOf(awake_.rowOf(y, z), x)].inMotion >> (x & 63) & 1) wakeAt(x, y, z);
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
    motion_[awake_.wordOf(awake_.rowOf(y, z), x)].inMotion |= std::uint64_t{1} << (x & 63);
}

void GridSweep::wake(std::uint32_t cell) {
    const Int3 c = coordinateOf(cell);
    if (c.y == 0 && !bottomIsOutlet_) return; // the floor has nothing below it: never visited
    wakeAt(c.x, c.y, c.z);
}

void GridSweep::wakeAroundEmptied(const CellGrid& grid, int x, int y, int z) {
    if (granular_) {
        empty_.setEmpty(x, y, z, true);
        layout_.setOpen(grid.index(x, y, z), true); // an obstacle's cell may open so (Scene::clearObstacles)
        granularWakes(grid).aroundEmptied(x, y, z);
        outlet_.emptied(x, y, z);
        if (y + 1 < size_.y) wakeIfInMotion(x, y + 1, z); // a rider asleep there lost its support
    } else {
        wakePredecessorsOf(x, y, z);
        outlet_.emptied(x, y, z);
    }
}

void GridSweep::takeLoggedMoves(std::vector<GrainMove>& moved) {
    for (StripLog& log : logs_) {
        moved.insert(moved.end(), log.moved.begin(), log.moved.end());
        log.moved.clear();
    }
}

void GridSweep::wakeEveryGrain(const CellGrid& grid) {
    const auto cells = grid.cells();
    for (std::uint32_t n = 0; n < cells.size(); ++n)
        if (cells[n] >= 0) wake(n);
}

void GridSweep::clear() {
    awake_.clear();
    std::fill(motion_.begin(), motion_.end(), MotionWord{});
    for (StripLog& log : logs_) {
        log.moved.clear();
        log.carried = 0;
    }
    timers_.forget(logs_); // the caller sets every fall state (restore, reset)
}

SweepResult GridSweep::sweep(const SweepContext& context, WorkerPool* pool) {
    return granular_ ? sweepGranular(context, pool) : sweepClassic(context, pool);
}

namespace {

// Whether the sweep may share a layer's strips between threads at all.
bool threadsShareStrips(const WorkerPool* pool, int sizeZ) {
    return pool && pool->threadCount() > 1 && (sizeZ + kStripRows - 1) / kStripRows > 1;
}

} // namespace

SweepResult GridSweep::sweepClassic(const SweepContext& context, WorkerPool* pool) {
    const int strips = int(logs_.size());
    const bool threaded = threadsShareStrips(pool, size_.z);
    // Each strip on a thread adds to its own totals, summed after the sweep.
    std::vector<SweepResult> stripTotals(threaded ? std::size_t(strips) : 0);
    SweepResult result;
    const ClassicStep step{context, awake_, outlet_, bottomIsOutlet_};
    for (int y = 1; y < size_.y; ++y) {
        // The count of awake rows only decides whether threads share the layer's strips.
        const int awakeRows = !context.sleeping ? size_.z : threaded ? awake_.awakeRowsInLayer(y) : int(awake_.anyRowAwake(y, 0, size_.z));
        if (awakeRows == 0) continue;
        const bool parallel = threaded && awakeRows >= kMinAwakeRowsForThreads;
        for (int phase = 0; phase < 2; ++phase) {
            if (!parallel) {
                for (int strip = phase; strip < strips; strip += 2) result += step.sweepStrip(y, strip, logs_[std::size_t(strip)]);
                continue;
            }
            pool->parallelFor((strips - phase + 1) / 2, [&](int i) {
                const int strip = phase + 2 * i;
                stripTotals[std::size_t(strip)] += step.sweepStrip(y, strip, logs_[std::size_t(strip)]);
            });
        }
    }
    for (const SweepResult& t : stripTotals) result += t;
    return result;
}

SweepResult GridSweep::sweepGranular(const SweepContext& context, WorkerPool* pool) {
    const bool threaded = threadsShareStrips(pool, size_.z);
    std::vector<SweepResult> stripTotals(threaded ? logs_.size() : 0);
    SweepResult result;
    const GranularSweepState state = granularState();
    // The sleepers whose fall reaches a cell in this step (or whose longest sleep ends) wake
    // before any visit.
    timers_.wakeDue(context.step, awake_);
    for (int y = 1; y < size_.y; ++y) {
        // The count of awake rows only decides whether threads share the layer's strips; on one
        // thread, the turn finds an idle layer as it lists the strips.
        const int awakeRows = !context.sleeping ? size_.z : threaded ? awake_.awakeRowsInLayer(y) : 1;
        if (awakeRows == 0) continue;
        turn_.list(awake_, y, context.sleeping);
        if (turn_.empty()) continue; // nothing awake in the layer
        const GranularStep step(context, state, y);
        if (!threaded || awakeRows < kMinAwakeRowsForThreads) {
            // One thread: one queue for the whole turn, even strips then odd, so its visits ask
            // ahead across strips and phases (no visit wakes a cell of its own layer).
            result += step.sweepStrips(turn_.all(), turnQueue_);
        } else {
            for (const std::span<const int> phase : {turn_.even(), turn_.odd()})
                pool->parallelFor(int(phase.size()), [&](int i) {
                    const int strip = phase[std::size_t(i)];
                    stripTotals[std::size_t(strip)] += step.sweepStrips(phase.subspan(std::size_t(i), 1), logs_[std::size_t(strip)].awake);
                });
        }
        endGranularTurn(y, turn_.all(), state, leftEarlier_);
    }
    wakeAroundCellsLeft(granularWakes(context.grid), leftEarlier_);
    // Each gatherer or rider that slept through this step changed its fall without a visit.
    speedChangesLastSweep_ = timers_.endSweep(logs_);
    for (const SweepResult& t : stripTotals) result += t;
    return result;
}

} // namespace sandcore
