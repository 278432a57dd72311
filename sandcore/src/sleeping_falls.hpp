// SPDX-License-Identifier: MIT
#pragma once
// Granular: the grains asleep in their fall, and the bits that tell which grains may be in motion
// at all. Private to sandcore; grid_sweep.hpp says why a grain may sleep while it falls.

#include "awake_cells.hpp"
#include "sweep_context.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace sandcore {

/// Granular, per 64 cells of a row as AwakeCells::Word (the same index finds both): the cells
/// whose grain may be in motion (a visit reads a grain's fall state by id, a cache miss, and most
/// visited grains are at rest), and the grains visited in this step before their layer's turn
/// (carried up their column: that turn skips them and leaves them awake for the next step). Side
/// by side, the turn's queue takes the second and finds the first in the same cache line.
struct MotionWord {
    std::uint64_t inMotion = 0;
    std::uint64_t carriedEarly = 0;
};

/// Wakes the grain in (x, y, z) when it sleeps in its fall (in motion, its occupied bit clear).
inline void wakeFallAsleepAt(AwakeCells& awake, const MotionWord* motion, int x, int y, int z) {
    const std::size_t word = awake.wordOf(awake.rowOf(y, z), x);
    if ((motion[word].inMotion & ~awake.words()[word].occupied) >> (x & 63) & 1) awake.wakeAt(x, y, z);
}

/// Wakes the grains asleep in their fall (in motion, their occupied bit clear) in the 8 cells
/// around (x, y, z), which a grain just entered: from the next step it may dive under one of them
/// (GranularRules::slide), which the visits a sleeping gatherer skips would have seen. A gatherer
/// falls asleep only with none of those cells holding a grain (GranularStep), so this is every way
/// a diver can come next to one.
inline void wakeFallsAsleepAround(AwakeCells& awake, const MotionWord* motion, int x, int y, int z) {
    const Int3 size = awake.size();
    for (int zz = std::max(z - 1, 0); zz <= std::min(z + 1, size.z - 1); ++zz)
        for (int xx = std::max(x - 1, 0); xx <= std::min(x + 1, size.x - 1); ++xx) {
            wakeFallAsleepAt(awake, motion, xx, y, zz);
        }
}

/// The timers of the gatherers and riders asleep in their fall: the cells to wake at step s lie
/// in slot s % kSlots, woken as the sweep of step s begins, before any visit.
class FallTimers {
public:
    /// A sleep lasts at most 44 steps (a fall from rest at the smallest gravity, 0.001), and
    /// GranularRules::stepsOnlyGathering stops at kLongestSleep all the same, so the ring of
    /// slots cannot wrap.
    static constexpr int kSlots = 64, kLongestSleep = kSlots - 1;

    /// Wakes the sleepers whose timer ends at `step`, as its sweep begins.
    void wakeDue(std::uint64_t step, AwakeCells& awake);
    /// After the sweep: sets the timers of the grains that fell asleep in it (logged per strip),
    /// counts those that woke, and returns the grains whose fall changed without a move: those
    /// the strips counted, and every one that slept through the sweep (its fall changes every step).
    std::int64_t endSweep(std::span<StripLog> logs);
    /// No grain sleeps any more: the caller has set every fall state (restore, reset, new rules).
    void forget(std::span<StripLog> logs);
    /// A sleeping grain left the grid from outside a step.
    void sleeperRemoved() { --asleep_; }

private:
    std::array<std::vector<StripLog::SleeperCell>, kSlots> timers_;
    std::int64_t asleep_ = 0;       // grains asleep in their fall
    std::int64_t asleepAtStart_ = 0; // as the current sweep began
};

} // namespace sandcore
