// SPDX-License-Identifier: MIT
#include "sandcore/scene.hpp"

#include "granular_rules.hpp"
#include "grid_sweep.hpp"
#include "layout_bits.hpp"
#include "move_feed.hpp"
#include "neck_flow.hpp"
#include "push_search.hpp"
#include "sandcore/counter_random.hpp"
#include "worker_pool.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace sandcore {

namespace {

// Indices of GrainStore::fall.
constexpr std::size_t kLowerGrid = std::size_t(GridLevel::Lower), kUpperGrid = std::size_t(GridLevel::Upper);

bool layoutOnly(const CellGrid& grid) {
    const auto cells = grid.cells();
    return std::all_of(cells.begin(), cells.end(), [](CellValue v) { return v == kEmpty || v == kInvalid; });
}

CellBox clipped(CellBox box, Int3 size) {
    box.min = {std::max(box.min.x, 0), std::max(box.min.y, 0), std::max(box.min.z, 0)};
    box.max = {std::min(box.max.x, size.x), std::min(box.max.y, size.y), std::min(box.max.z, size.z)};
    return box;
}

template <class Visit> void forEachCellIn(const CellGrid& grid, CellBox box, Visit&& visit) {
    box = clipped(box, grid.size());
    for (int y = box.min.y; y < box.max.y; ++y)
        for (int z = box.min.z; z < box.max.z; ++z)
            for (int x = box.min.x; x < box.max.x; ++x) visit(grid.index(x, y, z));
}

// Writes the grain records of a step's moves fed by the sweeps (MoveFeed::drain and help).
struct RecordWriter {
    GrainStore& grains;
    std::uint64_t step;
    void operator()(const GrainMove& move) const { grains.recordMove(move.grain, move.cell, move.cameFrom, step); }
    void ask(const GrainMove& move) const { __builtin_prefetch(grains.place.data() + move.grain, 1); }
};

} // namespace

Scene::Scene(SceneShape shape, CellGrid upperLayout, CellGrid lowerLayout, std::vector<std::uint32_t> upperFill,
             StepSettings settings)
    : shape_(shape), settings_(settings), upper_(std::move(upperLayout)), lower_(std::move(lowerLayout)),
      upperFill_(std::move(upperFill)) {
    if (upper_.size().x != lower_.size().x || upper_.size().z != lower_.size().z)
        throw std::invalid_argument("upper and lower grid must have the same x and z size");
    if (!layoutOnly(upper_) || !layoutOnly(lower_))
        throw std::invalid_argument("grid layouts may hold only EMPTY and INVALID cells");
    for (std::uint32_t cell : upperFill_)
        if (cell >= upper_.cellCount() || upper_[cell] != kEmpty)
            throw std::invalid_argument("a fill cell lies outside the upper grid or on an INVALID cell");
    // The grids hold the layouts until reset() fills them: keep a bit per cell of each.
    upperLayout_ = std::make_unique<LayoutBits>(upper_);
    lowerLayout_ = std::make_unique<LayoutBits>(lower_);
    if (settings_.threads < 1) throw std::invalid_argument("threads must be at least 1");
    makeSweeps();
    pool_ = std::make_unique<WorkerPool>(settings_.threads, settings_.tasks);
    reset();
}

void Scene::configurePhysics() {
    const PhysicsSettings& physics = settings_.physics;
    validatePhysics(physics);
    const bool granular = physics.level == PhysicsLevel::Granular;
    granular_ = granular ? std::make_unique<GranularRules>(physics) : nullptr;
    // Model only what a scene needs: the neck's discharge belongs to an hourglass neck.
    neckFlow_ = granular && shape_.hourglassNeck
                    ? std::make_unique<NeckFlow>(upperLayout_->openCellsOfBottomLayer(), double(physics.gravity))
                    : nullptr;
    for (GridSweep* sweep : {upperSweep_.get(), lowerSweep_.get()}) {
        sweep->setGranular(granular_.get());
        sweep->setSeed(settings_.seed);
    }
}

void Scene::setPhysics(const PhysicsSettings& physics) {
    validatePhysics(physics);
    settings_.physics = physics;
    configurePhysics();
    for (FallStates& grid : grains_.fall) std::fill(grid.begin(), grid.end(), FallState{});
    // The new rules read further than the old ones: every grain looks again (a superset of the awake set).
    markEverythingAwake();
}

double Scene::neckFlowRate() const { return neckFlow_ ? neckFlow_->rate() : 0.0; }

Scene::~Scene() = default;

CellGrid Scene::layout(GridLevel level) const { return (level == GridLevel::Upper ? *upperLayout_ : *lowerLayout_).grid(); }
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;

void Scene::makeSweeps() {
    upperSweep_ = std::make_unique<GridSweep>(upperLayout_->size(), true);
    lowerSweep_ = std::make_unique<GridSweep>(lowerLayout_->size(), false);
    lowerSweep_->setGridAbove(upperSweep_.get());
    configurePhysics(); // the new sweeps get the rules; a turned hourglass's neck is measured again
}

GridSweep& Scene::sweepOf(GridLevel level) { return level == GridLevel::Upper ? *upperSweep_ : *lowerSweep_; }

void Scene::rebuildCells(GridLevel level) {
    CellGrid& grid = gridRef(level);
    (level == GridLevel::Upper ? *upperLayout_ : *lowerLayout_).writeInto(grid);
    for (const CellBox& box : obstacles(level))
        forEachCellIn(grid, box, [&](std::uint32_t n) { grid[n] = kInvalid; });
    if (level == GridLevel::Lower)
        for (std::size_t b = 0; b < bodies_.size(); ++b)
            for (std::uint32_t n : bodyCells(b)) grid[n] = kInvalid;
}

void Scene::reset() {
    if (flipped_) {
        // The fill belongs to the upright hourglass: turn the layouts back first.
        flipLayouts();
        upper_ = CellGrid(upperLayout_->size());
        lower_ = CellGrid(lowerLayout_->size());
    }
    grains_.clear();
    movedGrains_.clear();
    nextIdentity_ = 0;
    counters_ = {};
    rebuildCells(GridLevel::Upper);
    rebuildCells(GridLevel::Lower);
    upperSweep_->clear();
    lowerSweep_->clear();
    upperSweep_->readEmptyCells(upper_);
    lowerSweep_->readEmptyCells(lower_);
    grains_.reserve(std::uint32_t(upperFill_.size())); // a big fill grows no array piece by piece
    movedGrains_.reserve(upperFill_.size());           // address space only, until steps move grains
    for (std::uint32_t cell : upperFill_) addGrain(GridLevel::Upper, cell);
}

void Scene::step() {
    const std::uint64_t stepNumber = counters_.stepsDone + 1;
    WorkerPool* pool = settings_.threads > 1 ? pool_.get() : nullptr;
    const std::uint64_t stepKey = counterRandomStepKey(settings_.seed, stepNumber);
    SweepResult lower, upper;
    // The two grids touch no common cell during their sweeps (the lower grid's wakes of the
    // outlet row wait until both are done), so when both have comparable work they run side by
    // side, each on one thread; otherwise the busy grid splits its layers into strips over the
    // threads. Neither choice changes the result. One thread needs no measure of the work.
    bool sideBySide = false;
    if (pool) {
        const std::int64_t lowerWork = settings_.sleeping ? lowerSweep_->awakeRowCount() : std::int64_t(lower_.cellCount());
        const std::int64_t upperWork = settings_.sleeping ? upperSweep_->awakeRowCount() : std::int64_t(upper_.cellCount());
        sideBySide = std::min(lowerWork, upperWork) > 0 && 4 * std::min(lowerWork, upperWork) >= std::max(lowerWork, upperWork);
    }
    // Side by side, the sweeps feed their moves to the thread that writes the grain records
    // (move_feed.hpp); each grid's granular rules keep their fall states in their own array.
    // Otherwise strips on several threads list their moved grains in their own logs, and one
    // thread lists them in movedGrains_ directly.
    movedGrains_.clear();
    const bool feeding = sideBySide;
    std::vector<GrainMove>* movedList = pool ? nullptr : &movedGrains_;
    MoveFeed* lowerFeed = feeding ? &lowerSweep_->feed() : nullptr;
    MoveFeed* upperFeed = feeding ? &upperSweep_->feed() : nullptr;
    const SweepContext lowerContext{lower_,   grains_,           settings_.seed,      stepNumber, GridLevel::Lower,
                                    settings_.sleeping, stepKey, lowerFeed, movedList};
    const SweepContext upperContext{upper_,   grains_,           settings_.seed,      stepNumber, GridLevel::Upper,
                                    settings_.sleeping, stepKey, upperFeed, movedList};
    if (sideBySide) {
        lowerSweep_->setDeferWakesAbove(true);
        if (feeding) {
            lowerFeed->start(grains_.size());
            upperFeed->start(grains_.size());
        }
        // The thread whose sweep ends first writes the records of both grids' moves and lists
        // them: its own grid's at once, then the other's as they are fed. A sweep that no thread
        // has started by then (its worker is not running) writes its own after it, on whichever
        // thread takes it: nobody waits for a sweep that has not begun. While a sweep runs, only
        // one thread writes grain records, and only one ever writes movedGrains_; a sweep reads
        // neither. Once both sweeps are over, the thread whose sweep ended last writes records of
        // the chunks it claims too (MoveFeed::help), each record still written by one thread.
        enum : int { kWaiting, kStarted, kWritesItsOwn };
        std::atomic<int> sweepState[2] = {kWaiting, kWaiting};
        std::atomic<int> sweepsDone{0};
        pool->parallelFor(2, [&](int grid) {
            GridSweep& sweep = grid == 0 ? *lowerSweep_ : *upperSweep_;
            int state = kWaiting;
            const bool writesItsOwn = !sweepState[grid].compare_exchange_strong(state, kStarted, std::memory_order_acq_rel);
            (grid == 0 ? lower : upper) = sweep.sweep(grid == 0 ? lowerContext : upperContext, nullptr);
            if (!feeding) return;
            sweep.feed().finish();
            const RecordWriter record{grains_, stepNumber};
            auto list = [&](std::span<const GrainMove> moves) { movedGrains_.insert(movedGrains_.end(), moves.begin(), moves.end()); };
            auto drainGrid = [&](int which) {
                if (which == 1) upperMovesBegin_ = movedGrains_.size();
                (which == 0 ? *lowerSweep_ : *upperSweep_).feed().drain(list, record);
            };
            if (writesItsOwn) return drainGrid(grid);
            if (sweepsDone.fetch_add(1, std::memory_order_acq_rel) != 0) {
                // The other thread lists the moves and writes records, behind this sweep: share
                // the writes still left, this grid's first (usually where the other thread is).
                sweep.feed().help(record);
                (grid == 0 ? *upperSweep_ : *lowerSweep_).feed().help(record);
                return;
            }
            drainGrid(grid);
            state = kWaiting;
            if (sweepState[1 - grid].compare_exchange_strong(state, kWritesItsOwn, std::memory_order_acq_rel)) return;
            drainGrid(1 - grid);
        });
        lowerSweep_->setDeferWakesAbove(false);
        lowerSweep_->applyDeferredWakes();
    } else {
        lower = lowerSweep_->sweep(lowerContext, pool);
        upperMovesBegin_ = movedGrains_.size(); // listed directly: the lower grid's moves so far
        upper = upperSweep_->sweep(upperContext, pool);
    }
    lowerSweep_->takeLoggedMoves(movedGrains_); // fed or listed directly: nothing left
    if (pool && !sideBySide) upperMovesBegin_ = movedGrains_.size(); // logged by strips
    upperSweep_->takeLoggedMoves(movedGrains_);
    counters_.stepsDone = stepNumber;
    counters_.movesLastStep = lower.moves + upper.moves;
    counters_.visitedLastStep = lower.visited + upper.visited;
    counters_.speedChangesLastStep = granular_ ? lowerSweep_->speedChangesLastSweep() + upperSweep_->speedChangesLastSweep() : 0;
    if (granular_)
        transitionGranular();
    else
        transition();
}

// thesis §3.3.3 transition/insert: a grain in the upper grid's bottom row moves into the cell of
// the lower grid's top row at the same world position when that cell is EMPTY.
void Scene::transition() {
    const int lowerTop = lower_.size().y - 1;
    std::int64_t moved = 0, visited = 0;
    upperSweep_->forEachInBottomLayer(settings_.sleeping, [&](std::uint32_t cell) {
        ++visited;
        const CellValue grain = upper_[cell];
        if (grain < 0) return;
        const Int3 c = upper_.coordinate(cell);
        const std::uint32_t below = lower_.index(c.x, lowerTop, c.z);
        if (lower_[below] != kEmpty) return; // woken again when that cell empties
        lower_[below] = grain;
        upper_[cell] = kEmpty;
        grains_.level[std::size_t(grain)] = GridLevel::Lower;
        grains_.place[std::size_t(grain)].cell = below;
        // Same world position: a grain that fell into the shared row in this very step keeps
        // gliding from where it came from; one that was resting there does not move on screen.
        listTransition(std::uint32_t(grain), below);
        lowerSweep_->grainEntered(c.x, lowerTop, c.z);
        upperSweep_->wakeAroundEmptied(upper_, c.x, 0, c.z);
        ++moved;
    });
    moveListedIntoLowerGrid();
    counters_.grainsUpper -= moved;
    counters_.grainsLower += moved;
    counters_.movesLastStep += moved;
    counters_.visitedLastStep += visited;
}

// The granular transition: as the thesis's, except that in an hourglass the neck lets through
// only the grains Beverloo's rate allows this step (neck_flow.hpp), chosen by a counter hash so
// no part of the neck is favoured; the others wait, awake, in the flow.
// A grain that cannot pass because the cell below is full rides the grain there while that one
// falls (as GranularRules::visit does within a grid), so a block crossing the seam falls as one;
// it stops when the grain below is at rest.
void Scene::transitionGranular() {
    const int lowerTop = lower_.size().y - 1;
    const std::uint64_t step = counters_.stepsDone;
    std::vector<std::uint32_t>& ready = transitionReady_;
    ready.clear();
    std::int64_t visited = 0, stopped = 0, riding = 0;
    upperSweep_->forEachInBottomLayer(settings_.sleeping, [&](std::uint32_t cell) {
        ++visited;
        const CellValue grain = upper_[cell];
        if (grain < 0) return;
        const Int3 c = upper_.coordinate(cell);
        const CellValue under = lower_.at(c.x, lowerTop, c.z);
        if (under == kEmpty) {
            ready.push_back(cell);
            return;
        }
        FallState& fall = grains_.fall[kUpperGrid][std::size_t(grain)];
        const std::uint32_t speedUnder = under >= 0 ? granular_->caughtUp(grains_.fall[kLowerGrid][std::size_t(under)], step).speed : 0;
        if (speedUnder > 0) {
            // Kept awake while it rides: the grain under it, in the other grid, cannot wake it.
            // Its speed changed without a move: the grain resting on it looks again.
            granular_->ride(fall, speedUnder, true, false);
            upperSweep_->markInMotion(c.x, 0, c.z);
            upperSweep_->wakeAt(c.x, 0, c.z);
            if (upper_.size().y > 1 && upper_.at(c.x, 1, c.z) >= 0) upperSweep_->wakeAt(c.x, 1, c.z);
            ++riding;
            return;
        }
        if (fall.speed | fall.fraction) ++stopped;
        fall = FallState{}; // woken again when that cell empties
    });
    std::size_t passing = ready.size();
    if (neckFlow_) {
        passing = std::min(passing, std::size_t(neckFlow_->allowance(step)));
        if (passing < ready.size()) {
            auto key = [&](std::uint32_t cell) { return counterRandom(settings_.seed, step, 2, cell); };
            std::sort(ready.begin(), ready.end(), [&](std::uint32_t a, std::uint32_t b) {
                const std::uint64_t ka = key(a), kb = key(b);
                return ka != kb ? ka < kb : a < b;
            });
        }
    }
    for (std::size_t i = 0; i < ready.size(); ++i) {
        const std::uint32_t cell = ready[i];
        const auto grain = std::size_t(upper_[cell]);
        const Int3 c = upper_.coordinate(cell);
        // Grains in the neck row, let through or waiting, move at the flow's speed: a cell a step,
        // so the cell below the neck is free again by the next step and the column above refills
        // the neck row at once. The neck, not the supply around it, sets the rate.
        FallState& fall = grains_.fall[kUpperGrid][grain];
        if (neckFlow_) {
            fall.speed = NeckFlow::kFlowSpeed;
            upperSweep_->markInMotion(c.x, 0, c.z);
        }
        if (i >= passing) {
            upperSweep_->wakeAt(c.x, 0, c.z); // waits for a later step
            // Its speed may have changed without a move: the grain resting on it looks again.
            if (upper_.size().y > 1 && upper_.at(c.x, 1, c.z) >= 0) upperSweep_->wakeAt(c.x, 1, c.z);
            continue;
        }
        const std::uint32_t below = lower_.index(c.x, lowerTop, c.z);
        lower_[below] = CellValue(grain);
        upper_[cell] = kEmpty;
        grains_.level[grain] = GridLevel::Lower;
        grains_.place[grain].cell = below;
        if (neckFlow_) fall.speed = std::max(fall.speed, neckFlow_->exitSpeed()); // it leaves the neck at the stream's speed
        grains_.fall[kLowerGrid][grain] = fall; // its state goes with it into the lower grid's array
        if (fall.speed | fall.fraction) lowerSweep_->markInMotion(c.x, lowerTop, c.z);
        listTransition(std::uint32_t(grain), below);
        lowerSweep_->grainEntered(c.x, lowerTop, c.z);
        upperSweep_->wakeAroundEmptied(upper_, c.x, 0, c.z);
        if (neckFlow_) drawIntoNeck(c.x, c.z);
    }
    moveListedIntoLowerGrid();
    const auto moved = std::int64_t(passing);
    counters_.grainsUpper -= moved;
    counters_.grainsLower += moved;
    counters_.movesLastStep += moved;
    counters_.visitedLastStep += visited;
    // The grains held back, riding or stopped above a full cell changed their fall without a move.
    counters_.speedChangesLastStep += std::int64_t(ready.size() - passing) + riding + stopped;
}

// The grain right above a neck cell the transition emptied follows into it in the next step, at
// the flow's speed at least, as if it had ridden the grain that passed: the neck, not gravity
// from rest (a cell in sqrt(2/g) steps), sets how fast the sand above it moves. It never sleeps
// in its fall (GranularStep::fallAsleepGathering, GranularRules::ride), so its state is its own.
void Scene::drawIntoNeck(int x, int z) {
    if (upper_.size().y < 2) return;
    const CellValue above = upper_.at(x, 1, z);
    if (above < 0) return;
    FallState& fall = grains_.fall[kUpperGrid][std::size_t(above)];
    fall.speed = std::max(fall.speed, NeckFlow::kFlowSpeed);
    fall.fraction = std::uint16_t(kOneCell - 1);
    upperSweep_->markInMotion(x, 1, z);
    upperSweep_->wakeAt(x, 1, z);
}

// A grain the transition passed into the lower grid's top row (its record says so already).
// Same world position: one that fell into the shared row in this very step keeps gliding from
// where it came from, and its sweep listed it already (moveListedIntoLowerGrid corrects that
// entry); one that was resting there does not move on screen.
void Scene::listTransition(std::uint32_t grain, std::uint32_t lowerCell) {
    if (grains_.place[grain].movedAtStep == counters_.stepsDone) {
        ++listedTransitions_;
        return;
    }
    grains_.place[grain].cameFrom = kNoMove;
    grains_.place[grain].movedAtStep = counters_.stepsDone;
    movedGrains_.push_back({grain, lowerCell, kNoMove, GridLevel::Lower});
}

// The entries of grains that moved into the upper grid's bottom row in this step's sweep and
// then passed into the lower grid: where they are now. Only such entries lie in that row of the
// upper grid and name a grain the lower grid holds, so a pass over the list finds them without
// reading the records of the others. It starts at the upper grid's moves and stops at the last
// one to correct: the upper sweep goes bottom up, so with the classic rules (one layer a move)
// they are the first of its moves, and the pass, serial after both sweeps, reads few entries.
void Scene::moveListedIntoLowerGrid() {
    std::size_t left = listedTransitions_;
    listedTransitions_ = 0;
    const std::uint32_t bottomRow = upper_.layerSize();
    for (std::size_t i = upperMovesBegin_; left > 0 && i < movedGrains_.size(); ++i) {
        GrainMove& move = movedGrains_[i];
        if (move.level != GridLevel::Upper || move.cell >= bottomRow || grains_.level[move.grain] != GridLevel::Lower) continue;
        move.level = GridLevel::Lower;
        move.cell = grains_.place[move.grain].cell;
        --left;
    }
}

std::span<const GrainMove> Scene::movedGrains() const { return movedGrains_; }

std::uint64_t Scene::stateHash() const {
    // Fixed constants and explicit widths keep the value the same on every platform.
    std::uint64_t hash = 0x9e3779b97f4a7c15ull;
    for (const CellGrid* grid : {&upper_, &lower_}) {
        const Int3 s = grid->size();
        hash = mix64(hash ^ (std::uint64_t(std::uint32_t(s.x)) | std::uint64_t(std::uint32_t(s.y)) << 21 |
                             std::uint64_t(std::uint32_t(s.z)) << 42));
        for (CellValue v : grid->cells()) hash = mix64(hash + std::uint64_t(std::uint32_t(v)) + 0x632be59bd9b4e019ull);
    }
    return hash;
}

Int3 Scene::gridOrigin(GridLevel level) const {
    return level == GridLevel::Upper ? Int3{0, lower_.size().y - 1, 0} : Int3{0, 0, 0};
}

void Scene::setSeed(std::uint64_t seed) {
    if (seed == settings_.seed) return;
    settings_.seed = seed;
    upperSweep_->setSeed(seed);
    lowerSweep_->setSeed(seed);
    // The granular thresholds are dithered by the seed: a grain that could not slide may now.
    // (A classic grain sleeps only where no move is open, whatever the seed picks among them.)
    if (granular_) markEverythingAwake();
}

void Scene::setThreads(int threads) {
    if (threads < 1) throw std::invalid_argument("threads must be at least 1");
    if (threads == settings_.threads) return;
    settings_.threads = threads;
    pool_ = std::make_unique<WorkerPool>(threads, settings_.tasks);
}

void Scene::setSleeping(bool sleeping) {
    if (sleeping && !settings_.sleeping) markEverythingAwake();
    settings_.sleeping = sleeping;
}

void Scene::markEverythingAwake() {
    upperSweep_->readEmptyCells(upper_);
    lowerSweep_->readEmptyCells(lower_);
    upperSweep_->wakeEveryGrain(upper_);
    lowerSweep_->wakeEveryGrain(lower_);
}

bool Scene::sweepsMatchCells() const { return upperSweep_->emptyCellsMatch(upper_) && lowerSweep_->emptyCellsMatch(lower_); }

SceneSnapshot Scene::snapshot() const {
    SceneSnapshot saved{upper_, lower_, grains_, nextIdentity_, counters_, upperObstacles_, lowerObstacles_, flipped_, bodies_};
    // Every state as after the last step, so a file or an undo holds no sweep's bookkeeping.
    if (granular_)
        for (std::uint32_t id = 0; id < saved.grains.size(); ++id) saved.grains.fallOf(id) = fallOf(id);
    return saved;
}

FallState Scene::fallOf(std::uint32_t id) const {
    const FallState& stored = grains_.fallOf(id);
    return granular_ ? granular_->caughtUp(stored, counters_.stepsDone) : stored;
}

void Scene::restore(const SceneSnapshot& saved) {
    // Checked before anything changes, so a snapshot of another scene leaves this one as it was:
    // turned over, the upper grid takes the lower layout's size and the lower the upper's.
    const bool turn = saved.flipped != flipped_;
    const Int3 upperSize = turn ? lowerLayout_->size() : upperLayout_->size();
    const Int3 lowerSize = turn ? upperLayout_->size() : lowerLayout_->size();
    if (!(saved.upper.size() == upperSize) || !(saved.lower.size() == lowerSize))
        throw std::invalid_argument("the snapshot belongs to a scene with other grids");
    if (turn) {
        flipLayouts();
        upper_ = CellGrid(upperLayout_->size());
        lower_ = CellGrid(lowerLayout_->size());
    }
    std::copy(saved.upper.cells().begin(), saved.upper.cells().end(), upper_.cells().begin());
    std::copy(saved.lower.cells().begin(), saved.lower.cells().end(), lower_.cells().begin());
    grains_ = saved.grains;
    movedGrains_.clear(); // the grains the saved state's last step moved
    for (std::uint32_t id = 0; id < grains_.size(); ++id)
        if (saved.counters.stepsDone > 0 && grains_.place[id].movedAtStep == saved.counters.stepsDone)
            movedGrains_.push_back({id, grains_.place[id].cell, grains_.place[id].cameFrom, grains_.level[id]});
    nextIdentity_ = saved.nextIdentity;
    counters_ = saved.counters;
    upperObstacles_ = saved.upperObstacles;
    lowerObstacles_ = saved.lowerObstacles;
    bodies_ = saved.bodies; // their cells are INVALID in the saved lower grid
    // Waking every grain is a superset of the awake set at the time: the sweep's result is the same (R5).
    upperSweep_->clear();
    lowerSweep_->clear();
    markEverythingAwake();
    // A file keeps no count of the last step's speed changes: the grains in motion stand for it.
    if (granular_) counters_.speedChangesLastStep = std::max(counters_.speedChangesLastStep, markGrainsInMotion());
}

// Granular: tells the sweeps which grains are in motion after their fall states were set from
// outside a step, and counts them.
std::int64_t Scene::markGrainsInMotion() {
    std::int64_t count = 0;
    for (std::uint32_t id = 0; id < grains_.size(); ++id) {
        const FallState& fall = grains_.fallOf(id);
        if (!(fall.speed | fall.fraction)) continue;
        const Int3 c = grid(grains_.level[id]).coordinate(grains_.place[id].cell);
        sweepOf(grains_.level[id]).markInMotion(c.x, c.y, c.z);
        ++count;
    }
    return count;
}

std::int64_t Scene::addGrain(GridLevel level, std::uint32_t cell, std::uint32_t rgba) {
    CellGrid& grid = gridRef(level);
    if (cell >= grid.cellCount() || grid[cell] != kEmpty) return -1;
    const std::uint32_t id = grains_.add(level, cell, nextIdentity_++, rgba);
    grid[cell] = CellValue(id);
    sweepOf(level).grainEntered(cell);
    (level == GridLevel::Upper ? counters_.grainsUpper : counters_.grainsLower) += 1;
    return id;
}

bool Scene::removeGrain(GridLevel level, std::uint32_t cell) {
    CellGrid& grid = gridRef(level);
    if (cell >= grid.cellCount() || grid[cell] < 0) return false;
    const std::uint32_t id = std::uint32_t(grid[cell]);
    grid[cell] = kEmpty;
    if (grains_.fallOf(id).gatheringSince) sweepOf(level).sleepingFallRemoved();
    const std::uint32_t moved = grains_.removeBySwap(id);
    if (moved != id) gridRef(grains_.level[id])[grains_.place[id].cell] = CellValue(id);
    // The last step's list follows the renumbering: the removed grain leaves it, the last takes its id.
    std::erase_if(movedGrains_, [&](const GrainMove& move) { return move.grain == id; });
    if (moved != id)
        for (GrainMove& move : movedGrains_)
            if (move.grain == moved) move.grain = id;
    const Int3 c = grid.coordinate(cell);
    sweepOf(level).wakeAroundEmptied(grid, c.x, c.y, c.z);
    (level == GridLevel::Upper ? counters_.grainsUpper : counters_.grainsLower) -= 1;
    return true;
}

std::int64_t Scene::addObstacle(GridLevel level, CellBox box) {
    CellGrid& grid = gridRef(level);
    std::int64_t removed = 0;
    forEachCellIn(grid, box, [&](std::uint32_t n) {
        if (grid[n] >= 0) removed += removeGrain(level, n) ? 1 : 0;
        if (grid[n] == kEmpty) sweepOf(level).cellBlocked(n);
        grid[n] = kInvalid;
    });
    (level == GridLevel::Upper ? upperObstacles_ : lowerObstacles_).push_back(box);
    return removed;
}

void Scene::clearObstacles(GridLevel level) {
    auto& list = level == GridLevel::Upper ? upperObstacles_ : lowerObstacles_;
    if (list.empty()) return;
    const std::vector<CellBox> removed = std::move(list);
    list.clear();
    CellGrid& grid = gridRef(level);
    const LayoutBits& layout = level == GridLevel::Upper ? *upperLayout_ : *lowerLayout_;
    for (const CellBox& box : removed)
        forEachCellIn(grid, box, [&](std::uint32_t n) {
            if (grid[n] != kInvalid || !layout.open(n)) return;
            if (level == GridLevel::Lower && coveredByBody(n)) return; // a body stands there
            grid[n] = kEmpty;
            const Int3 c = grid.coordinate(n);
            sweepOf(level).wakeAroundEmptied(grid, c.x, c.y, c.z);
        });
}

const std::vector<CellBox>& Scene::obstacles(GridLevel level) const {
    return level == GridLevel::Upper ? upperObstacles_ : lowerObstacles_;
}

} // namespace sandcore
