// SPDX-License-Identifier: MIT
#pragma once
// How a layer's turn is shared between threads (R6). The layer's rows are cut into strips of
// kStripRows; the even strips are swept first, then the odd ones. A visit reads and writes cells
// and bits only a few rows from its own (classic: 1, granular: kGranularReach, the 7x7 windows of
// its slides and wakes), less than a strip, so strips of one phase never touch each other's
// cells or bits and may run on different threads in any order; the phases follow one another,
// so the result is the same for any thread count. Private to sandcore.

#include "awake_cells.hpp"
#include "granular_rules.hpp"
#include "sweep_context.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace sandcore {

// A word of bits holds 64 cells of one row: two strips of a phase must never come within a
// visit's reach of each other's rows.
static_assert(kStripRows >= 2 * kGranularReach + 1, "strips of one phase would share rows");

/// Below this many awake rows in a layer, handing strips to other threads costs more than it saves.
inline constexpr int kMinAwakeRowsForThreads = 24;

/// The strips of one layer's turn that hold awake rows (every strip in a full sweep), even ones
/// first. A strip without any has nothing to visit in the turn, and nothing can wake its rows
/// before the turn ends (the strips running beside it keep apart, the layers below are done, and
/// a strip of the other phase runs before or after it), so it is left out whole: most strips of
/// a busy layer are idle. Listed once, the phases, the carried counts and the turn's end go over
/// those only.
class TurnStrips {
public:
    void list(const AwakeCells& awake, int y, bool sleeping) {
        const int sizeZ = awake.size().z, strips = (sizeZ + kStripRows - 1) / kStripRows;
        strips_.clear();
        for (int phase = 0; phase < 2; ++phase) {
            if (phase == 1) oddBegin_ = strips_.size();
            for (int strip = phase; strip < strips; strip += 2)
                if (!sleeping || awake.anyRowAwake(y, strip * kStripRows, std::min((strip + 1) * kStripRows, sizeZ)))
                    strips_.push_back(strip);
        }
    }
    bool empty() const { return strips_.empty(); }
    std::span<const int> all() const { return strips_; }   ///< both phases, in turn order
    std::span<const int> even() const { return all().first(oddBegin_); }
    std::span<const int> odd() const { return all().subspan(oddBegin_); }

private:
    std::vector<int> strips_;
    std::size_t oddBegin_ = 0; // where the odd ones (the second phase) begin
};

} // namespace sandcore
