// SPDX-License-Identifier: MIT
#pragma once
// A scene: an upper and a lower grid that share one row (R4), the grains in them, and the
// step that moves them (R2, R3, R5, R6). Build one with the functions in scenes.hpp.

#include "sandcore/cell_grid.hpp"
#include "sandcore/grain_store.hpp"
#include "sandcore/moving_body.hpp"
#include "sandcore/physics_settings.hpp"
#include "sandcore/task_system.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace sandcore {

class WorkerPool;
class GridSweep;
class LayoutBits;
class GranularRules;
class NeckFlow;
struct PushSearch;

/// What a scene's two grids are, as plain facts: what the step does where they meet and which
/// edits the scene takes. The recipes in scenes.hpp fill it (sceneShapeOf); the defaults are an
/// open box under a release grid, as the canvas and the sculpture are.
struct SceneShape {
    /// The shared row is an hourglass's neck: under granular rules grains pass it at the
    /// Beverloo discharge rate (PH4). False: sand falls through the shared row as anywhere else.
    bool hourglassNeck = false;
    /// The two grids are the two bulbs of one vessel, so the scene may be turned over (T1, flip()).
    bool turnsOver = false;
    /// Moving bodies may stand in the lower grid (addBody). A scene that turns over takes none:
    /// a body would stand on its head.
    bool takesBodies = true;
    bool operator==(const SceneShape&) const = default;
};

/// How a step runs; threads and sleeping never change the result, seed and physics do.
struct StepSettings {
    std::uint64_t seed = 1;  ///< feeds the counter-based randomness of slips (R3)
    int threads = 1;         ///< threads that share a step (R6); the result is the same for any count
    bool sleeping = true;    ///< R5: visit only awake grains; false = sweep every cell (same result, slower)
    PhysicsSettings physics; ///< PH1: classic or granular rules, repose angle, gravity
    /// The host's task system for the step's parallel loops, split `threads` ways; inactive
    /// (the default): the scene starts threads of its own.
    TaskSystem tasks{};
};

/// An axis-aligned box of cells, min inclusive, max exclusive, in one grid's coordinates.
struct CellBox {
    Int3 min; ///< first cell, inclusive
    Int3 max; ///< past-the-end cell, exclusive
};

/// R14 counters.
struct SceneCounters {
    std::int64_t grainsUpper = 0;   ///< filled cells in the upper grid
    std::int64_t grainsLower = 0;   ///< filled cells in the lower grid
    std::int64_t movesLastStep = 0; ///< grains moved by the last step, transitions included
    std::int64_t visitedLastStep = 0; ///< cells the last step looked at (shows what R5 saves)
    /// Granular: grains whose fall the last step changed without moving them (a grain gathering
    /// its next cell of progress, riding a moving grain, stopping, or held at the neck). Not
    /// saved in files: a loaded scene counts its grains in motion here.
    std::int64_t speedChangesLastStep = 0;
    std::uint64_t stepsDone = 0;    ///< steps since the last reset
};

/// Everything that makes up a scene's state, saved so an edit can be undone (P7).
struct SceneSnapshot {
    CellGrid upper;                        ///< upper grid cells
    CellGrid lower;                        ///< lower grid cells
    GrainStore grains;                     ///< per-grain records
    std::uint32_t nextIdentity = 0;        ///< identity the next new grain gets
    SceneCounters counters;                ///< R14 counters
    std::vector<CellBox> upperObstacles;   ///< obstacles of the upper grid
    std::vector<CellBox> lowerObstacles;   ///< obstacles of the lower grid
    bool flipped = false;                  ///< the hourglass was turned over an odd number of times
    std::vector<MovingBody> bodies;        ///< moving bodies standing in the lower grid
};

/// Two grids of sand and the step that moves it: the library's main object. Movable, not copyable.
class Scene {
public:
    /// A scene from two layouts (cells kEmpty or kInvalid only) of equal x and z size, and the
    /// upper-grid cells that reset fills with sand. Throws std::invalid_argument otherwise.
    Scene(SceneShape shape, CellGrid upperLayout, CellGrid lowerLayout, std::vector<std::uint32_t> upperFill,
          StepSettings settings = {});
    ~Scene();
    Scene(Scene&&) noexcept;
    Scene& operator=(Scene&&) noexcept;

    const SceneShape& shape() const { return shape_; } ///< what the grids are (neck, turning over, bodies)

    /// One simulation step (R3): the lower grid, then the upper grid, bottom-up, then the
    /// transition of the shared row from the upper into the lower grid (R4).
    void step();
    /// Empties both grids (obstacles stay) and refills the initial sand; counters restart.
    void reset();

    const CellGrid& grid(GridLevel level) const { return level == GridLevel::Upper ? upper_ : lower_; } ///< a grid
    const GrainStore& grains() const { return grains_; } ///< per-grain records for drawing
    /// Grain id's fall state after the last step (granular; classic keeps every grain at rest).
    /// GrainStore::fallOf may hold the state of a grain asleep in its fall (a gatherer or a grain
    /// riding one) as of an earlier step.
    FallState fallOf(std::uint32_t id) const;
    const SceneCounters& counters() const { return counters_; } ///< R14
    /// The grains the last step moved (transitions included), each once with where it is now (its
    /// record's cell, level and cameFrom), in no particular order.
    std::span<const GrainMove> movedGrains() const;
    std::int64_t grainCount() const { return std::int64_t(grains_.size()); } ///< grains in both grids
    /// True once a step has moved nothing and changed no grain's fall: no later step will move
    /// anything until the scene is edited. (A granular grain falling from rest gathers its first
    /// cell for several steps without a move: those steps are not settled.)
    bool settled() const {
        return counters_.stepsDone > 0 && counters_.movesLastStep == 0 && counters_.speedChangesLastStep == 0;
    }
    /// R7: a 64-bit hash of both grids' cell contents, stable across runs and platforms.
    std::uint64_t stateHash() const;
    /// What the sweeps keep of the grids (the granular rules' EMPTY and INVALID cells) agrees with the grids:
    /// a check for tests, since every edit of a cell must tell the sweeps (R5).
    bool sweepsMatchCells() const;

    /// World offset of a grid's cell (0, 0, 0), in cells: the lower grid sits at the origin and
    /// the upper grid's bottom row on the lower grid's top row.
    Int3 gridOrigin(GridLevel level) const;

    const StepSettings& settings() const { return settings_; } ///< how steps run
    void setSeed(std::uint64_t seed);   ///< changes the randomness of later steps (granular: wakes every grain)
    void setThreads(int threads);       ///< 1 or more; the result does not change
    /// The threads its steps share, or null on one thread. Idle between steps: work that follows
    /// a step (the surface upkeep, a renderer's stores) may share them too, never during one.
    WorkerPool* workers() const { return settings_.threads > 1 ? pool_.get() : nullptr; }
    void setSleeping(bool sleeping);    ///< R5 on or off; the result does not change
    /// PH1: switches the rules (level, repose angle, gravity) from the next step on; every grain
    /// starts at rest. Throws std::invalid_argument for settings validatePhysics refuses.
    void setPhysics(const PhysicsSettings& physics);
    /// Granular rules and an hourglass neck only: grains per step the neck lets through (PH4), else 0.
    double neckFlowRate() const;

    /// Turns the hourglass over (T1): the sand becomes the exact mirror in y of what it was,
    /// the lower grid becomes the upper and the upper the lower, every grain keeps its identity
    /// and colour, and the drain goes on. Two flips with no step between give back the same
    /// state. Returns false (and changes nothing) unless shape().turnsOver.
    bool flip();
    /// True after an odd number of flips; reset() turns the hourglass upright again.
    bool flipped() const { return flipped_; }
    /// An independent copy of the scene in its current state: the same later steps, the same hash.
    Scene clone() const;

    /// The whole state, for undo.
    SceneSnapshot snapshot() const;
    /// Returns to a state taken by snapshot() of this scene: the state hash and every later
    /// step are as they were then. Throws std::invalid_argument for a snapshot of other grids.
    void restore(const SceneSnapshot& saved);

    /// Places a grain in an EMPTY cell; returns its id, or -1 when the cell is not EMPTY.
    /// rgba 0 means the default sand colours.
    std::int64_t addGrain(GridLevel level, std::uint32_t cell, std::uint32_t rgba = 0);
    /// Removes the grain in a cell; false when the cell holds no grain (obstacles stay).
    bool removeGrain(GridLevel level, std::uint32_t cell);

    /// R11: marks a box of a grid INVALID (clipped to the grid); grains inside it are removed.
    /// Returns the number of grains removed.
    std::int64_t addObstacle(GridLevel level, CellBox box);
    /// Removes every obstacle of a grid; their cells become EMPTY again where the layout allows.
    void clearObstacles(GridLevel level);
    /// The obstacles placed in a grid, in the order they were added.
    const std::vector<CellBox>& obstacles(GridLevel level) const;

    /// Moving bodies (moving_body.hpp), all in the lower grid of a canvas or sculpture. Each
    /// call is an edit between steps, on the calling thread: the result does not depend on the
    /// threads or on sleeping. Grains in the cells a body enters are pushed out of it (never
    /// destroyed or duplicated; they keep their ids), and every cell it enters or leaves and every
    /// grain pushed wakes its neighbours as the other edits do (R5).
    /// Places a body; its cells must lie in the grid and hold no wall (INVALID), and the grains
    /// in them are pushed out. Returns its index, or -1 (nothing placed) when it does not fit.
    /// Throws std::invalid_argument unless shape().takesBodies, or for an empty shape.
    std::int64_t addBody(MovingBody body);
    /// Moves body `index` toward `target` (its anchor's cell) in at most maxCells unit moves
    /// along the straight line, each a move by one cell along one axis (so it never tunnels).
    /// A unit move into a wall, past the grid's edge, or into a grain that finds no EMPTY cell
    /// near enough (kPushSearchCells) stops the body where it is.
    BodyMove moveBody(std::size_t index, Int3 target, int maxCells);
    /// Turns body `index` to a heading (quarter turns 0..3) in place, pushing as a move does.
    BodyMove turnBody(std::size_t index, int quarterTurns);
    /// Removes body `index` (later bodies take the index before theirs); its cells become EMPTY.
    void removeBody(std::size_t index);
    const std::vector<MovingBody>& bodies() const { return bodies_; } ///< the bodies standing, by index
    /// The lower-grid cells body `index` covers, in ascending order.
    std::vector<std::uint32_t> bodyCells(std::size_t index) const;
    /// Grains bodies pushed since the scene was built (not part of a snapshot).
    std::int64_t grainsPushedTotal() const { return grainsPushedTotal_; }
    /// Most cells a push walks along a grain's layer before it climbs to the surface (the way
    /// out most pushes take, docs/engine.md "Moving bodies").
    static constexpr int kPushReach = 8;
    /// Most cells a push with no such way looks through for an EMPTY cell before the body stops instead.
    static constexpr int kPushSearchCells = 1 << 16;

    /// A grid's layout (EMPTY and INVALID cells only, no obstacles, no grains), turned over as the
    /// scene is (flipped()): with fillCells(), shape() and settings() what the constructor needs
    /// to build this scene again, after mirroring both layouts back when it is turned over.
    /// Built on each call from the one bit per cell the scene keeps.
    CellGrid layout(GridLevel level) const;
    /// The upper-grid cells reset() fills with sand, in the order they are filled.
    const std::vector<std::uint32_t>& fillCells() const { return upperFill_; }
    /// The identity the next new grain gets (part of snapshot(), without copying the grids).
    std::uint32_t nextIdentity() const { return nextIdentity_; }

private:
    CellGrid& gridRef(GridLevel level) { return level == GridLevel::Upper ? upper_ : lower_; }
    GridSweep& sweepOf(GridLevel level);
    void transition();
    void rebuildCells(GridLevel level);
    void markEverythingAwake();
    void configurePhysics();
    void transitionGranular();
    void drawIntoNeck(int x, int z); // the grain above an emptied neck cell follows at the flow speed
    void listTransition(std::uint32_t grain, std::uint32_t lowerCell);
    void moveListedIntoLowerGrid();
    std::int64_t markGrainsInMotion(); // returns how many grains are in motion
    void flipLayouts();
    void makeSweeps();
    bool bodyCellsAt(const MovingBody& body, std::vector<std::uint32_t>& cells) const;
    bool shiftBody(MovingBody& body, const MovingBody& next, Int3 ahead, std::int64_t& pushed);
    bool pushOut(std::uint32_t cell, Int3 ahead);
    bool straightWayOut(std::uint32_t cell, Int3 ahead);
    bool nearestWayOut(std::uint32_t cell, Int3 ahead);
    void dropPushedFromMoveList();
    void moveGrainAside(std::uint32_t from, std::uint32_t to);
    bool coveredByBody(std::uint32_t lowerCell) const;

    SceneShape shape_;
    StepSettings settings_;
    std::unique_ptr<LayoutBits> upperLayout_, lowerLayout_; // the grids as built: what reset restores
    CellGrid upper_, lower_;
    std::vector<std::uint32_t> upperFill_;
    std::vector<CellBox> upperObstacles_, lowerObstacles_;
    GrainStore grains_;
    std::uint32_t nextIdentity_ = 0;
    SceneCounters counters_;
    bool flipped_ = false;
    std::unique_ptr<GridSweep> upperSweep_, lowerSweep_;
    std::unique_ptr<WorkerPool> pool_;
    std::unique_ptr<GranularRules> granular_; // null: classic
    std::unique_ptr<NeckFlow> neckFlow_;      // granular rules at an hourglass neck only
    std::vector<MovingBody> bodies_;             // bodies(); their cells are INVALID in lower_
    std::unique_ptr<PushSearch> pushSearch_;     // scratch of the pushes, made at the first
    std::int64_t grainsPushedTotal_ = 0;
    std::vector<std::uint32_t> transitionReady_; // scratch of transitionGranular
    std::vector<GrainMove> movedGrains_;         // movedGrains(); a flip moves every grain
    std::size_t listedTransitions_ = 0;          // grains a transition passed that their sweep listed (scratch of step)
    std::size_t upperMovesBegin_ = 0;            // where the upper grid's moves start in movedGrains_ (scratch of step)
};

/// Runs task(0) .. task(count - 1) side by side on the threads of `pool` (Scene::workers(), the
/// caller's thread among them), or one after another on this thread when pool is null. For work
/// that follows a step, never during one.
void parallelFor(WorkerPool* pool, int count, const std::function<void(int)>& task);

} // namespace sandcore
