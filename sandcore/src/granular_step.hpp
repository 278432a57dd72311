// SPDX-License-Identifier: MIT
#pragma once
// The granular rules (granular_rules.hpp) applied by the sweep: one layer's turn over a list of
// its strips, and what each visit keeps up to date besides the cells (the EMPTY bits, the awake
// and in-motion bits, the sleepers in their fall, the riders carried up a column). Private to
// sandcore; grid_sweep.hpp tells the visiting order and why a grain may sleep in its fall.

#include "awake_cells.hpp"
#include "empty_cells.hpp"
#include "granular_rules.hpp"
#include "granular_wakes.hpp"
#include "layout_bits.hpp"
#include "sleeping_falls.hpp"
#include "sweep_context.hpp"
#include "threshold_dither.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace sandcore {

/// How many visits ahead the granular strip loop asks for a cell (and the one below it), and for
/// the fall state of the grain in it: far enough that the loads of several visits are in flight
/// together, near enough that they are still in the cache when their visit comes.
inline constexpr std::size_t kCellsAhead = 8, kStatesAhead = 4;

/// What a grid's sweep keeps for the granular visits besides the cells (GridSweep owns it all).
struct GranularSweepState {
    const GranularRules& rules;
    const ThresholdDither& dither; ///< the grid's under the seed: the visits' and the wakes'
    EmptyCellBits& empty;
    const LayoutBits& layout;
    AwakeCells& awake;
    MotionWord* motion; ///< one per word of `awake`
    OutletWakes& outlet;
    std::span<StripLog> logs; ///< one per strip
    bool bottomIsOutlet;      ///< layer 0 is the outlet row (the upper grid)
};

/// The granular visits of one layer's turn, or of one strip of it where threads share the
/// turn's strips. What every visit reads is gathered here once per turn, read through one
/// pointer instead of through the sweep's members and their vectors.
class GranularStep {
public:
    GranularStep(const SweepContext& context, const GranularSweepState& state, int y);

    /// Visits the awake cells (every cell, when not sleeping) of `strips` of the layer, one
    /// strip after another, in the step's visiting order (grid_sweep.hpp). `queue`: where the
    /// awake cells are listed before the first visit, grown as needed.
    SweepResult sweepStrips(std::span<const int> strips, std::vector<StripLog::Cell>& queue) const;

private:
    /// The cell a visit looks at, with what the strip loop knows of it.
    struct VisitedCell {
        int x, z;
        std::uint32_t row;   ///< y * sizeZ + z
        bool mayBeMoving;    ///< the cell's in-motion bit
    };
    /// What a visit did: GranularOutcome::Kind (Resting for a cell without a grain), and
    /// whether a grain in motion came to rest.
    struct Visit {
        GranularOutcome::Kind kind;
        bool stopped;
    };
    Visit visit(StripLog& log, const VisitedCell& cell) const;
    std::uint64_t fallAsleepGathering(StripLog& log, const VisitedCell& cell, std::uint32_t from) const;
    /// The grains riding on the grain of `cell`, which stays there moving at `speed`.
    struct Column {
        const VisitedCell& base;
        std::uint32_t from;        ///< the base's cell index
        std::uint32_t speed;       ///< > 0
        std::uint64_t asleepUntil; ///< the step the base's timer wakes it, or 0 when it stays awake
    };
    int carryRiders(StripLog& log, const Column& column) const;
    void markInMotion(Int3 cell) const {
        const std::size_t row = std::size_t(cell.y) * std::size_t(sizeZ_) + std::size_t(cell.z);
        motion_[row * std::size_t(rowWords_) + std::size_t(cell.x >> 6)].inMotion |= std::uint64_t{1} << (cell.x & 63);
    }

    const SweepContext& context_;
    const GranularRules& rules_;
    EmptyCellBits& empty_;
    AwakeCells& awake_;
    OutletWakes& outlet_;
    std::span<StripLog> logs_;
    GranularContext on_; // what GranularRules::visit reads
    GranularWakes wakes_;
    CellValue* cells_;
    AwakeCells::Word* words_;
    MotionWord* motion_;
    std::uint8_t* rowAwake_;
    std::size_t layerWords_; // words of awake and in-motion bits per layer
    int y_, sizeX_, sizeY_, sizeZ_, rowWords_;
    bool bottomIsOutlet_;
};

/// Granular, at the end of layer y's turn: the cells its grains left (logged by `strips`) become
/// EMPTY in the kept bits, and are listed in `leftEarlier` for wakeAroundCellsLeft.
void endGranularTurn(int y, std::span<const int> strips, const GranularSweepState& state, std::vector<Int3>& leftEarlier);
/// Granular, at the end of the sweep: the own-layer wakes of the cells left in its turns that
/// are still EMPTY; empties `left`.
void wakeAroundCellsLeft(GranularWakes wakes, std::vector<Int3>& left);

} // namespace sandcore
