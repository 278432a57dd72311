#include "sandcore/surface_upkeep.hpp"

#include "sandcore/inner_grains.hpp"
#include "sandcore/normals.hpp"

#include "layer_neighbourhood.hpp"

#include <algorithm>
#include <cstdint>

namespace sandcore {

void SurfaceUpkeep::rebuild(const Scene& scene) {
    inner_.assign(scene.grains().size(), 0);
    innerCount_ = flagInnerGrains(scene, inner_);
    for (GridLevel level : {GridLevel::Lower, GridLevel::Upper}) {
        const CellGrid& grid = scene.grid(level);
        const Int3 s = grid.size();
        std::vector<int>& heights = heights_[index(level)];
        heights = columnHeights(grid);
        std::vector<Vec3>& normals = normals_[index(level)];
        normals.resize(heights.size());
        for (int z = 0; z < s.z; ++z)
            for (int x = 0; x < s.x; ++x)
                normals[std::size_t(x) + std::size_t(s.x) * std::size_t(z)] = columnNormal(heights, s, x, z);
        columnStamp_[index(level)].assign(heights.size(), 0);
        columnListed_[index(level)].assign(heights.size(), 0);
    }
    listed_.assign(scene.grains().size(), 0);
    grainStamp_.assign(scene.grains().size(), 0);
    gradientStamp_.assign(trackGradient_ ? scene.grains().size() : 0, 0);
    gradient_.clear();
    if (trackGradient_) {
        gradient_.resize(scene.grains().size());
        estimateGrainNormals(scene, NormalMethod::OccupancyGradient, gradient_);
    }
    updateNumber_ = 0;
    changedPlace_.clear();
    changedInner_.clear();
    changedGradient_.clear();
    changedColumns_.clear();
    rebuilt_ = true;
}

void SurfaceUpkeep::clearChanges() {
    for (std::vector<std::uint32_t>* grains : {&changedPlace_, &changedInner_, &changedGradient_}) {
        for (std::uint32_t id : *grains) listed_[id] = 0;
        grains->clear();
    }
    for (const ColumnRef& ref : changedColumns_) columnListed_[index(ref.level)][ref.column] = 0;
    changedColumns_.clear();
    rebuilt_ = false;
}

namespace {
constexpr std::uint8_t kPlaceListed = 1, kInnerListed = 2, kGradientListed = 4;
} // namespace

void SurfaceUpkeep::list(std::uint32_t grain, std::uint8_t bit, std::vector<std::uint32_t>& into) {
    if (listed_[grain] & bit) return;
    listed_[grain] |= bit;
    into.push_back(grain);
}

// A world cell the step filled or emptied, in every grid that holds it (the shared row is in both).
void SurfaceUpkeep::markWorldCell(const Scene& scene, Int3 world) {
    for (GridLevel level : {GridLevel::Lower, GridLevel::Upper}) {
        const CellGrid& grid = scene.grid(level);
        const Int3 origin = origins_[index(level)];
        const int x = world.x - origin.x, y = world.y - origin.y, z = world.z - origin.z;
        if (grid.contains(x, y, z)) changedCells_.emplace_back(level, grid.index(x, y, z));
    }
}

void SurfaceUpkeep::refreshFlag(const Scene& scene, GridLevel level, std::uint32_t cell) {
    const CellValue grain = scene.grid(level)[cell];
    if (grain < 0) return;
    // Neighbouring changed cells share grains: look at each once per update.
    std::uint32_t& seen = grainStamp_[std::size_t(grain)];
    if (seen == updateNumber_) return;
    seen = updateNumber_;
    const std::uint8_t now = isInnerGrain(scene, level, cell) ? 1 : 0;
    std::uint8_t& flag = inner_[std::size_t(grain)];
    if (flag == now) return;
    innerCount_ += now ? 1 : -1;
    flag = now;
    list(std::uint32_t(grain), kInnerListed, changedInner_);
}

// isInnerGrain reads the 6 face neighbours, across the seam too (the lower grid's top row looks
// at the upper grid's layer 1, the upper grid's layer 0 at the lower grid's second row from the
// top): so a changed cell can change the flag of the grain in it and of the grains in its 6 world
// neighbours, in either grid.
void SurfaceUpkeep::refreshInnerAround(const Scene& scene, GridLevel level, std::uint32_t cell) {
    const Int3 c = scene.grid(level).coordinate(cell);
    const Int3 o = origins_[index(level)];
    const Int3 world{c.x + o.x, c.y + o.y, c.z + o.z};
    static constexpr Int3 kAround[7] = {{0, 0, 0}, {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    for (const Int3& d : kAround)
        for (GridLevel other : {GridLevel::Lower, GridLevel::Upper}) {
            const CellGrid& grid = scene.grid(other);
            const Int3 origin = origins_[index(other)];
            const int x = world.x + d.x - origin.x, y = world.y + d.y - origin.y, z = world.z + d.z - origin.z;
            if (grid.contains(x, y, z)) refreshFlag(scene, other, grid.index(x, y, z));
        }
}

// gradientNormal reads the 26 neighbours within the grain's own grid.
void SurfaceUpkeep::refreshGradientAround(const Scene& scene, GridLevel level, std::uint32_t cell) {
    const CellGrid& grid = scene.grid(level);
    const Int3 c = grid.coordinate(cell);
    for (int y = c.y - 1; y <= c.y + 1; ++y)
        for (int z = c.z - 1; z <= c.z + 1; ++z)
            for (int x = c.x - 1; x <= c.x + 1; ++x) {
                if (!grid.contains(x, y, z)) continue;
                const std::uint32_t n = grid.index(x, y, z);
                const CellValue grain = grid[n];
                if (grain < 0) continue;
                std::uint32_t& seen = gradientStamp_[std::size_t(grain)];
                if (seen == updateNumber_) continue;
                seen = updateNumber_;
                const Vec3 now = gradientNormal(grid, n);
                Vec3& normal = gradient_[std::size_t(grain)];
                if (now.x == normal.x && now.y == normal.y && now.z == normal.z) continue;
                normal = now;
                list(std::uint32_t(grain), kGradientListed, changedGradient_);
            }
}

void SurfaceUpkeep::update(const Scene& scene) {
    const GrainStore& grains = scene.grains();
    // A rebuild also restarts the stamps before the 32-bit update number could wrap (after
    // about 1.4e9 steps), when an old stamp could look current.
    if (inner_.size() != grains.size() || heights_[0].empty() || gradient_.size() != (trackGradient_ ? grains.size() : 0) ||
        updateNumber_ > UINT32_MAX - 8) {
        rebuild(scene);
        return;
    }
    changedCells_.clear();
    origins_ = {scene.gridOrigin(GridLevel::Lower), scene.gridOrigin(GridLevel::Upper)};
    // Each moved grain filled its cell and emptied the one it came from (for a transition with
    // no glide, the same world cell in the other grid).
    for (std::uint32_t id : scene.movedGrains()) {
        list(id, kPlaceListed, changedPlace_);
        const GridLevel level = grains.level[id];
        const Int3 c = scene.grid(level).coordinate(grains.cell[id]);
        const Int3 o = origins_[index(level)];
        const Int3 world{c.x + o.x, c.y + o.y, c.z + o.z};
        const MoveCode from = grains.cameFrom[id];
        markWorldCell(scene, world);
        if (from != kNoMove) markWorldCell(scene, {world.x + moveDx(from), world.y + moveDy(from), world.z + moveDz(from)});
    }
    ++updateNumber_;
    for (const auto& [level, cell] : changedCells_) {
        refreshInnerAround(scene, level, cell);
        if (trackGradient_) refreshGradientAround(scene, level, cell);
    }

    // Heights: a filled cell can only raise its column; then each touched column scans down from
    // its (upper bound of the) height to its top grain.
    ++updateNumber_;
    touchedColumns_.clear();
    heightsBefore_.clear();
    for (const auto& [level, cell] : changedCells_) {
        const CellGrid& grid = scene.grid(level);
        const std::uint32_t column = cell % grid.layerSize();
        const int y = int(cell / grid.layerSize());
        int& height = heights_[index(level)][column];
        std::uint32_t& stamp = columnStamp_[index(level)][column];
        if (stamp != updateNumber_) {
            stamp = updateNumber_;
            touchedColumns_.push_back({level, column});
            heightsBefore_.push_back(height);
        }
        if (grid[cell] >= 0) height = std::max(height, y + 1);
    }
    const std::uint32_t normalsPass = ++updateNumber_;
    normalCandidates_.clear();
    for (std::size_t i = 0; i < touchedColumns_.size(); ++i) {
        const ColumnRef& touched = touchedColumns_[i];
        const CellGrid& grid = scene.grid(touched.level);
        const Int3 s = grid.size();
        int& height = heights_[index(touched.level)][touched.column];
        int y = height - 1;
        while (y >= 0 && grid[touched.column + std::uint32_t(y) * grid.layerSize()] < 0) --y;
        height = y + 1;
        if (height == heightsBefore_[i]) continue;
        // Its normal and its 8 neighbours' read this height.
        const int x = int(touched.column % std::uint32_t(s.x)), z = int(touched.column / std::uint32_t(s.x));
        LayerNeighbourhood(x, z, s.x, s.z).forEachWithCentre([&](int dx, int dz) {
            const auto column = std::uint32_t(std::int64_t(x + dx) + std::int64_t(s.x) * (z + dz));
            std::uint32_t& stamp = columnStamp_[index(touched.level)][column];
            if (stamp == normalsPass) return;
            stamp = normalsPass;
            normalCandidates_.push_back({touched.level, column});
        });
    }
    // Recompute after every height is final; list only the columns whose normal really changed.
    for (const ColumnRef& ref : normalCandidates_) {
        const Int3 s = scene.grid(ref.level).size();
        const std::vector<int>& heights = heights_[index(ref.level)];
        const int x = int(ref.column % std::uint32_t(s.x)), z = int(ref.column / std::uint32_t(s.x));
        const Vec3 now = columnNormal(heights, s, x, z);
        Vec3& normal = normals_[index(ref.level)][ref.column];
        if (now.x == normal.x && now.y == normal.y && now.z == normal.z) continue;
        normal = now;
        std::uint8_t& listed = columnListed_[index(ref.level)][ref.column];
        if (listed) continue;
        listed = 1;
        changedColumns_.push_back(ref);
    }
}

} // namespace sandcore
