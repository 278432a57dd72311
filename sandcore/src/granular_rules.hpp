// SPDX-License-Identifier: MIT
#pragma once
// The granular rules (SPEC PH2, PH3), private to sandcore. Applied to a grain at (x, y, z):
//
// 1. fall: if the cell below is EMPTY the grain falls with a 16.16 fixed-point speed that grows
//    by g each step, as far as its speed carries it this step, checking every cell of the path
//    (a one-cell obstacle stops it at any speed, as The Powder Toy does). On contact it takes the
//    speed of a moving grain it lands on, or stops; reaching a slower grain in motion, it glances
//    off it instead when it can, into an EMPTY cell beside it a layer lower, keeping its speed
//    (deflected), so a stream spreads instead of jamming. A grain resting on a moving grain moves with
//    it: it takes its speed and gathers up to a cell of progress, so a column flows as one.
// 2. slide: a grain resting on something at rest may move to the cell one layer down in any
//    column up to 3 cells away (48 offsets e) when the sideways path at its own level is clear
//    (for one of the 8 columns next to it, a dive, only the vessel blocks the path: a grain there
//    lies over the EMPTY target and carries nothing)
//    and the column there is at least `need` cells deep, need = floor(T|e| + u): T a calibrated
//    slope and u in [0, 1) fixed per column and offset (ThresholdDither: blue noise, picked by
//    the seed) that never changes with the step, so a grain that wakes up meets the same
//    threshold and piles do not creep (PH2). The dither makes the angle continuous in T instead
//    of locked to integer heights. Every move goes down at
//    least one layer, so grains never swap back and forth. One of the possible moves is chosen
//    by a counter hash of (seed, step, grid, cell) (R3).
//    A grain lying on the vessel (an INVALID cell below it) slides on the glass, which is smoother
//    than the sand: any free cell one layer down within reach will do (need = 1). The vessel's
//    walls are carved so that every inside cell has one in the 3x3 below it (removeSharpEdges),
//    so no grain is left on a ledge of the glass and the bulb empties, as with the classic rules.
//
// What a grain reads, so the sweep can keep threads apart and wake exactly the grains whose
// options a change can widen (R5, R6): its own column downwards and the speed of the grain
// below it; cells of its own layer within 3 columns (the paths); and the 7x7 columns of the
// layers up to maxDrop() below it. A falling grain that reaches a slower one also reads the 8
// cells beside the cell it would stop in and those under them, in the step it moves.
//
// The paths read the grain's layer as it was when the layer's turn in the sweep began: a cell
// that a grain of the same layer leaves in this step opens paths from the next step on (the
// EmptyCellBits the slides read are updated at the end of the turn). So within a layer no grain
// slides through a gap opened a moment before in the sweep's order, and a cell that is left and
// filled again in one step (a column moving down a cell: the grain above falls in) opens no path
// at all and wakes nobody in its layer. The layers below, the targets and columns, are read as
// they are: two grains of one layer never enter the same cell.

#include "empty_cells.hpp"
#include "threshold_dither.hpp"
#include "sandcore/cell_grid.hpp"
#include "sandcore/counter_random.hpp"
#include "sandcore/grain_store.hpp"
#include "sandcore/physics_settings.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

namespace sandcore {

/// FallState::gatheringSince: 0, or kGatheringAsleep plus the step (kAsleepStepMask of it) after
/// which a grain falling through an EMPTY cell short of its next cell, or riding such a grain
/// (kRidingAsleep), stopped being visited: speed and fraction are as of that step, and only
/// gravity changes them until the step the fall reaches the cell, when it is visited again
/// (grid_sweep.hpp says why a grain may sleep while it falls).
inline constexpr std::uint16_t kGatheringAsleep = 0x8000, kRidingAsleep = 0x4000;
inline constexpr std::uint16_t kAsleepStepMask = 0x1fff; ///< the step's bits in FallState::gatheringSince

/// One cell in the 16.16 fixed point of fall speeds and fractions.
inline constexpr std::uint32_t kOneCell = 1u << 16;

/// How far sideways a granular grain may slide, cells (Chebyshev distance).
inline constexpr int kGranularReach = 3;

/// What a visit did, so the sweep knows whom to wake.
struct GranularOutcome {
    enum Kind : std::uint8_t {
        Resting, ///< nothing can move it: it sleeps until a cell it reads empties
        Waiting, ///< it did not change cells but is in motion (speed or fraction grew): keep it awake
        Moved,   ///< it moved to `to`
        Riding,  ///< it rides a moving grain and nothing of it changed: it sleeps until the one below
                 ///< changes speed or leaves (both wake it), so a held column is not visited every step
    } kind = Resting;
    Int3 to{};   ///< the cell it moved to (Moved only)
    MoveCode cameFrom = kNoMove; ///< offset from `to` back to the cell it left (Moved only): its record's
    bool stopped = false; ///< Resting only: it was in motion and stopped, so whoever rides it must look again
    bool inMotion = false; ///< its fall state (speed or fraction) is not zero after the visit
};

/// What the sweep knows of the fall states around a visit without reading them: a grain whose
/// cell's bit is clear is at rest (speed and fraction 0), so its state need not be read.
struct MotionHints {
    bool grain = true; ///< the visited grain may be in motion
    bool below = true; ///< the grain below it, if any, may be in motion
};

/// What every granular visit of one grid's sweep reads alike, set up once per list of strips.
struct GranularContext {
    CellGrid& grid;                ///< the grid; a move changes its cells only (the sweep writes the record)
    const EmptyCellBits& empty;    ///< the grid's EMPTY cells as bits, up to date: the slides read their windows there
    std::span<FallState> falls;    ///< the fall states of the grid's grains (GrainStore::fall of its level)
    const ThresholdDither& dither; ///< the grid's under the seed
    std::uint64_t stepKey;         ///< counterRandomStepKey of this step
    std::uint64_t stream;          ///< tells the grids apart in the random draws
    std::uint64_t step;            ///< this step's number: a grain landing on a sleeping gatherer reads it caughtUp to it
    bool bottomIsOutlet;           ///< layer 0 is open below (the upper grid): a grain falling onto it keeps its speed
};

/// The cell of the grain a visit applies the rules to, and its index in the grid.
struct GrainCell {
    int x, y, z;
    std::uint32_t index; ///< grid.index(x, y, z)
};

/// The tables the granular rules need, computed once from PhysicsSettings.
class GranularRules {
public:
    /// Cells per side of the window a slide looks at.
    static constexpr int kWindow = 2 * kGranularReach + 1;

    explicit GranularRules(const PhysicsSettings& physics);

    /// Applies the rules to the grain in cell `at` (y >= 1) of on.grid. A move changes the grid's
    /// cells only: the caller writes the grain's record from the outcome and updates the EMPTY
    /// bits. hints: which fall states are known to be zero (the result is the same; only fewer
    /// states are read). The visited grain's own state must be up to date (not asleep).
    GranularOutcome visit(const GranularContext& on, GrainCell at, MotionHints hints = {}) const;

    /// A grain resting on a grain that moves at `speed` (> 0) rides it: it takes that speed and
    /// gathers up to a cell of progress (rule 1). Riding when nothing of it changed (it may sleep:
    /// the grain below wakes it when it changes speed or leaves), else Waiting. mayBeMoving: its
    /// own state may be non-zero (else it is read as at rest); maySleep: false on the outlet row
    /// of the upper grid, whose speeds the transition sets without a visit.
    GranularOutcome::Kind ride(FallState& own, std::uint32_t speed, bool mayBeMoving, bool maySleep) const {
        const FallState before = mayBeMoving ? own : FallState{};
        const auto fraction = std::uint16_t(std::min<std::uint32_t>(before.fraction + speed + gravity_ / 2, kOneCell - 1));
        if (speed == before.speed && fraction == before.fraction && maySleep) return GranularOutcome::Riding;
        own = {speed, fraction};
        return GranularOutcome::Waiting;
    }

    /// A grain's state after step `step`: its own, or, where it sleeps (FallState::gatheringSince),
    /// the state it stored advanced by the steps since, in the same integers as the visits that
    /// were skipped. A gatherer's each added its mean speed to its fraction and g to its speed
    /// (fall's rule while nothing is reached: x(n) = g n^2 / 2 + v n); a rider's took the gatherer's
    /// new speed, g more each step, and added it and g / 2 to its fraction, up to a cell (ride).
    FallState caughtUp(const FallState& state, std::uint64_t step) const {
        if (!(state.gatheringSince & kGatheringAsleep)) return state;
        const std::uint32_t n = (std::uint32_t(step) - state.gatheringSince) & kAsleepStepMask;
        // The speeds the gatherer started the n steps with: v, v + g, ..., v + (n - 1) g.
        const std::uint32_t gathered = state.fraction + n * state.speed + n * (gravity_ / 2) + gravity_ * (n * (n - 1) / 2);
        if (!(state.gatheringSince & kRidingAsleep)) return {state.speed + n * gravity_, std::uint16_t(gathered), 0};
        // A rider takes each step's new speed, g more than the gatherer started it with.
        return {state.speed + n * gravity_, std::uint16_t(std::min<std::uint32_t>(gathered + n * gravity_, kOneCell - 1)), 0};
    }
    /// How many of the next steps, at most `limit`, a grain falling with this state through an
    /// EMPTY cell only gathers, before the step whose travel reaches that cell.
    int stepsOnlyGathering(const FallState& state, int limit) const {
        std::uint32_t speed = state.speed, fraction = state.fraction;
        int steps = 0;
        for (; steps < limit; ++steps) {
            fraction += speed + gravity_ / 2;
            if (fraction >= kOneCell) break;
            speed += gravity_;
        }
        return steps;
    }

    /// Deepest column a slide ever looks into, cells below the grain's layer.
    int maxDrop() const { return maxDrop_; }
    /// The grains that an EMPTY cell c may let move, `layersAbove` (0..maxDrop()) layers above c:
    /// bit (dz + 3) * 7 + (dx + 3) stands for the grain at c + (dx, dz) in that layer.
    std::uint64_t wakeMask(int layersAbove) const { return wakeMasks_[std::size_t(layersAbove)]; }
    /// Paths in a 7x7 window as a table: [r][taken] holds the paths (one bit each) that cross one of
    /// the cells `taken` (7 bits) of window row r, so a window's blocked paths are 7 look-ups.
    using RowBlockTable = std::array<std::array<std::uint64_t, 1u << kWindow>, kWindow>;
    /// The paths of `table` that cross a cell outside `clear` (a window's EMPTY cells), for tables
    /// whose paths cross only rows FirstRow..LastRow of the window.
    template <int FirstRow = 0, int LastRow = kWindow - 1>
    static std::uint64_t blockedIn(const RowBlockTable& table, std::uint64_t clear) {
        std::uint64_t blocked = 0;
        for (int r = FirstRow; r <= LastRow; ++r)
            blocked |= table[std::size_t(r)][~(clear >> (r * kWindow)) & ((1u << kWindow) - 1)];
        return blocked;
    }

    /// Cells of the layer below a cell c that a slide across c may end in: every path across c
    /// ends within kAcrossReach columns of c's (it runs on from c towards its target).
    static constexpr int kAcrossReach = kGranularReach - 1;
    static constexpr int kAcrossWindow = 2 * kAcrossReach + 1;
    /// Of the grains `among` around c (window bits as in wakeMask), those with a slide across c
    /// into the column t = (tdz + 2) * 5 + (tdx + 2) around it whose path at their level is EMPTY
    /// (inside `clear`, the EMPTY cells of the layer's 7x7 window around c, where all such paths
    /// lie): a grain has at most one slide into a given column. Every slide into c's own column
    /// crosses c (its path ends there), so those are the paths towards the centre, five look-ups;
    /// into any other column at most 8 grains slide across c, and each one's path is the slide's
    /// own, moved to where the grain lies. Nothing is read when no grain of `among` has such a slide.
    std::uint64_t grainsWithOpenSlideAcrossCentreTo(int t, std::uint64_t among, std::uint64_t clear) const {
        std::uint64_t grains = slidesAcrossCentreTo_[std::size_t(t)] & among;
        if (!grains) return 0;
        if (t == kAcrossCentre) return grains & ~blockedTowardsCentre(clear);
        const auto& paths = pathsAcrossCentreInto_[std::size_t(t)];
        const auto& slots = slotAcrossCentreInto_[std::size_t(t)];
        std::uint64_t open = 0;
        for (; grains; grains &= grains - 1) {
            const int bit = std::countr_zero(grains);
            if (!(paths[slots[std::size_t(bit)]] & ~clear)) open |= std::uint64_t{1} << bit;
        }
        return open;
    }
    /// The columns t of the 5x5 under c (bits as in grainsWithOpenSlideAcrossCentreTo) into which
    /// some grain of `among` (window bits) has a slide across c: seven look-ups, so a wake asks
    /// about those columns only.
    std::uint32_t targetsAcrossCentreOf(std::uint64_t among) const {
        std::uint32_t targets = 0;
        for (int r = 0; r < kWindow; ++r)
            targets |= targetsAcrossCentreByRow_[std::size_t(r)][(among >> (r * kWindow)) & ((1u << kWindow) - 1)];
        return targets;
    }
    /// Of the grains around a column c (window bits as in wakeMask), those whose slide into c's
    /// column crosses only EMPTY cells at their level (inside `clear`, as above).
    std::uint64_t grainsWithOpenPathTowardsCentre(std::uint64_t clear) const {
        return ~blockedTowardsCentre(clear) & ((std::uint64_t{1} << (kWindow * kWindow)) - 1);
    }
    /// True when a grain in column (x, z) of the grid whose dither is `dither` (off the vessel)
    /// needs the column of slide k at least `depth` >= 2 cells deep: the dither of its threshold
    /// is fixed per column and offset, so a wake can tell that a cell emptied deeper down is none
    /// of its business. Inline: the wakes ask it for many grains, most of which it answers from
    /// the threshold alone.
    bool needsDepth(const ThresholdDither& dither, int x, int z, int k, int depth) const {
        const int whole = int(offsets_[std::size_t(k)].thresholdQ8 >> 8);
        if (whole != depth - 1) return whole >= depth;
        return carries(dither, x, z, k);
    }
    /// True when the dither of slide k of a grain in column (x, z) carries its threshold past the
    /// whole cells: it needs the column one cell deeper than the threshold's whole part.
    bool carries(const ThresholdDither& dither, int x, int z, int k) const {
        return dither.of(x, z, k) > restComplement_[std::size_t(k)];
    }
    /// carries() of all the slides at once, bit k for slide k, as a slide reads them (16 compares
    /// to a vector instruction where the build has SSE2).
    std::uint64_t carriedSlides(const ThresholdDither& dither, int x, int z) const;
    /// Of the grains around a column c (window bits as in wakeMask), those whose slide into c's
    /// column has a threshold of `whole` whole cells (and a fraction): so needsDepth(d) is true
    /// for them when d <= whole, false when d > whole + 1, and their dither tells at d = whole + 1.
    std::uint64_t towardsCentreWithWhole(int whole) const {
        return whole >= 0 && whole < int(towardsCentreByWhole_.size()) ? towardsCentreByWhole_[std::size_t(whole)] : 0;
    }
    /// The same, with a threshold of at least `whole` whole cells.
    std::uint64_t towardsCentreWithWholeAtLeast(int whole) const {
        return whole < int(towardsCentreAtLeast_.size()) ? towardsCentreAtLeast_[std::size_t(std::max(whole, 0))] : 0;
    }
    /// The slide (index into offset()) to the column (dx, dz) away, both within kGranularReach.
    static constexpr int offsetIndex(int dx, int dz) {
        const int bit = (dz + kGranularReach) * kWindow + dx + kGranularReach;
        return bit < kOffsets / 2 ? bit : bit - 1; // the window's centre has no slide
    }
    /// g in cells per step squared, 16.16 fixed point.
    std::uint32_t gravity() const { return gravity_; }
    /// The slope T the thresholds use for the asked angle (calibratedThresholds).
    double thresholdSlope() const { return slope_; }

    /// One sideways move: the offset, and the cells of the grain's layer its path crosses.
    struct Offset {
        int dx = 0, dz = 0;            ///< column offset, cells
        std::uint32_t thresholdQ8 = 0; ///< T|e| in 1/256 cells
        std::uint64_t pathMask = 0;    ///< the path's cells in the 7x7 window, bit (dz + 3) * 7 + (dx + 3)
    };
    static constexpr int kOffsets = kWindow * kWindow - 1; ///< 48
    /// One of the 48 slides.
    const Offset& offset(int k) const { return offsets_[std::size_t(k)]; }

private:
    static_assert(ThresholdDither::kGroups * 8 == kOffsets, "a dither word holds 8 slides' bytes");

    GranularOutcome fall(const GranularContext& on, const GrainCell& at, CellValue grain, bool mayBeMoving) const;
    GranularOutcome slide(const GranularContext& on, const GrainCell& at, CellValue grain, bool onVessel) const;
    int deflected(const GranularContext& on, const GrainCell& landing) const;

    std::array<Offset, kOffsets> offsets_{};
    std::uint64_t divesMask_ = 0; // the slides into the 8 columns next to the grain, bit k for offset k (slide's dives)
    // blockedBy_[r][taken]: the slides (bit k for offset k) whose path crosses one of the cells
    // `taken` (7 bits) of row r of the window, so a window's blocked slides are 7 look-ups.
    RowBlockTable blockedBy_{};
    // A slide's need is floor((T|e| in 1/256 cells + dither) / 256): the whole part of T|e|
    // plus a carry when the dither reaches past the rest. wholeAtLeast_[d]: the slides whose whole
    // part is d or more; wholeExactly_[d]: exactly d; restComplement_[k]: 255 minus the rest, so
    // the carry is dither > restComplement_[k].
    std::vector<std::uint64_t> wholeAtLeast_, wholeExactly_;
    std::array<std::uint8_t, kOffsets> restComplement_{};
    double slope_ = 0;
    int maxDrop_ = 1;
    std::uint32_t gravity_ = 0;
    std::vector<std::uint64_t> wakeMasks_;
    std::vector<std::uint64_t> towardsCentreByWhole_, towardsCentreAtLeast_; // towardsCentreWithWhole(AtLeast)
    // towardsBlockedBy_[r][taken]: of the grains around a column c (window bits), those whose slide
    // into c's column crosses, at their own level, a taken cell of window row r around c.
    RowBlockTable towardsBlockedBy_{};
    // For each column t of the 5x5 under a cell c: the grains with a slide across c into t.
    std::array<std::uint64_t, kAcrossWindow * kAcrossWindow> slidesAcrossCentreTo_{};
    static constexpr int kAcrossCentre = kAcrossReach * kAcrossWindow + kAcrossReach; // c's own column

    // Paths towards a column never reach the window's first and last rows (a grain 3 rows away
    // leaves its own row at its first step): the constructor checks it.
    std::uint64_t blockedTowardsCentre(std::uint64_t clear) const { return blockedIn<1, kWindow - 2>(towardsBlockedBy_, clear); }
    // For each column t of the 5x5 under c other than c's own: the paths at their level (window
    // bits around c) of the at most 8 grains with a slide across c into t, and which of them is
    // the grain at each window bit's: small enough to stay in the cache, where a table of every
    // row pattern would not.
    static constexpr int kMaxSlidesAcrossInto = 8;
    std::array<std::array<std::uint64_t, kMaxSlidesAcrossInto>, kAcrossWindow * kAcrossWindow> pathsAcrossCentreInto_{};
    std::array<std::array<std::uint8_t, kWindow * kWindow>, kAcrossWindow * kAcrossWindow> slotAcrossCentreInto_{};
    // [r][pattern]: the columns under c into which a grain of window row r at the cells `pattern`
    // (7 bits) slides across c (targetsAcrossCentreOf).
    std::array<std::array<std::uint32_t, 1u << kWindow>, kWindow> targetsAcrossCentreByRow_{};
};

// Inline: the sweep calls it for every visited grain, most of which only take a speed or rest.
inline GranularOutcome GranularRules::visit(const GranularContext& on, GrainCell at, MotionHints hints) const {
    const CellValue grain = on.grid[at.index];
    if (grain < 0) return {};
    const CellValue below = on.grid[at.index - on.grid.layerSize()];
    if (below == kEmpty) return fall(on, at, grain, hints.grain);

    // Most visited grains rest on grains at rest: the hints spare them both states (a cache miss
    // each, by id).
    const auto id = std::size_t(grain);
    // The grain below may be asleep in its fall (this one came to rest on it in the last step).
    const std::span<FallState> falls = on.falls;
    const std::uint32_t speedBelow = below >= 0 && hints.below ? caughtUp(falls[std::size_t(below)], on.step).speed : 0;
    if (speedBelow > 0) {
        // Resting on a grain that is still moving: move with it, and keep up to a cell of progress
        // so the grain follows at once when the one below moves on (a column flows as one).
        GranularOutcome outcome;
        outcome.inMotion = true; // speed > 0
        outcome.kind = ride(falls[id], speedBelow, hints.grain, at.y > 1 || !on.bottomIsOutlet);
        return outcome;
    }
    if (hints.grain && (falls[id].speed | falls[id].fraction)) { // it was in motion and stops here
        falls[id] = FallState{};
        GranularOutcome outcome = slide(on, at, grain, below == kInvalid);
        outcome.stopped = outcome.kind == GranularOutcome::Resting;
        return outcome;
    }
    return slide(on, at, grain, below == kInvalid);
}

/// The thresholds that make a poured cone stand at `reposeDegrees`, as round as the lattice lets
/// it (a measured calibration: the grains find the low-threshold paths, so T lies above tan of
/// the angle). A slide at angle phi from the x axis, |e| columns away, needs a drop of
/// T (1 + s sin^2 2phi) |e| cells.
struct ThresholdCalibration {
    double slope;              ///< T
    double diagonalStiffening; ///< s
};
ThresholdCalibration calibratedThresholds(double reposeDegrees);

} // namespace sandcore
