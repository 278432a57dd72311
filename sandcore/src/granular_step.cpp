// SPDX-License-Identifier: MIT
#include "granular_step.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>

namespace sandcore {

GranularStep::GranularStep(const SweepContext& context, const GranularSweepState& state, int y)
    : context_(context), rules_(state.rules), empty_(state.empty), awake_(state.awake), outlet_(state.outlet),
      logs_(state.logs),
      on_{context.grid,  state.empty,          context.grains.fall[std::size_t(context.level)],
          state.dither,  context.stepKey,      std::uint64_t(context.level),
          context.step,  state.bottomIsOutlet},
      wakes_{state.rules, state.dither, state.empty, state.layout, context.grid, state.awake}, cells_(context.grid.cells().data()),
      words_(state.awake.words()), motion_(state.motion), rowAwake_(state.awake.rowFlags()),
      layerWords_(std::size_t(state.awake.size().z) * std::size_t(state.awake.rowWords())), y_(y),
      sizeX_(state.awake.size().x), sizeY_(state.awake.size().y), sizeZ_(state.awake.size().z),
      rowWords_(state.awake.rowWords()), bottomIsOutlet_(state.bottomIsOutlet) {}

// The occupied bits are kept as the classic visit keeps them, so the granular wakes can AND with
// them instead of reading cells. Kept inside the strip loop, which calls it for every visited cell.
[[gnu::always_inline]] inline GranularStep::Visit GranularStep::visit(StripLog& log, const VisitedCell& cell) const {
    const int x = cell.x, y = y_, z = cell.z;
    const std::size_t word = std::size_t(cell.row) * std::size_t(rowWords_) + std::size_t(x >> 6);
    const std::uint64_t bit = std::uint64_t{1} << (x & 63);
    const std::uint32_t from = cell.row * std::uint32_t(sizeX_) + std::uint32_t(x);
    const CellValue* cells = cells_;
    AwakeCells::Word* words = words_;
    MotionWord* motion = motion_;
    const std::span<FallState> falls = on_.falls;
    if (cells[from] < 0) {
        words[word].occupied &= ~bit;
        return {GranularOutcome::Resting, false};
    }
    // A sleeping gatherer or rider wakes: its state as after the step before this one. Whatever
    // it does, the column that slept on it (whose occupied bits are clear) must follow.
    bool wasAsleep = false;
    if (cell.mayBeMoving) {
        FallState& own = falls[std::size_t(cells[from])];
        if (own.gatheringSince) {
            wasAsleep = true;
            own = rules_.caughtUp(own, context_.step - 1);
            ++log.sleepsEnded;
        }
    }
    // The grain's own bit comes with the queue (StripLog::Cell); the grain below is in the same
    // column of the layer below: the same bit, one layer's words back.
    const MotionHints hints{cell.mayBeMoving, (motion[word - layerWords_].inMotion & bit) != 0};
    // A grain that came to rest on a sleeping gatherer or rider (in the last step; in this one it
    // rides it, reading its state caught up) wakes it for the next step, as the grain carrying
    // the column must carry this one too. The layer below has had its turn. (Woken here, where
    // the state below is read anyway, rather than by every move, which would read the cell under
    // the one it entered.)
    if (hints.below) {
        const CellValue below = cells[from - on_.grid.layerSize()];
        if (below >= 0 && falls[std::size_t(below)].gatheringSince) {
            words[word - layerWords_].awake |= bit;
            words[word - layerWords_].occupied |= bit;
            rowAwake_[cell.row - std::uint32_t(sizeZ_)] = 1;
        }
    }
    const GranularOutcome outcome = rules_.visit(on_, {x, y, z, from}, hints);
    // The bit follows the grain's state: cleared where it was, set where it is when in motion.
    if (outcome.kind == GranularOutcome::Moved) {
        if (hints.grain) motion[word].inMotion &= ~bit;
        if (outcome.inMotion) markInMotion(outcome.to);
    } else if (outcome.inMotion != hints.grain) {
        motion[word].inMotion ^= bit;
    }
    if (outcome.kind == GranularOutcome::Waiting || outcome.stopped) {
        std::uint64_t asleepUntil = 0; // the step its timer wakes it, when it sleeps
        if (outcome.kind == GranularOutcome::Waiting) { // in motion: visited again next step, or asleep
            asleepUntil = fallAsleepGathering(log, cell, from);
            if (asleepUntil) {
                // The wakes of cells emptied nearby pass it by: nothing they change is read by
                // its visit. Its timer, or a grain arriving on it, sets the bit again.
                words[word].occupied &= ~bit;
            } else {
                words[word].occupied |= bit;
                words[word].awake |= bit;
                rowAwake_[cell.row] = 1;
            }
        }
        // A grain that rests on this one follows it while it moves (granular_rules.hpp): its
        // speed changed without a cell emptying, so the grain above must look again. While this
        // one moves, the grains resting on it ride (carryRiders); when it stops (or gathers at a
        // speed of 0, without gravity), the grain above is woken. The occupied bit says whether
        // the cell above may hold one: it is never clear under a grain (but in a column that
        // slept in its fall, hence the look above whenever this grain slept), and reading it
        // spares reading the cell above: most grains in motion, those in the stream, carry none.
        if (y + 1 < sizeY_ && ((words[word + layerWords_].occupied & bit) || wasAsleep)) {
            const std::uint32_t speed = outcome.kind == GranularOutcome::Waiting ? falls[std::size_t(cells[from])].speed : 0;
            if (speed > 0) {
                const int carried = carryRiders(log, {cell, from, speed, asleepUntil});
                log.carried += carried;
                log.speedChanges += carried; // each one's speed or fraction changed
            } else {
                words[word + layerWords_].awake |= bit;
                words[word + layerWords_].occupied |= bit; // a rider that slept had it cleared
                rowAwake_[cell.row + std::uint32_t(sizeZ_)] = 1;
            }
        } else if (y + 1 == sizeY_ && outcome.kind == GranularOutcome::Waiting) {
            outlet_.fallChanged(x, y, z);
        }
    }
    if (outcome.kind != GranularOutcome::Moved) return {outcome.kind, outcome.stopped};
    words[word].occupied &= ~bit; // every move goes down at least a layer: the cell it left is EMPTY
    const Int3 to = outcome.to;
    const std::uint32_t toCell = on_.grid.index(to.x, to.y, to.z);
    empty_.setEmpty(to.x, to.y, to.z, false); // the cell it entered; the one it left: at the turn's end
    recordMove(context_, log, {std::uint32_t(cells[toCell]), toCell, outcome.cameFrom, context_.level});
    if (to.y > 0 || bottomIsOutlet_) awake_.wakeAt(to.x, to.y, to.z); // it may move on next step
    wakeFallsAsleepAround(awake_, motion_, to.x, to.y, to.z);
    // A dive or a glance ends under a grain: when that one sleeps in its fall, its EMPTY cell below is gone.
    if (to.y + 1 < sizeY_) wakeFallAsleepAt(awake_, motion_, to.x, to.y + 1, to.z);
    // The cell it left is free: the layers above may use it in this step; its own layer in the
    // next (endGranularTurn).
    log.left.push_back({x, z});
    if (wasAsleep && y + 1 < sizeY_) awake_.wakeAt(x, y + 1, z); // a rider that slept on it, unseen by the wakes
    wakes_.layersAbove(x, y, z);
    outlet_.emptied(x, y, z);
    return {GranularOutcome::Moved, outcome.stopped};
}

// After a visit in which the grain in `cell` fell without reaching its next cell: puts it to
// sleep until the step its fall reaches that cell, when the cell below is EMPTY (grid_sweep.hpp
// says why nothing else can change meanwhile). The column resting on it sleeps with it
// (carryRiders). Not in a full sweep, which visits every cell. Returns the step its timer wakes
// it, or 0 when it stays awake.
inline std::uint64_t GranularStep::fallAsleepGathering(StripLog& log, const VisitedCell& cell, std::uint32_t from) const {
    if (!context_.sleeping) return 0;
    if (cells_[from - on_.grid.layerSize()] != kEmpty) return 0; // rides a moving grain
    if (bottomIsOutlet_ && y_ <= 1) return 0; // over the outlet row: the transition may set its speed
    // A grain next to it could dive under it (GranularRules::slide) while it sleeps: it stays
    // awake then. A grain that comes next to it later wakes it (wakeFallsAsleepAround).
    for (int z = std::max(cell.z - 1, 0); z <= std::min(cell.z + 1, sizeZ_ - 1); ++z)
        for (int x = std::max(cell.x - 1, 0); x <= std::min(cell.x + 1, sizeX_ - 1); ++x)
            if ((x != cell.x || z != cell.z) && cells_[on_.grid.index(x, y_, z)] >= 0) return 0;
    FallState& own = on_.falls[std::size_t(cells_[from])];
    const int gathering = rules_.stepsOnlyGathering(own, FallTimers::kLongestSleep);
    if (gathering == 0) return 0; // it moves in the next step
    own.gatheringSince = std::uint16_t(kGatheringAsleep | (context_.step & kAsleepStepMask));
    const std::uint64_t wakeStep = context_.step + std::uint64_t(gathering) + 1;
    log.sleepers.push_back({{cell.row, std::uint32_t(cell.x)}, wakeStep});
    return wakeStep;
}

// The grains resting one on another above the column's base, which stays where it is moving at
// column.speed after its visit in this step, visited now rather than in their layers' turns:
// each one's visit would only ride the grain below it (GranularRules::ride), and nothing it reads
// can change before its turn (the cell below it stays taken, the speed of the grain in it is
// final for the step). Visiting a column at once spares each grain the queue and the reads of
// the cell and the state below it. A grain that rode is marked (MotionWord::carriedEarly): its
// layer's turn skips it and keeps it awake for the next step, as its own visit would have. The
// column ends at the first cell without a grain, or at a grain whose ride changed nothing (it
// sleeps, as after its own visit). Returns the grains visited.
// When the base sleeps until column.asleepUntil (fallAsleepGathering), the riders sleep with it:
// each is marked (kRidingAsleep) and gets a timer for that step instead of staying awake, since
// then the base moves on and they follow in their own turns. Gravity is never 0
// (validatePhysics), so every rider's speed changes every step and the whole column rides.
int GranularStep::carryRiders(StripLog& log, const Column& column) const {
    const int x = column.base.x, z = column.base.z;
    const std::uint32_t layer = on_.grid.layerSize();
    const std::uint64_t bit = std::uint64_t{1} << (x & 63);
    // The column is read a batch of cells at a time and each rider's fall state asked for before
    // the first ride: a state is found by the id in the cell, so read one after another each
    // cell's state would wait on its cell, and the next rider on both.
    constexpr int kBatch = 16;
    std::array<CellValue, kBatch> riders;
    int carried = 0;
    std::uint32_t cell = column.from;
    for (int above = y_ + 1; above < sizeY_;) {
        int count = 0;
        for (; count < kBatch && above + count < sizeY_; ++count) {
            const CellValue rider = cells_[cell + std::uint32_t(count + 1) * layer];
            if (rider < 0) break;
            __builtin_prefetch(on_.falls.data() + rider);
            riders[std::size_t(count)] = rider;
        }
        for (int i = 0; i < count; ++i, ++above) {
            const std::uint32_t row = std::uint32_t(above) * std::uint32_t(sizeZ_) + std::uint32_t(z);
            const std::size_t word = std::size_t(row) * std::size_t(rowWords_) + std::size_t(x >> 6);
            MotionWord& motion = motion_[word];
            const bool mayBeMoving = (motion.inMotion & bit) != 0;
            FallState& state = on_.falls[std::size_t(riders[std::size_t(i)])];
            const bool wasAsleep = mayBeMoving && state.gatheringSince != 0;
            if (wasAsleep) { // it slept with the grain below: brought up to the step before
                state = rules_.caughtUp(state, context_.step - 1);
                ++log.sleepsEnded;
            }
            if (rules_.ride(state, column.speed, mayBeMoving, above > 1 || !bottomIsOutlet_) == GranularOutcome::Riding)
                return carried; // it sleeps, as after its own visit
            motion.inMotion |= bit;
            if (above == sizeY_ - 1) outlet_.fallChanged(x, above, z);
            if (column.asleepUntil) {
                state.gatheringSince = std::uint16_t(kGatheringAsleep | kRidingAsleep | (context_.step & kAsleepStepMask));
                words_[word].awake &= ~bit; // not kept awake: its timer wakes it
                words_[word].occupied &= ~bit;
                log.sleepers.push_back({{row, std::uint32_t(x)}, column.asleepUntil});
            } else {
                motion.carriedEarly |= bit;
                rowAwake_[row] = 1;
                if (wasAsleep) words_[word].occupied |= bit;
            }
            ++carried;
        }
        if (count < kBatch) break; // the column ends at a cell without a grain (or the grid's top)
        cell += std::uint32_t(kBatch) * layer;
    }
    return carried;
}

// A grain visited later finds the cells of the layer below taken by one visited earlier, so a
// fixed order would let grains run one way more easily than the other and cones would lean (PH2).
// The order therefore turns with the step: x ascending or descending by bit 0 of the step number,
// z by bit 1 within each strip, so over four steps every mirror of the grid is swept alike. No
// visit wakes a cell of its own layer for this step (grid_sweep.hpp), so all the strips' awake
// bits are taken at once, before the first visit.
SweepResult GranularStep::sweepStrips(std::span<const int> strips, std::vector<StripLog::Cell>& queue) const {
    SweepResult totals;
    if (strips.empty()) return totals;
    const int y = y_;
    const bool xDown = (context_.step & 1) != 0, zDown = (context_.step & 2) != 0;
    // The grains these strips' visits carried up their columns count as visited (carryRiders).
    auto addCarried = [&] {
        for (const int index : strips) {
            totals.visited += logs_[std::size_t(index)].carried;
            logs_[std::size_t(index)].carried = 0;
        }
    };
    // Calls f(z) for the rows of the strips in visiting order.
    auto forEachRow = [&](auto&& f) {
        for (const int index : strips) {
            const int zBegin = index * kStripRows, zEnd = std::min(zBegin + kStripRows, sizeZ_);
            for (int i = zBegin; i < zEnd; ++i) f(zDown ? zBegin + zEnd - 1 - i : i);
        }
    };
    // Calls f(x) for the cells `bits` of word w of a row, in visiting order.
    auto forEachBit = [&](int w, std::uint64_t bits, auto&& f) {
        while (bits) {
            const int bit = xDown ? 63 - std::countl_zero(bits) : std::countr_zero(bits);
            bits &= ~(std::uint64_t{1} << bit);
            f(w * 64 + bit);
        }
    };
    auto visitAt = [&](int x, int z, bool mayBeMoving) {
        const std::uint32_t row = std::uint32_t(y) * std::uint32_t(sizeZ_) + std::uint32_t(z);
        StripLog& log = logs_[std::size_t(z / kStripRows)]; // each strip's moves and cells left in its own log
        ++totals.visited;
        const Visit done = visit(log, {x, z, row, mayBeMoving});
        totals.moves += done.kind == GranularOutcome::Moved ? 1 : 0;
        log.speedChanges += done.kind == GranularOutcome::Waiting || done.stopped ? 1 : 0;
    };
    if (!context_.sleeping) { // every cell of every row, as if awake
        forEachRow([&](int z) {
            const std::uint32_t row = std::uint32_t(y) * std::uint32_t(sizeZ_) + std::uint32_t(z);
            rowAwake_[row] = 0;
            AwakeCells::Word* words = words_ + std::size_t(row) * std::size_t(rowWords_);
            MotionWord* motion = motion_ + std::size_t(row) * std::size_t(rowWords_);
            for (int j = 0; j < rowWords_; ++j) {
                const int w = xDown ? rowWords_ - 1 - j : j;
                words[w].awake = 0; // a full sweep keeps no awake bits: turning sleeping on wakes every grain
                const std::uint64_t visitedEarly = motion[w].carriedEarly; // visited in this step already
                motion[w].carriedEarly = 0;
                const std::uint64_t moving = motion[w].inMotion;
                forEachBit(w, awake_.wholeWord(w) & ~visitedEarly, [&](int x) { visitAt(x, z, (moving >> (x & 63)) & 1); });
            }
            if (context_.feed) context_.feed->publishSome();
        });
        addCarried();
        return totals;
    }
    // The awake cells, in visiting order. A visit waits on its cell, the cell below and, for a
    // grain in motion, its fall state, which only the cell's grain id locates: so each visit asks
    // for the cells kCellsAhead visits on, and for the fall state kStatesAhead visits on, by when
    // that grain's cell has arrived. The loads of several visits are then in flight together
    // instead of one after another. One queue serves all the strips of a turn that one thread
    // sweeps, both phases, so the look ahead runs on across strips. Each entry carries its cell's
    // in-motion bit, read with the carried-early word of the same cells, so neither the look ahead
    // nor the visit loads it again. (The classic loop keeps its row-ahead hint: its visits are
    // too short for a queue to pay.)
    const std::size_t most = strips.size() * std::size_t(kStripRows) * std::size_t(sizeX_);
    if (queue.size() < most) queue.resize(most);
    StripLog::Cell* const queued = queue.data();
    std::size_t count = 0;
    forEachRow([&](int z) {
        const std::uint32_t row = std::uint32_t(y) * std::uint32_t(sizeZ_) + std::uint32_t(z);
        if (!rowAwake_[row]) return;
        AwakeCells::Word* words = words_ + std::size_t(row) * std::size_t(rowWords_);
        MotionWord* motion = motion_ + std::size_t(row) * std::size_t(rowWords_);
        __builtin_prefetch(motion - layerWords_); // the visits read the in-motion bits under the row
        std::uint64_t stillAwake = 0;
        for (int j = 0; j < rowWords_; ++j) {
            const int w = xDown ? rowWords_ - 1 - j : j;
            // The grains carried early were visited in this step: awake for the next one only.
            const std::uint64_t visitedEarly = motion[w].carriedEarly;
            motion[w].carriedEarly = 0;
            const std::uint64_t bits = words[w].awake & ~visitedEarly;
            words[w].awake = visitedEarly;
            stillAwake |= visitedEarly;
            const std::uint64_t moving = motion[w].inMotion;
            forEachBit(w, bits, [&](int x) {
                assert(count < most); // awake bits lie only on cells of the strips' rows
                queued[count++] = {std::uint32_t(x), std::uint32_t((moving >> (x & 63)) & 1), std::uint32_t(z)};
            });
        }
        rowAwake_[row] = stillAwake != 0;
    });
    const std::uint32_t layerRowStart = std::uint32_t(y) * std::uint32_t(sizeZ_);
    const auto cellOf = [&](const StripLog::Cell& c) { return (layerRowStart + c.z) * std::uint32_t(sizeX_) + c.x; };
    for (std::size_t n = 0; n < count; ++n) {
        if (n + kCellsAhead < count) {
            const CellValue* cell = cells_ + cellOf(queued[n + kCellsAhead]);
            __builtin_prefetch(cell);
            __builtin_prefetch(cell - on_.grid.layerSize());
        }
        if (n + kStatesAhead < count) {
            const StripLog::Cell ahead = queued[n + kStatesAhead];
            if (ahead.inMotion) {
                const CellValue grain = cells_[cellOf(ahead)];
                if (grain >= 0) __builtin_prefetch(on_.falls.data() + grain);
            }
        }
        const StripLog::Cell at = queued[n];
        if (context_.feed && n > 0 && at.z != queued[n - 1].z) context_.feed->publishSome(); // a row done
        visitAt(int(at.x), int(at.z), at.inMotion);
    }
    if (context_.feed) context_.feed->publishSome();
    addCarried();
    return totals;
}

// A layer's paths see it as its turn began (granular_rules.hpp), so the cells its grains leave
// become EMPTY in the kept bits only when the turn ends, for the layers above and the next step.
// Their own-layer wakes (the grains of the layer that may slide across them) matter only for the
// next step, and only if the cell is still EMPTY then; after a layer's turn its cells and those
// below can only fill (grains of later turns land there), never empty. So they wait until the
// grid's sweep ends (wakeAroundCellsLeft): a cell EMPTY then is woken around as
// GranularWakes::aroundEmptied does, reading the windows as the step leaves them (what the next
// step's turns below empty before this layer's turn wakes this layer itself); one filled again
// wakes nobody, as nobody can gain from it, and most are filled by the end of the next turn.
void endGranularTurn(int y, std::span<const int> strips, const GranularSweepState& state, std::vector<Int3>& leftEarlier) {
    for (const int strip : strips) {
        StripLog& log = state.logs[std::size_t(strip)];
        for (const StripLog::Column column : log.left) {
            state.empty.setEmpty(column.x, y, column.z, true);
            leftEarlier.push_back({column.x, y, column.z});
        }
        log.left.clear();
    }
}

void wakeAroundCellsLeft(GranularWakes wakes, std::vector<Int3>& left) {
    for (const Int3& c : left)
        if (wakes.empty.isEmpty(c.x, c.y, c.z)) wakes.grainsAround(c.x, c.y, c.z, 0);
    left.clear();
}

} // namespace sandcore
