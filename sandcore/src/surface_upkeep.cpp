// SPDX-License-Identifier: MIT
#include "sandcore/surface_upkeep.hpp"

#include "sandcore/inner_grains.hpp"
#include "sandcore/normals.hpp"
#include "worker_pool.hpp"

#include "layer_neighbourhood.hpp"
#include "surface_bits.hpp"
#include "surface_shares.hpp"

#include <algorithm>
#include <cstdint>

namespace sandcore {

using surface::kGradientListed;
using surface::kInnerListed;
using surface::prefetch;

namespace {

// occupancyGradientNormal of every sum a 3x3x3 neighbourhood can give (each in -9..9): the same
// floats, without a square root and three divisions per grain.
// A grain's gradient is kept as its sums (gx, gy, gz), each in -9..9, packed in 16 bits: 2 bytes
// per grain instead of a 12-byte normal, and a table gives the normal. The 3 bits the sums leave
// free hold the grain's occlusion level, which changes exactly where its gradient may: with the
// occupancy of one of its 26 neighbours.
std::uint16_t gradientKey(int gx, int gy, int gz) { return std::uint16_t((gx + 9) + 19 * (gy + 9) + 361 * (gz + 9)); }
std::uint16_t surfaceKey(int gx, int gy, int gz, int occupied) {
    return std::uint16_t(gradientKey(gx, gy, gz) + SurfaceUpkeep::kGradientKeys * std::size_t(occlusionLevel(occupied)));
}
constexpr std::size_t kGradientKeys = SurfaceUpkeep::kGradientKeys;

class GradientTable {
public:
    GradientTable() {
        for (int gz = -9; gz <= 9; ++gz)
            for (int gy = -9; gy <= 9; ++gy)
                for (int gx = -9; gx <= 9; ++gx) normals_[gradientKey(gx, gy, gz)] = occupancyGradientNormal(gx, gy, gz);
    }
    const Vec3& operator[](std::uint16_t key) const { return normals_[key % kGradientKeys]; }

private:
    Vec3 normals_[kGradientKeys];
};

const GradientTable& gradientTable() {
    static const GradientTable table;
    return table;
}

// gradientNormal's sums, read from the grid: for cells at the grid's edge.
std::uint16_t gradientKeyFromGrid(const CellGrid& grid, std::uint32_t cell) {
    const Int3 g = occupancyGradientSums(grid, cell);
    return surfaceKey(g.x, g.y, g.z, occupiedNeighbours(grid, cell));
}

// For the 3 bits of a row (x-1, x, x+1): how many grains, and their summed x offsets.
constexpr int kGrainsInRow[8] = {0, 1, 1, 2, 1, 2, 2, 3};
constexpr int kXSumOfRow[8] = {0, -1, 0, -1, 1, 0, 1, 0};

} // namespace

Vec3 SurfaceUpkeep::normalOfGradientKey(std::uint16_t key) { return gradientTable()[key]; }

int SurfaceUpkeep::occlusionLevelOfKey(std::uint16_t key) { return int(key / kGradientKeys); }

Vec3 SurfaceUpkeep::gradientNormal(std::uint32_t grain) const {
    if (!trackGradient_) return {0.0f, 1.0f, 0.0f};
    return gradientTable()[grains_[grain].gradient];
}

bool SurfaceUpkeep::firstLook(GrainSurface& grain, std::uint32_t what) const {
    const std::uint32_t stamp = updateNumber_ << 2;
    if ((grain.seen & ~3u) != stamp) grain.seen = stamp;
    if (grain.seen & what) return false;
    grain.seen |= what;
    return true;
}

SurfaceUpkeep::SurfaceUpkeep() : bits_(std::make_unique<Bits>()) {}
SurfaceUpkeep::~SurfaceUpkeep() = default;
SurfaceUpkeep::SurfaceUpkeep(SurfaceUpkeep&&) noexcept = default;
SurfaceUpkeep& SurfaceUpkeep::operator=(SurfaceUpkeep&&) noexcept = default;

CellBitWords SurfaceUpkeep::grainBits(GridLevel level) const { return CellBitWords(bits_->grain[index(level)].bytes()); }
CellBitWords SurfaceUpkeep::hideBits(GridLevel level) const { return CellBitWords(bits_->hide[index(level)].bytes()); }

void SurfaceUpkeep::rebuild(const Scene& scene) {
    trackFlags_ = tracking_.grainFlags;
    trackGradient_ = trackFlags_ && tracking_.gradientNormals;
    trackColumns_ = tracking_.columnNormals;
    const GrainStore& grains = scene.grains();
    grainCount_ = grains.size();
    std::vector<std::uint8_t> inner(grains.size());
    innerCount_ = flagInnerGrains(scene, inner);
    for (GridLevel level : {GridLevel::Lower, GridLevel::Upper}) {
        const CellGrid& grid = scene.grid(level);
        const Int3 s = grid.size();
        bits_->shapes[index(level)] = GridShape(s);
        CellBits& holds = bits_->grain[index(level)];
        CellBits& hides = bits_->hide[index(level)];
        holds.assign(grid.cellCount());
        hides.assign(grid.cellCount());
        for (std::uint32_t n = 0; n < grid.cellCount(); ++n) {
            if (grid[n] >= 0) holds.set(n, true);
            if (grid[n] != kEmpty) hides.set(n, true);
        }
        if (!trackColumns_) {
            heights_[index(level)] = {};
            normals_[index(level)] = {};
            columnStamp_[index(level)] = {};
            columnListed_[index(level)] = {};
            continue;
        }
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
    if (!trackFlags_) grains_ = {};
    else grains_.assign(grains.size(), GrainSurface{});
    for (std::uint32_t id = 0; id < grains_.size(); ++id) {
        grains_[id].inner = inner[id];
        if (trackGradient_) grains_[id].gradient = gradientKeyAt(scene, grains.level[id], grains.place[id].cell);
    }
    updateNumber_ = 0;
    changedCells_.clear();
    changedPlace_.clear();
    forgetPlaces();
    changedInner_.clear();
    changedGradient_.clear();
    changedColumns_.clear();
    changedCellsListed_.clear();
    rebuilt_ = true;
    built_ = true;
}

void SurfaceUpkeep::clearChanges() {
    for (std::vector<std::uint32_t>* grains : {&changedPlace_, &changedInner_, &changedGradient_}) {
        for (std::uint32_t id : *grains) grains_[id].listed = 0;
        grains->clear();
    }
    for (const ColumnRef& ref : changedColumns_) columnListed_[index(ref.level)][ref.column] = 0;
    changedColumns_.clear();
    forgetPlaces();
    changedCellsListed_.clear();
    rebuilt_ = false;
}

void SurfaceUpkeep::list(std::uint32_t grain, std::uint8_t bit, std::vector<std::uint32_t>& into) {
    std::uint8_t& listed = grains_[grain].listed;
    if (listed & bit) return;
    listed |= bit;
    into.push_back(grain);
}

// A cell a moved grain filled or left: a net change when its occupancy now differs from the
// bits (a grain that left a cell another grain filled in the same step changed nothing there).
void SurfaceUpkeep::syncCell(const Scene& scene, GridLevel level, std::uint32_t cell) {
    const CellValue value = scene.grid(level)[cell];
    CellBits& grains = bits_->grain[index(level)];
    if (grains.test(cell) == (value >= 0)) return;
    changeCell(level, cell, value >= 0); // a step only moves grains: EMPTY or a grain, never INVALID
}

void SurfaceUpkeep::setCell(GridLevel level, std::uint32_t cell, bool filled) {
    bits_->grain[index(level)].set(cell, filled);
    bits_->hide[index(level)].set(cell, filled);
}

// A net change: the cell now holds a grain (filled) or is EMPTY. Without per-grain flags the
// inner count follows each change as it is made: only the cell and its 6 world neighbours can
// change their flag, so the count moves by their flags after the change less their flags before
// (a sum of such steps is the change of the whole update, whatever the order). Here in either
// grid, across the seam too; applyNetChanges does the cells away from faces and seam cheaper.
void SurfaceUpkeep::changeCell(GridLevel level, std::uint32_t cell, bool filled) {
    changedCells_.push_back({level, cell});
    if (trackFlags_) return setCell(level, cell, filled);
    const Int3 c = bits_->shapes[index(level)].coordinate(cell);
    const std::int64_t before = innerAround(level, c);
    setCell(level, cell, filled);
    innerCount_ += innerAround(level, c) - before;
}

// The inner grains among a cell and its 6 world neighbours, in either grid (from the bits).
std::int64_t SurfaceUpkeep::innerAround(GridLevel level, Int3 c) const {
    const Bits& kept = *bits_; // one load of the pointer, not one per cell
    static constexpr Int3 kAround[7] = {{0, 0, 0}, {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    const Int3 o = origins_[index(level)];
    std::int64_t inner = 0;
    for (GridLevel other : {GridLevel::Lower, GridLevel::Upper}) {
        const GridShape& shape = kept.shapes[index(other)];
        const Int3 p = origins_[index(other)];
        for (const Int3& d : kAround) {
            const Int3 at{c.x + o.x - p.x + d.x, c.y + o.y - p.y + d.y, c.z + o.z - p.z + d.z};
            if (at.x < 0 || at.y < 0 || at.z < 0 || at.x >= shape.size.x || at.y >= shape.size.y || at.z >= shape.size.z) continue;
            const std::uint32_t n = std::uint32_t(at.x) + shape.row * std::uint32_t(at.z) + shape.layer * std::uint32_t(at.y);
            if (kept.grain[index(other)].test(n) && innerFromBits(other, n, at)) ++inner;
        }
    }
    return inner;
}

// Away from faces and seam, what filling `cell` adds to the inner count (emptying it takes as
// much away), read before the change without reading the cell's own bits: its own flag (its 6
// neighbours hide), and each neighbour grain whose 5 other neighbours hide (the cell decides it).
// The bits are read a row's 3 or 5 cells at a time and combined without branches: the 7 flags
// involved are 42 tests that a branch each made unpredictable.
std::int64_t SurfaceUpkeep::innerChangeInside(GridLevel level, std::uint32_t cell) const {
    const GridShape& shape = bits_->shapes[index(level)];
    const CellBits& grains = bits_->grain[index(level)];
    const CellBits& hides = bits_->hide[index(level)];
    const std::uint32_t row = shape.row, layer = shape.layer;
    // Hide bits: the cell's row x-2..x+2 (bits 0..4); the rows beside, below and above it
    // x-1..x+1 (bits 0..2); single cells further out.
    const unsigned centre = hides.around5(cell);
    const unsigned back = hides.around(cell - row), front = hides.around(cell + row);
    const unsigned down = hides.around(cell - layer), up = hides.around(cell + layer);
    const unsigned backDown = hides.test(cell - row - layer), backUp = hides.test(cell - row + layer);
    const unsigned frontDown = hides.test(cell + row - layer), frontUp = hides.test(cell + row + layer);
    const unsigned back2 = hides.test(cell - 2 * row), front2 = hides.test(cell + 2 * row);
    const unsigned down2 = hides.test(cell - 2 * layer), up2 = hides.test(cell + 2 * layer);
    const unsigned grainsInRow = grains.around(cell);
    const unsigned own = (centre >> 1) & (centre >> 3) & (back >> 1) & (front >> 1) & (down >> 1) & (up >> 1) & 1u;
    const unsigned left = grainsInRow & centre & back & front & down & up & 1u;
    const unsigned right = (grainsInRow >> 2) & (centre >> 4) & (back >> 2) & (front >> 2) & (down >> 2) & (up >> 2) & 1u;
    const unsigned behind = grains.test(cell - row) & back & (back >> 2) & back2 & backDown & backUp & 1u;
    const unsigned ahead = grains.test(cell + row) & front & (front >> 2) & front2 & frontDown & frontUp & 1u;
    const unsigned below = grains.test(cell - layer) & down & (down >> 2) & down2 & backDown & frontDown & 1u;
    const unsigned above = grains.test(cell + layer) & up & (up >> 2) & up2 & backUp & frontUp & 1u;
    return std::int64_t(own + left + right + behind + ahead + below + above);
}

// isInnerGrain from the bits; at the grid's edge and across the seam, isInnerGrain itself.
bool SurfaceUpkeep::innerAt(const Scene& scene, GridLevel level, std::uint32_t cell) const {
    const GridShape& shape = bits_->shapes[index(level)];
    if (!shape.interior(shape.coordinate(cell))) return isInnerGrain(scene, level, cell);
    const CellBits& hides = bits_->hide[index(level)];
    return (hides.around(cell) & 5u) == 5u && hides.test(cell - shape.row) && hides.test(cell + shape.row) &&
           hides.test(cell - shape.layer) && hides.test(cell + shape.layer);
}

// gradientNormal's sums from the bits, 3 cells a read; at the grid's edge from the grid.
std::uint16_t SurfaceUpkeep::gradientKeyAt(const Scene& scene, GridLevel level, std::uint32_t cell) const {
    const GridShape& shape = bits_->shapes[index(level)];
    if (!shape.interior(shape.coordinate(cell))) return gradientKeyFromGrid(scene.grid(level), cell);
    const CellBits& grains = bits_->grain[index(level)];
    int gx = 0, gy = 0, gz = 0, occupied = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
            const auto centre = std::uint32_t(std::int64_t(cell) + dy * std::int64_t(shape.layer) + dz * std::int64_t(shape.row));
            const unsigned row = grains.around(centre);
            gx += kXSumOfRow[row];
            gy += dy * kGrainsInRow[row];
            gz += dz * kGrainsInRow[row];
            occupied += kGrainsInRow[row];
        }
    occupied -= int((grains.around(cell) >> 1) & 1u); // the cell itself is no neighbour
    return surfaceKey(gx, gy, gz, occupied);
}

void SurfaceUpkeep::refreshFlag(const Scene& scene, GridLevel level, std::uint32_t cell, std::uint32_t grain) {
    // Neighbouring changed cells share grains: look at each once per update.
    GrainSurface& record = grains_[grain];
    if (!firstLook(record, 1)) return;
    const std::uint8_t now = innerAt(scene, level, cell) ? 1 : 0;
    std::uint8_t& flag = record.inner;
    if (flag == now) return;
    innerCount_ += now ? 1 : -1;
    flag = now;
    list(grain, kInnerListed, changedInner_);
}

void SurfaceUpkeep::refreshGradient(const Scene& scene, GridLevel level, std::uint32_t cell, std::uint32_t grain) {
    GrainSurface& record = grains_[grain];
    if (!firstLook(record, 2)) return;
    const std::uint16_t now = gradientKeyAt(scene, level, cell);
    if (record.gradient == now) return;
    record.gradient = now;
    list(grain, kGradientListed, changedGradient_);
}

// isInnerGrain reads the 6 face neighbours, across the seam too (the lower grid's top row looks
// at the upper grid's layer 1, the upper grid's layer 0 at the lower grid's second row from the
// top): so a changed cell can change the flag of the grain in it and of the grains in its 6 world
// neighbours, in either grid.
void SurfaceUpkeep::refreshInnerAround(const Scene& scene, GridLevel level, std::uint32_t cell) {
    Bits& kept = *bits_; // one load of the pointer, not one per cell
    const Int3 c = kept.shapes[index(level)].coordinate(cell);
    const Int3 o = origins_[index(level)];
    const Int3 world{c.x + o.x, c.y + o.y, c.z + o.z};
    static constexpr Int3 kAround[7] = {{0, 0, 0}, {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    // First the grains, their records fetched together; then each looked at, in the same order.
    struct Found {
        GridLevel level;
        std::uint32_t cell, grain;
    };
    std::array<Found, 14> found;
    std::size_t count = 0;
    for (const Int3& d : kAround)
        for (GridLevel other : {GridLevel::Lower, GridLevel::Upper}) {
            const CellGrid& grid = scene.grid(other);
            const Int3 origin = origins_[index(other)];
            const int x = world.x + d.x - origin.x, y = world.y + d.y - origin.y, z = world.z + d.z - origin.z;
            if (!grid.contains(x, y, z)) continue;
            const std::uint32_t n = grid.index(x, y, z);
            if (!kept.grain[index(other)].test(n)) continue; // the bits hold the occupancy: no grid read for an empty cell
            const CellValue value = grid[n];
            if (value < 0) continue;
            prefetch(&grains_[std::uint32_t(value)]);
            found[count++] = {other, n, std::uint32_t(value)};
        }
    for (std::size_t i = 0; i < count; ++i) refreshFlag(scene, found[i].level, found[i].cell, found[i].grain);
}

// gradientNormal reads the 26 neighbours within the grain's own grid.
void SurfaceUpkeep::refreshGradientAround(const Scene& scene, GridLevel level, std::uint32_t cell) {
    const CellGrid& grid = scene.grid(level);
    const CellBits& grains = bits_->grain[index(level)];
    const Int3 c = bits_->shapes[index(level)].coordinate(cell);
    std::array<std::pair<std::uint32_t, std::uint32_t>, 27> found; // (cell, grain), records fetched together
    std::size_t count = 0;
    for (int y = c.y - 1; y <= c.y + 1; ++y)
        for (int z = c.z - 1; z <= c.z + 1; ++z)
            for (int x = c.x - 1; x <= c.x + 1; ++x) {
                if (!grid.contains(x, y, z)) continue;
                const std::uint32_t n = grid.index(x, y, z);
                if (!grains.test(n)) continue;
                const CellValue value = grid[n];
                if (value < 0) continue;
                prefetch(&grains_[std::uint32_t(value)]);
                found[count++] = {n, std::uint32_t(value)};
            }
    for (std::size_t i = 0; i < count; ++i) refreshGradient(scene, level, found[i].first, found[i].second);
}

void SurfaceUpkeep::update(const Scene& scene) {
    const GrainStore& grains = scene.grains();
    // A rebuild also restarts the stamps before the 32-bit update number could wrap (after
    // about 3.5e8 steps), when an old stamp could look current.
    if (!built_ || grainCount_ != grains.size() || updateNumber_ > (UINT32_MAX >> 2) - 8) {
        rebuild(scene);
        return;
    }
    changedCells_.clear();
    origins_ = {scene.gridOrigin(GridLevel::Lower), scene.gridOrigin(GridLevel::Upper)};
    // With the scene's threads (idle between steps), one grid each (see syncMovedGrains). Per-grain
    // flags (the CPU path) list grains in shared lists: one thread.
    WorkerPool* pool = trackFlags_ ? nullptr : scene.workers();
    shares_[0].levels = pool != nullptr ? 1u : 3u;
    shares_[1].levels = 2u;
    // First the net changes: after this the bits hold the grids' occupancy again.
    // The last update's places live in the scene's list, which this step has overwritten: unless
    // they were cleared or retained, they are lost (the consumer re-reads every place).
    if (!latestMoves_.empty()) placesComplete_ = false;
    syncMovedGrains(scene, pool);
    changedCellsListed_.insert(changedCellsListed_.end(), changedCells_.begin(), changedCells_.end());
    if (trackFlags_) {
        // A moved grain's flag and normal are about its new cell: look again at each. Grains that
        // stayed change only next to a net change, in its 6 world neighbours (flag) or its 26
        // neighbours in its grid (normal); both read only the bits, final by now.
        ++updateNumber_;
        for (const GrainMove& grain : latestMoves_) {
            refreshFlag(scene, grain.level, grain.cell, grain.grain);
            if (trackGradient_) refreshGradient(scene, grain.level, grain.cell, grain.grain);
        }
        for (const auto& [level, cell] : changedCells_) {
            refreshInnerAround(scene, level, cell);
            if (trackGradient_) refreshGradientAround(scene, level, cell);
        }
    }
    if (trackColumns_) updateHeights(scene, pool);
}

void SurfaceUpkeep::retainMoves() {
    for (const GrainMove& move : latestMoves_) retainedPlaces_.push_back(placeOf(move, latestStep_));
    latestMoves_ = {};
}

void SurfaceUpkeep::forgetPlaces() {
    retainedPlaces_.clear();
    latestMoves_ = {};
    placesComplete_ = true;
}

// isInnerGrain from the bits alone, at the grid's edge and across the seam too.
bool SurfaceUpkeep::hidesFromBits(GridLevel level, int x, int y, int z) const {
    const GridShape& shape = bits_->shapes[index(level)];
    if (x < 0 || y < 0 || z < 0 || x >= shape.size.x || y >= shape.size.y || z >= shape.size.z) return true;
    return bits_->hide[index(level)].test(std::uint32_t(x) + shape.row * std::uint32_t(z) + shape.layer * std::uint32_t(y));
}

bool SurfaceUpkeep::innerFromBits(GridLevel level, std::uint32_t cell, Int3 c) const {
    const GridShape& shape = bits_->shapes[index(level)];
    if (shape.interior(c)) {
        const CellBits& hides = bits_->hide[index(level)];
        return (hides.around(cell) & 5u) == 5u && hides.test(cell - shape.row) && hides.test(cell + shape.row) &&
               hides.test(cell - shape.layer) && hides.test(cell + shape.layer);
    }
    if (!(hidesFromBits(level, c.x - 1, c.y, c.z) && hidesFromBits(level, c.x + 1, c.y, c.z) &&
          hidesFromBits(level, c.x, c.y, c.z - 1) && hidesFromBits(level, c.x, c.y, c.z + 1)))
        return false;
    const int lowerTop = bits_->shapes[index(GridLevel::Lower)].size.y - 1;
    const bool above = level == GridLevel::Lower && c.y == lowerTop ? hidesFromBits(GridLevel::Upper, c.x, 1, c.z)
                                                                   : hidesFromBits(level, c.x, c.y + 1, c.z);
    const bool below = level == GridLevel::Upper && c.y == 0 ? hidesFromBits(GridLevel::Lower, c.x, lowerTop - 1, c.z)
                                                             : hidesFromBits(level, c.x, c.y - 1, c.z);
    return above && below;
}

// Heights: a filled cell can only raise its column; then each touched column scans down from
// its (upper bound of the) height to its top grain. Column normals: around changed heights.
// The grain bits, final by now, say which cells hold a grain: a bit is a far smaller read than
// the grid's cell. Each grid's columns are its own: on two threads, one grid each.
void SurfaceUpkeep::updateHeights(const Scene& scene, WorkerPool* pool) {
    const std::uint32_t heightsPass = ++updateNumber_, normalsPass = ++updateNumber_;
    forEachShare(pool, [&](GridShare& share) { updateHeightsOf(scene, share, heightsPass, normalsPass); });
    for (GridShare& share : shares_) {
        changedColumns_.insert(changedColumns_.end(), share.changedColumns.begin(), share.changedColumns.end());
        share.changedColumns.clear();
    }
}

void SurfaceUpkeep::updateHeightsOf(const Scene& scene, GridShare& share, std::uint32_t heightsPass,
                                    std::uint32_t normalsPass) {
    Bits& kept = *bits_; // one load of the pointer, not one per cell
    share.touchedColumns.clear();
    share.heightsBefore.clear();
    for (const auto& [level, cell] : changedCells_) {
        if (((share.levels >> index(level)) & 1u) == 0) continue;
        const CellGrid& grid = scene.grid(level);
        const std::uint32_t column = cell % grid.layerSize();
        const int y = int(cell / grid.layerSize());
        int& height = heights_[index(level)][column];
        std::uint32_t& stamp = columnStamp_[index(level)][column];
        if (stamp != heightsPass) {
            stamp = heightsPass;
            share.touchedColumns.push_back({level, column});
            share.heightsBefore.push_back(height);
        }
        if (kept.grain[index(level)].test(cell)) height = std::max(height, y + 1);
    }
    share.normalCandidates.clear();
    for (std::size_t i = 0; i < share.touchedColumns.size(); ++i) {
        const ColumnRef& touched = share.touchedColumns[i];
        const CellGrid& grid = scene.grid(touched.level);
        const Int3 s = grid.size();
        int& height = heights_[index(touched.level)][touched.column];
        const CellBits& holds = kept.grain[index(touched.level)];
        int y = height - 1;
        while (y >= 0 && !holds.test(touched.column + std::uint32_t(y) * grid.layerSize())) --y;
        height = y + 1;
        if (height == share.heightsBefore[i]) continue;
        // Its normal and its 8 neighbours' read this height.
        const int x = int(touched.column % std::uint32_t(s.x)), z = int(touched.column / std::uint32_t(s.x));
        LayerNeighbourhood(x, z, s.x, s.z).forEachWithCentre([&](int dx, int dz) {
            const auto column = std::uint32_t(std::int64_t(x + dx) + std::int64_t(s.x) * (z + dz));
            std::uint32_t& stamp = columnStamp_[index(touched.level)][column];
            if (stamp == normalsPass) return;
            stamp = normalsPass;
            share.normalCandidates.push_back({touched.level, column});
        });
    }
    // Recompute after every height is final; list only the columns whose normal really changed.
    for (const ColumnRef& ref : share.normalCandidates) {
        const Int3 s = scene.grid(ref.level).size();
        const std::vector<int>& heights = heights_[index(ref.level)];
        const int x = int(ref.column % std::uint32_t(s.x)), z = int(ref.column / std::uint32_t(s.x));
        const Vec3 now = columnNormal(heights, s, x, z);
        Vec3& normal = normals_[index(ref.level)][ref.column];
        if (now == normal) continue;
        normal = now;
        std::uint8_t& listed = columnListed_[index(ref.level)][ref.column];
        if (listed) continue;
        listed = 1;
        share.changedColumns.push_back(ref);
    }
}

void SurfaceUpkeep::shareOut(WorkerPool* pool, std::size_t count, const std::function<void(std::size_t, std::size_t)>& part) {
    const int pieces = pool != nullptr && count >= kPlacesPerPiece ? pool->threadCount() : 1;
    auto piece = [&](int p) { part(count * std::size_t(p) / std::size_t(pieces), count * std::size_t(p + 1) / std::size_t(pieces)); };
    if (pieces > 1) pool->parallelFor(pieces, piece);
    else piece(0);
}

} // namespace sandcore
