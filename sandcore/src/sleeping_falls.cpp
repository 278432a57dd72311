// SPDX-License-Identifier: MIT
#include "sleeping_falls.hpp"

namespace sandcore {

void FallTimers::wakeDue(std::uint64_t step, AwakeCells& awake) {
    asleepAtStart_ = asleep_;
    // A column that falls asleep again in this step puts its riders back to sleep after this.
    std::vector<StripLog::SleeperCell>& due = timers_[std::size_t(step % kSlots)];
    for (const StripLog::SleeperCell& cell : due) {
        AwakeCells::Word& word = awake.rowWords(cell.row)[cell.x >> 6];
        word.awake |= std::uint64_t{1} << (cell.x & 63);
        word.occupied |= std::uint64_t{1} << (cell.x & 63);
        awake.rowFlags()[cell.row] = 1;
    }
    due.clear();
}

std::int64_t FallTimers::endSweep(std::span<StripLog> logs) {
    std::int64_t ended = 0, speedChanges = 0;
    for (StripLog& log : logs) {
        speedChanges += log.speedChanges;
        log.speedChanges = 0;
        ended += log.sleepsEnded;
        log.sleepsEnded = 0;
        for (const StripLog::Sleeper& sleeper : log.sleepers)
            timers_[std::size_t(sleeper.wakeStep % kSlots)].push_back(sleeper.cell);
        asleep_ += std::int64_t(log.sleepers.size());
        log.sleepers.clear();
    }
    asleep_ -= ended;
    return speedChanges + asleepAtStart_ - ended;
}

void FallTimers::forget(std::span<StripLog> logs) {
    for (std::vector<StripLog::SleeperCell>& cells : timers_) cells.clear();
    for (StripLog& log : logs) {
        log.sleepers.clear();
        log.sleepsEnded = 0;
    }
    asleep_ = 0;
}

} // namespace sandcore
