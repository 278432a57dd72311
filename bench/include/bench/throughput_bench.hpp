// SPDX-License-Identifier: MIT
#pragma once
// Moves per second of the hourglass drain on 1 and N threads, next to what the machine's memory
// can do at all (measured here, briefly): the distance to the physical limit (issue: two cores).

#include "bench/report_files.hpp"

#include "sandcore/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sandbench {

/// What the memory system gives, measured on buffers larger than the caches.
struct MemoryCeiling {
    std::size_t bufferBytes = 0;      ///< size of the buffer each measure runs over
    double copyGigabytesPerSecond = 0; ///< bytes read plus bytes written per second by memcpy, best of three
    int threads = 1;                   ///< threads of the second random-write measure
    double randomWritesPerSecond = 0;  ///< 4-byte writes to random places, 1 thread
    double randomWritesPerSecondThreads = 0; ///< the same on `threads` threads together
};

/// Measures the ceiling on a buffer of bufferBytes (take several times the last-level cache;
/// 256 MiB takes about a second in all).
MemoryCeiling measureMemoryCeiling(std::size_t bufferBytes, int threads);

/// Moves per second of one drain of the procedural hourglass until settled.
struct MoveRate {
    int resolution = 0;
    int threads = 1;
    std::int64_t grains = 0;
    std::int64_t steps = 0;
    std::int64_t moves = 0;     ///< grains moved over the whole drain, transitions included
    double stepSeconds = 0;     ///< time inside Scene::step over the whole drain
    double medianMs = 0;        ///< median milliseconds per step
    double movesPerSecond = 0;  ///< moves / stepSeconds
    std::uint64_t hash = 0;     ///< state hash once settled
};

/// Drains the hourglass at this resolution once per thread count (sleeping on, the seed and the
/// rules of `step`), the runs taking turns of a few steps in one process so they share the
/// machine's conditions.
std::vector<MoveRate> measureMoveRates(int resolution, const std::vector<int>& threads, const sandcore::StepSettings& step);

/// The rates next to the ceiling: per run, moves per second and how many random writes per move
/// the machine could have done in the same time (1 thread: the 1-thread rate, more: the N-thread rate).
Table moveRateTable(const std::vector<MoveRate>& runs, const MemoryCeiling& ceiling);
/// The ceiling as a table.
Table ceilingTable(const MemoryCeiling& ceiling);

} // namespace sandbench
