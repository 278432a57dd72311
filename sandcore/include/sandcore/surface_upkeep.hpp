#pragma once
// R12, R13 kept current by the step: the inner-grain flags and the column normals of a scene,
// updated after each step only around the cells that step changed (Scene::movedGrains and each
// moved grain's cameFrom), so their cost follows the moves, not the grain count. The result is
// exactly what flagInnerGrains and estimateGrainNormals(ColumnHeights) compute from scratch.

#include "sandcore/scene.hpp"
#include "sandcore/vec3.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace sandcore {

/// One column (x, z) of one grid.
struct ColumnRef {
    GridLevel level = GridLevel::Lower; ///< which grid
    std::uint32_t column = 0;           ///< x + sizeX * z
};

class SurfaceUpkeep {
public:
    /// Also keep every grain's occupancy-gradient normal (R12's other method; costs a 3x3x3
    /// look around each changed cell). Takes effect at the next rebuild.
    void setTrackGradientNormals(bool track) { trackGradient_ = track; }
    bool tracksGradientNormals() const { return trackGradient_; } ///< as set
    /// Everything from scratch: after a new scene and after any edit that did not go through
    /// Scene::step (painting, obstacles, undo, load, flip, reset, grain removal).
    void rebuild(const Scene& scene);
    /// After exactly one Scene::step since the last rebuild or update: updates the flags and
    /// normals around the cells that step changed. Rebuilds when the grain count changed.
    void update(const Scene& scene);

    /// 1 for every inner grain (R13), by grain id.
    std::span<const std::uint8_t> innerFlags() const { return inner_; }
    std::int64_t innerCount() const { return innerCount_; } ///< inner grains
    /// Column heights of a grid (as columnHeights), indexed x + sizeX * z.
    std::span<const int> heights(GridLevel level) const { return heights_[index(level)]; }
    /// The thesis's column normals of a grid (as columnNormal), indexed x + sizeX * z.
    std::span<const Vec3> columnNormals(GridLevel level) const { return normals_[index(level)]; }

    /// Every grain's gradientNormal, by grain id (empty unless tracked).
    std::span<const Vec3> gradientNormals() const { return gradient_; }

    // What changed since the last clearChanges(), for a consumer that mirrors these (the
    // renderer's GPU buffers); several steps between two frames add up, each entry listed once.
    /// True when a rebuild happened: everything may have changed, ids included.
    bool rebuilt() const { return rebuilt_; }
    /// Grains that changed cells (Scene::movedGrains of every update).
    std::span<const std::uint32_t> movedGrains() const { return changedPlace_; }
    /// Grains whose inner flag changed.
    std::span<const std::uint32_t> changedInnerFlags() const { return changedInner_; }
    /// Grains whose gradient normal changed (when tracked).
    std::span<const std::uint32_t> changedGradientNormals() const { return changedGradient_; }
    /// Columns whose normal changed.
    std::span<const ColumnRef> changedColumns() const { return changedColumns_; }
    /// Empties the lists above and clears rebuilt().
    void clearChanges();

private:
    static std::size_t index(GridLevel level) { return level == GridLevel::Upper ? 1 : 0; }
    void markWorldCell(const Scene& scene, Int3 world);
    void refreshInnerAround(const Scene& scene, GridLevel level, std::uint32_t cell);
    void refreshFlag(const Scene& scene, GridLevel level, std::uint32_t cell);
    void refreshGradientAround(const Scene& scene, GridLevel level, std::uint32_t cell);
    void list(std::uint32_t grain, std::uint8_t bit, std::vector<std::uint32_t>& into);

    bool trackGradient_ = false;
    std::array<Int3, 2> origins_{};                     // Scene::gridOrigin of both grids, this update
    std::vector<Vec3> gradient_;
    std::vector<std::uint32_t> changedGradient_;
    std::vector<std::uint8_t> inner_;
    std::int64_t innerCount_ = 0;
    std::array<std::vector<int>, 2> heights_;
    std::array<std::vector<Vec3>, 2> normals_;
    std::array<std::vector<std::uint32_t>, 2> columnStamp_; // last update that looked at a column
    std::uint32_t updateNumber_ = 0;                    // stamps: which update last looked at a grain or column
    std::vector<std::uint32_t> grainStamp_, gradientStamp_;
    bool rebuilt_ = true;
    std::vector<std::uint8_t> listed_;                  // per grain: bits of the change lists naming it
    std::array<std::vector<std::uint8_t>, 2> columnListed_; // per column: in changedColumns_
    std::vector<std::uint32_t> changedPlace_;
    std::vector<std::uint32_t> changedInner_;
    std::vector<ColumnRef> changedColumns_;
    std::vector<ColumnRef> normalCandidates_;           // scratch: columns around changed heights
    std::vector<ColumnRef> touchedColumns_;                       // scratch: columns whose height may have changed
    std::vector<int> heightsBefore_;                              // scratch: their heights before the step
    std::vector<std::pair<GridLevel, std::uint32_t>> changedCells_; // scratch: cells the step filled or emptied
};

} // namespace sandcore
