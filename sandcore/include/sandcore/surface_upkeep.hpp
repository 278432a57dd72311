// SPDX-License-Identifier: MIT
#pragma once
// R12, R13 kept current by the step: the inner-grain flags and the normals of a scene, updated
// after each step from what it moved, so their cost follows the moves, not the grain count. The
// result is exactly what flagInnerGrains, estimateGrainNormals and columnHeights compute from
// scratch.
//
// How: per grid, one bit per cell says which cells held a grain after the last update. A step's
// moved grains (Scene::movedGrains, each with its cameFrom) name every cell it filled or left;
// those whose occupancy differs from the bits are its net changes, found from the list and the
// bits alone (a cell filled and left in one step did not change). In a draining bulb a column
// of k falling grains moves k grains but changes 2 cells (its bottom filled, its top emptied).
// Only net changes alter a neighbour's flag, gradient normal or column height; a moved grain's
// own flag and normal are looked at again in its new cell, from the bits.
//
// A consumer that works out the flags and normals itself from the bits (the renderer's GPU path)
// asks for less (SurfaceTracking): then an update keeps only the bits, the moved grains' places,
// the cells that changed and the inner count, with no work per moved grain beyond its place.

#include "sandcore/normals.hpp"
#include "sandcore/scene.hpp"
#include "sandcore/vec3.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace sandcore {

/// One column (x, z) of one grid.
struct ColumnRef {
    GridLevel level = GridLevel::Lower; ///< which grid
    std::uint32_t column = 0;           ///< x + sizeX * z
};

/// Where a moved grain is after an update: what the renderer's copy of its place needs, gathered
/// while the upkeep reads the grain anyway, so a consumer writes it without reading the grain store.
struct MovedPlace {
    std::uint32_t grain = 0;    ///< grain id
    std::uint32_t cell = 0;     ///< cell index in its grid
    std::uint32_t level = 0;    ///< 0 lower grid, 1 upper grid
    MoveCode cameFrom = 0;      ///< its last move
    std::uint32_t movedStep = 0; ///< low 32 bits of the step of that move
};

/// One cell of one grid.
struct CellRef {
    GridLevel level = GridLevel::Lower; ///< which grid
    std::uint32_t cell = 0;             ///< cell index in it
};

/// What a SurfaceUpkeep keeps besides the occupancy bits, the moved places, the changed cells
/// and the inner count (always kept).
struct SurfaceTracking {
    /// Per grain: its inner flag (isInner, changedInnerFlags) and, with gradientNormals, its
    /// occupancy-gradient normal. Off, the consumer derives both from the bits itself.
    bool grainFlags = true;
    bool gradientNormals = false; ///< per-grain gradient normals (only with grainFlags)
    bool columnNormals = true;    ///< column heights and the thesis's column normals
    friend bool operator==(const SurfaceTracking&, const SurfaceTracking&) = default;
};

/// A read-only view of one bit per cell of a grid (SurfaceUpkeep::grainBits, hideBits), laid out
/// as the renderer uploads it: cell n (CellGrid's index) is bit n % 32 of word n / 32, bit 0 the
/// lowest, the same on any byte order; bits past the last cell are 0. Valid until the upkeep's
/// next rebuild or update.
class CellBitWords {
public:
    /// Over bytes holding cell n in bit n % 8 of byte n / 8, a whole number of 32-bit words.
    explicit CellBitWords(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
    std::uint32_t wordCount() const { return std::uint32_t(bytes_.size() / 4); } ///< words in the view
    /// Word w: cells 32w .. 32w+31.
    std::uint32_t word(std::uint32_t w) const {
        const std::uint8_t* b = bytes_.data() + std::size_t(w) * 4;
        return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
    }
    bool test(std::uint32_t n) const { return (bytes_[n >> 3] >> (n & 7u)) & 1u; } ///< cell n's bit

private:
    std::span<const std::uint8_t> bytes_;
};

class SurfaceUpkeep {
public:
    SurfaceUpkeep();
    ~SurfaceUpkeep();
    SurfaceUpkeep(SurfaceUpkeep&&) noexcept;
    SurfaceUpkeep& operator=(SurfaceUpkeep&&) noexcept;

    /// How many gradient sums there are: a key modulo this names the sums.
    static constexpr std::size_t kGradientKeys = 19 * 19 * 19;
    /// How many keys there are (gradientKeyOf(grain) is below this): the gradient sums and the
    /// occlusion level (occlusionLevel of occupiedNeighbours), key = sums + kGradientKeys * level.
    static constexpr std::size_t kSurfaceKeys = kGradientKeys * kOcclusionLevels;
    /// The normal a key stands for (gradientNormal's floats).
    static Vec3 normalOfGradientKey(std::uint16_t key);
    /// The occlusion level a key stands for (0..kOcclusionLevels-1).
    static int occlusionLevelOfKey(std::uint16_t key);
    /// Also keep every grain's occupancy-gradient normal (R12's other method; costs a 3x3x3
    /// look at each moved grain and around each changed cell). Takes effect at the next rebuild.
    void setTrackGradientNormals(bool track) { tracking_.gradientNormals = track; }
    /// True when per-grain gradient normals are kept (grainFlags and gradientNormals).
    bool tracksGradientNormals() const { return tracking_.grainFlags && tracking_.gradientNormals; }
    /// What to keep (see SurfaceTracking). Takes effect at the next rebuild.
    void setTracking(SurfaceTracking tracking) { tracking_ = tracking; }
    SurfaceTracking tracking() const { return tracking_; } ///< as set
    /// What the last rebuild took from setTracking: what the lists and accessors hold now.
    SurfaceTracking kept() const { return {trackFlags_, trackGradient_, trackColumns_}; }
    /// Everything from scratch: after a new scene and after any edit that did not go through
    /// Scene::step (painting, obstacles, undo, load, flip, reset, grain removal).
    void rebuild(const Scene& scene);
    /// After exactly one Scene::step since the last rebuild or update: updates the flags and
    /// normals the step changed. Rebuilds when the grain count changed.
    void update(const Scene& scene);

    std::uint32_t grainCount() const { return grainCount_; } ///< grains it knows
    /// True for an inner grain (R13), by grain id (tracking().grainFlags only).
    bool isInner(std::uint32_t grain) const { return grains_[grain].inner != 0; }
    std::int64_t innerCount() const { return innerCount_; } ///< inner grains (always kept)
    /// Column heights of a grid (as columnHeights), indexed x + sizeX * z (tracking().columnNormals only).
    std::span<const int> heights(GridLevel level) const { return heights_[index(level)]; }
    /// The thesis's column normals of a grid (as columnNormal), indexed x + sizeX * z (tracking().columnNormals only).
    std::span<const Vec3> columnNormals(GridLevel level) const { return normals_[index(level)]; }
    /// Per cell of a grid: holds a grain (as of the last update).
    CellBitWords grainBits(GridLevel level) const;
    /// Per cell of a grid: is not EMPTY (a grain or INVALID: hides a neighbour).
    CellBitWords hideBits(GridLevel level) const;
    /// A grain's gradientNormal, by grain id (when tracked; else (0, 1, 0)).
    Vec3 gradientNormal(std::uint32_t grain) const;
    /// A grain's occupancy-gradient sums and occlusion level as one key (when tracked):
    /// normalOfGradientKey gives its normal, occlusionLevelOfKey its occlusion.
    std::uint16_t gradientKeyOf(std::uint32_t grain) const { return grains_[grain].gradient; }

    // What changed since the last clearChanges(), for a consumer that mirrors these (the
    // renderer's GPU buffers); several steps between two frames add up, each entry listed once.
    /// True when a rebuild happened: everything may have changed, ids included.
    bool rebuilt() const { return rebuilt_; }
    /// Grains that changed cells (Scene::movedGrains of every update), each once (tracking().grainFlags only).
    std::span<const std::uint32_t> movedGrains() const { return changedPlace_; }
    /// Cells whose bits changed, in update order (a cell may be listed by several updates).
    std::span<const CellRef> changedCells() const { return changedCellsListed_; }
    /// Calls f(const MovedPlace&) for the place of every grain moved since clearChanges(), in
    /// update order: a grain moved by several updates comes once per update, the last its place
    /// now. The last update's places are read from the scene's list of moves (Scene::movedGrains),
    /// not copied: that list holds them until the scene steps again, so whoever steps it again
    /// before clearChanges() calls retainMoves() first (else placesComplete() turns false).
    template <class F> void forEachMovedPlace(F&& f) const { forEachMovedPlace(nullptr, f); }
    /// As forEachMovedPlace, with the last update's places shared out among the pool's threads
    /// (null: all on this one) after the earlier updates' on this one: f is called side by side
    /// for different grains (the last update lists each grain once), each grain's last place last.
    template <class F> void forEachMovedPlace(WorkerPool* pool, F&& f) const {
        for (const MovedPlace& place : retainedPlaces_) f(place);
        shareOut(pool, latestMoves_.size(), [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) f(placeOf(latestMoves_[i], latestStep_));
        });
    }
    /// How many places forEachMovedPlace gives.
    std::size_t movedPlaceCount() const { return retainedPlaces_.size() + latestMoves_.size(); }
    /// Copies the last update's places out of the scene's list of moves, which the scene's next
    /// step overwrites: call it before stepping the scene again while the changes are not cleared.
    void retainMoves();
    /// False when an update's places were lost (the scene stepped again before retainMoves or
    /// clearChanges): forEachMovedPlace then misses some moved grains, and a consumer that mirrors
    /// the places re-reads every grain's. True again after clearChanges() or a rebuild.
    bool placesComplete() const { return placesComplete_; }
    /// Grains whose inner flag changed.
    std::span<const std::uint32_t> changedInnerFlags() const { return changedInner_; }
    /// Grains whose gradient normal changed (when tracked).
    std::span<const std::uint32_t> changedGradientNormals() const { return changedGradient_; }
    /// Columns whose normal changed.
    std::span<const ColumnRef> changedColumns() const { return changedColumns_; }
    /// Empties the lists above and clears rebuilt() (and the places: nothing is retained).
    void clearChanges();
    /// Cells the last update found filled or emptied, each once, in either grid (0 after a rebuild).
    std::size_t netChangesLastUpdate() const { return changedCells_.size(); }

private:
    struct Bits; // the grids' shapes and occupancy bits (surface_bits.hpp)
    // All that is kept per grain, in one record: a moved grain costs one cache line, not four.
    struct GrainSurface {
        std::uint32_t seen = 0;     // (update number << 2) | which of flag (1), gradient (2) it looked at
        std::uint16_t gradient = 0; // occupancy-gradient sums and occlusion level, packed (see surfaceKey)
        std::uint8_t inner = 0;     // 1 for an inner grain
        std::uint8_t listed = 0;    // bits of the change lists naming it
    };
    // Fewer places than this are not worth waking another thread for.
    static constexpr std::size_t kPlacesPerPiece = 2048;
    // Calls part(begin, end) over pieces of [0, count): side by side, one per thread of the pool,
    // from kPlacesPerPiece items on; else once, on this thread.
    static void shareOut(WorkerPool* pool, std::size_t count, const std::function<void(std::size_t, std::size_t)>& part);
    static std::size_t index(GridLevel level) { return level == GridLevel::Upper ? 1 : 0; }
    static MovedPlace placeOf(const GrainMove& move, std::uint32_t step) {
        return {move.grain, move.cell, move.level == GridLevel::Upper ? 1u : 0u, move.cameFrom, step};
    }
    void forgetPlaces();
    bool firstLook(GrainSurface& grain, std::uint32_t what) const;
    void syncCell(const Scene& scene, GridLevel level, std::uint32_t cell);
    bool innerAt(const Scene& scene, GridLevel level, std::uint32_t cell) const;
    std::uint16_t gradientKeyAt(const Scene& scene, GridLevel level, std::uint32_t cell) const;
    void refreshFlag(const Scene& scene, GridLevel level, std::uint32_t cell, std::uint32_t grain);
    void refreshGradient(const Scene& scene, GridLevel level, std::uint32_t cell, std::uint32_t grain);
    void refreshInnerAround(const Scene& scene, GridLevel level, std::uint32_t cell);
    void refreshGradientAround(const Scene& scene, GridLevel level, std::uint32_t cell);
    void updateHeights(const Scene& scene, WorkerPool* pool);
    struct GridShare;
    void updateHeightsOf(const Scene& scene, GridShare& share, std::uint32_t heightsPass, std::uint32_t normalsPass);
    void list(std::uint32_t grain, std::uint8_t bit, std::vector<std::uint32_t>& into);
    void syncMovedGrains(const Scene& scene, WorkerPool* pool);
    template <class Part> void forEachShare(WorkerPool* pool, Part&& part);
    void flipMoves(const Scene& scene, GridShare& share);
    template <int Only> void flipMovesOf(const Scene& scene, GridShare& share);
    static void flipLeft(Bits& kept, GridLevel level, std::uint32_t cell, GridShare& share);
    void applyNetChanges(GridShare& share);
    static bool inSharedRow(const Bits& kept, GridLevel level, std::uint32_t cell);
    void setCell(GridLevel level, std::uint32_t cell, bool filled);
    void changeCell(GridLevel level, std::uint32_t cell, bool filled);
    std::int64_t innerAround(GridLevel level, Int3 c) const;
    std::int64_t innerChangeInside(GridLevel level, std::uint32_t cell) const;
    bool innerFromBits(GridLevel level, std::uint32_t cell, Int3 c) const;
    bool hidesFromBits(GridLevel level, int x, int y, int z) const;

    SurfaceTracking tracking_;
    bool trackGradient_ = false;                        // as of the last rebuild: tracking_'s
    bool trackFlags_ = true;
    bool trackColumns_ = true;
    bool built_ = false;                                // rebuild ran
    std::uint32_t grainCount_ = 0;
    std::array<Int3, 2> origins_{};   // Scene::gridOrigin of both grids, this update
    std::unique_ptr<Bits> bits_;
    std::vector<GrainSurface> grains_;
    std::int64_t innerCount_ = 0;
    std::array<std::vector<int>, 2> heights_;
    std::array<std::vector<Vec3>, 2> normals_;
    std::array<std::vector<std::uint32_t>, 2> columnStamp_; // last update that looked at a column
    std::uint32_t updateNumber_ = 0;                        // stamps: which update last looked at a grain or column
    bool rebuilt_ = true;
    std::array<std::vector<std::uint8_t>, 2> columnListed_; // per column: in changedColumns_
    std::vector<std::uint32_t> changedPlace_;
    std::vector<std::uint32_t> changedInner_;
    std::vector<std::uint32_t> changedGradient_;
    std::vector<ColumnRef> changedColumns_;
    std::vector<MovedPlace> retainedPlaces_;              // earlier updates' places since clearChanges (retainMoves)
    std::span<const GrainMove> latestMoves_;              // the last update's moves: the scene's list, not copied
    std::uint32_t latestStep_ = 0;                        // the step they moved in (low 32 bits)
    bool placesComplete_ = true;                          // no update's places lost since clearChanges
    std::vector<CellRef> changedCells_;                   // scratch: cells the step filled or emptied, net
    struct NetCell {
        CellRef ref;
        bool filled = false;
    };
    // Scratch of an update: what one thread found and did in the grids it owns (with the scene's
    // threads, one grid each; else one share owns both).
    struct GridShare {
        unsigned levels = 3;              // the grids it owns: bit 0 lower, bit 1 upper
        std::vector<NetCell> net;         // the net changes its flips found
        std::vector<CellRef> fromGrid;    // shared-row cells, synced from the grid afterwards
        std::vector<CellRef> otherLeaves; // cells its moves left in a grid it does not own: flipped afterwards
        std::vector<CellRef> changed;     // the net changes it applied
        std::vector<NetCell> nearEdge;    // net changes whose inner count reads both grids: applied afterwards
        std::int64_t innerChange = 0;     // what the changes it applied did to the inner count
        std::vector<ColumnRef> touchedColumns;   // columns whose height may have changed
        std::vector<int> heightsBefore;          // their heights before the step
        std::vector<ColumnRef> normalCandidates; // columns around changed heights
        std::vector<ColumnRef> changedColumns;   // columns whose normal changed, not yet listed
    };
    std::array<GridShare, 2> shares_;
    std::vector<CellRef> changedCellsListed_;             // changedCells_ of every update since clearChanges
};

} // namespace sandcore
