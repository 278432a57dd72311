// SPDX-License-Identifier: MIT
#include "granular_rules.hpp"

#include "empty_cells.hpp"
#include "sandcore/counter_random.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace sandcore {

namespace {

// Fastest fall per step, cells: far below what a MoveCode holds, far above any grid's height.
constexpr std::uint32_t kMaxFallSpeed = 4096u * kOneCell;

// Sets the random draws of deflections apart from those of slides (same step, grid and cell).
constexpr std::uint64_t kDeflectStream = 0x5bd1e995u;

} // namespace

// Measured: for each slope T and diagonal stiffening s (thresholds T (1 + s sin^2 2phi) |e| for a
// slide at angle phi from the grid's x axis), the mean angle of a cone poured at one column
// (granular_probe pour; means over 16 cones of 40,000 grains, 16 directions each). Grains find
// the lowest of the thresholds around them, so the cone stands well below atan(T); the lattice
// favours some directions, differently at each angle, and each point's s was chosen so the 4
// diagonal directions stand within 0.3 degrees of the 4 axis directions (0.43 at 20.9 degrees).
// Above about 41 degrees the lattice's own 45-degree facets can take over along the axes (a cone
// then stands at 45 along the axes and 2 degrees lower along the diagonals): there the points are
// those that kept the axes off them (diagonals within 0.3 degrees of the axes up to 42.9, then
// steeper by 0.4, 1.35, 1.1, 0.7, 0.4 and 0.6 at 43.3, 43.8, 44.1, 44.4, 44.9 and 45.0). Near
// T = 1 the needs of the slides along the axes are whole numbers, or nearly, and there cones took
// the facets (asked 43 with a table that interpolated T 1.0009, s 0.29 there: axes at 44.97,
// diagonals at 42.97): the two points measured at 43.80, T 0.998 and 1.01, are both entered at
// 43.80, so the table steps from one to the other (the search below never pairs them).
namespace {
struct CalibrationPoint {
    double degrees, slope, diagonalStiffening;
};
constexpr CalibrationPoint kCalibration[] = {
    {18.56, 0.5000, 0.080},  {18.98, 0.5577, -0.050}, {20.87, 0.5962, -0.030}, {22.17, 0.6202, -0.010},
    {24.98, 0.6500, 0.060},  {26.89, 0.7000, 0.080},  {27.36, 0.7404, 0.026},  {28.91, 0.8467, -0.080},
    {30.25, 0.8757, -0.070}, {30.89, 0.9000, -0.100}, {32.24, 0.9200, -0.100}, {33.13, 0.9350, -0.100},
    {34.09, 0.9450, -0.100}, {36.06, 0.9500, 0.000},  {37.57, 0.9700, 0.047},  {39.91, 0.9860, 0.140},
    {40.80, 0.9900, 0.200},  {41.90, 0.9950, 0.250},  {42.88, 0.9980, 0.300},  {43.32, 0.9980, 0.340},
    {43.80, 0.9980, 0.380},  {43.80, 1.0100, 0.320},  {44.08, 1.0500, 0.290},  {44.35, 1.0700, 0.270},
    {44.85, 1.0800, 0.280},  {44.99, 1.0850, 0.280},
};
} // namespace

ThresholdCalibration calibratedThresholds(double reposeDegrees) {
    const auto* next = std::find_if(std::begin(kCalibration), std::end(kCalibration),
                                    [&](const CalibrationPoint& p) { return p.degrees >= reposeDegrees; });
    if (next == std::begin(kCalibration)) next = std::begin(kCalibration) + 1;
    if (next == std::end(kCalibration)) next = std::end(kCalibration) - 1;
    const CalibrationPoint& a = next[-1];
    const CalibrationPoint& b = next[0];
    const double t = (reposeDegrees - a.degrees) / (b.degrees - a.degrees);
    return {a.slope + t * (b.slope - a.slope), a.diagonalStiffening + t * (b.diagonalStiffening - a.diagonalStiffening)};
}

namespace {

// Set bits of a word, without a library call on CPUs the build does not assume to have POPCNT.
int setBitCount(std::uint64_t v) {
    v -= (v >> 1) & 0x5555555555555555ull;
    v = (v & 0x3333333333333333ull) + ((v >> 2) & 0x3333333333333333ull);
    v = (v + (v >> 4)) & 0x0f0f0f0f0f0f0f0full;
    return int((v * 0x0101010101010101ull) >> 56);
}

// Enters path `path` (window bits) as bit `bit` of every row pattern of `table` it crosses.
void addPath(GranularRules::RowBlockTable& table, std::uint64_t path, int bit) {
    for (int r = 0; r < GranularRules::kWindow; ++r)
        for (unsigned taken = 0; taken < (1u << GranularRules::kWindow); ++taken)
            if ((path >> (r * GranularRules::kWindow)) & taken) table[std::size_t(r)][taken] |= std::uint64_t{1} << bit;
}

// The path of slide o at the grain's level, as window bits around the slide's target column.
std::uint64_t pathsTowardsCentreOf(const GranularRules::Offset& o) {
    constexpr int reach = kGranularReach, window = GranularRules::kWindow;
    std::uint64_t path = 0;
    for (int bit = 0; bit < window * window; ++bit)
        if (o.pathMask >> bit & 1) { // cell q of the path, q - o seen from the target column
            const int qx = bit % window - reach - o.dx, qz = bit / window - reach - o.dz;
            path |= std::uint64_t{1} << ((qz + reach) * window + qx + reach);
        }
    return path;
}

} // namespace

GranularRules::GranularRules(const PhysicsSettings& physics) {
    validatePhysics(physics);
    const ThresholdCalibration calibration = calibratedThresholds(physics.reposeDegrees);
    slope_ = calibration.slope;
    gravity_ = std::uint32_t(std::lround(double(physics.gravity) * kOneCell));
    int n = 0;
    for (int dz = -kGranularReach; dz <= kGranularReach; ++dz)
        for (int dx = -kGranularReach; dx <= kGranularReach; ++dx) {
            if (dx == 0 && dz == 0) continue;
            Offset& o = offsets_[std::size_t(n++)];
            o.dx = dx;
            o.dz = dz;
            const double sin2 = std::sin(2.0 * std::atan2(double(dz), double(dx)));
            const double threshold = slope_ * (1.0 + calibration.diagonalStiffening * sin2 * sin2) * std::hypot(dx, dz);
            o.thresholdQ8 = std::uint32_t(std::lround(threshold * 256.0));
            // The cells of the grain's layer under the straight line to the target column, the
            // target column included, each rounded half away from zero so the path is symmetric
            // under every mirror of the grid.
            const int samples = 4 * std::max(std::abs(dx), std::abs(dz));
            for (int i = 1; i <= samples; ++i) {
                const int cx = int(std::lround(double(dx) * i / samples)), cz = int(std::lround(double(dz) * i / samples));
                if (cx != 0 || cz != 0) o.pathMask |= std::uint64_t{1} << ((cz + kGranularReach) * kWindow + cx + kGranularReach);
            }
            maxDrop_ = std::max(maxDrop_, int((o.thresholdQ8 + 255) >> 8));
            if (std::max(std::abs(dx), std::abs(dz)) == 1) divesMask_ |= std::uint64_t{1} << (n - 1);
        }
    wholeAtLeast_.assign(std::size_t(maxDrop_) + 2, 0);
    wholeExactly_.assign(std::size_t(maxDrop_) + 2, 0);
    for (int k = 0; k < kOffsets; ++k) {
        const std::uint32_t threshold = offsets_[std::size_t(k)].thresholdQ8;
        for (std::uint32_t d = 0; d <= threshold >> 8; ++d) wholeAtLeast_[d] |= std::uint64_t{1} << k;
        wholeExactly_[threshold >> 8] |= std::uint64_t{1} << k;
        restComplement_[std::size_t(k)] = std::uint8_t(255 - (threshold & 255));
    }
    for (int k = 0; k < kOffsets; ++k) addPath(blockedBy_, offsets_[std::size_t(k)].pathMask, k);
    // The slides across a cell c, by the column t around c's they end in: the grain at b (from c)
    // slides by t - b, and its path, moved to b, crosses c. Every slide whose path crosses c is one
    // of them: the paths run straight from the grain to its target column, c lies on the way.
    int slidesAcross = 0;
    for (int t = 0; t < kAcrossWindow * kAcrossWindow; ++t) {
        const int tx = t % kAcrossWindow - kAcrossReach, tz = t / kAcrossWindow - kAcrossReach;
        for (int bit = 0; bit < kWindow * kWindow; ++bit) {
            const int bx = bit % kWindow - kGranularReach, bz = bit / kWindow - kGranularReach;
            const int dx = tx - bx, dz = tz - bz;
            if ((bx == 0 && bz == 0) || (dx == 0 && dz == 0) || std::max(std::abs(dx), std::abs(dz)) > kGranularReach) continue;
            const Offset& o = offsets_[std::size_t(offsetIndex(dx, dz))];
            if (!(o.pathMask >> ((kGranularReach - bz) * kWindow + kGranularReach - bx) & 1)) continue; // misses c
            ++slidesAcross;
            std::uint64_t path = 0; // as window bits around c
            for (int cell = 0; cell < kWindow * kWindow; ++cell) {
                if (!(o.pathMask >> cell & 1)) continue;
                const int px = cell % kWindow - kGranularReach + bx, pz = cell / kWindow - kGranularReach + bz;
                if (std::max(std::abs(px), std::abs(pz)) > kGranularReach)
                    throw std::logic_error("granular rules: a path across a cell leaves the 7x7 columns around it");
                path |= std::uint64_t{1} << ((pz + kGranularReach) * kWindow + px + kGranularReach);
            }
            const int slot = setBitCount(slidesAcrossCentreTo_[std::size_t(t)]);
            slidesAcrossCentreTo_[std::size_t(t)] |= std::uint64_t{1} << bit;
            if (t == kAcrossCentre) { // read as the paths towards the centre
                if (path != pathsTowardsCentreOf(o))
                    throw std::logic_error("granular rules: a slide into a column does not end at its cell");
                continue;
            }
            if (slot >= kMaxSlidesAcrossInto)
                throw std::logic_error("granular rules: more slides across a cell into one column than the wakes hold");
            pathsAcrossCentreInto_[std::size_t(t)][std::size_t(slot)] = path;
            slotAcrossCentreInto_[std::size_t(t)][std::size_t(bit)] = std::uint8_t(slot);
        }
    }
    for (int t = 0; t < kAcrossWindow * kAcrossWindow; ++t)
        for (std::uint64_t grains = slidesAcrossCentreTo_[std::size_t(t)]; grains; grains &= grains - 1) {
            const int bit = std::countr_zero(grains);
            auto& row = targetsAcrossCentreByRow_[std::size_t(bit / kWindow)];
            for (std::size_t pattern = 0; pattern < row.size(); ++pattern)
                if (pattern >> (bit % kWindow) & 1) row[pattern] |= 1u << t;
        }
    // Each cell of each path is a slide across that cell: all of them must lie in the tables.
    int slidesCrossing = 0;
    for (const Offset& o : offsets_) slidesCrossing += setBitCount(o.pathMask);
    if (slidesCrossing != slidesAcross)
        throw std::logic_error("granular rules: a slide across a cell ends beyond the columns the wakes look at");
    // The paths towards a column as a table of whole windows (grainsWithOpenPathTowardsCentre):
    // the grain at -o slides into the column by o.
    constexpr std::uint64_t kOuterRows = ((std::uint64_t{1} << kWindow) - 1) | ((std::uint64_t{1} << kWindow) - 1) << (kWindow * (kWindow - 1));
    for (const Offset& o : offsets_) {
        const std::uint64_t path = pathsTowardsCentreOf(o);
        if (path & kOuterRows) throw std::logic_error("granular rules: a path towards a column crosses the window's outer rows");
        addPath(towardsBlockedBy_, path, (kGranularReach - o.dz) * kWindow + kGranularReach - o.dx);
    }
    // The grains around a column by the whole cells of their slide into it (towardsCentreWithWhole):
    // the grain at -o slides into the column by o.
    towardsCentreByWhole_.assign(std::size_t(maxDrop_) + 1, 0);
    for (const Offset& o : offsets_)
        towardsCentreByWhole_[o.thresholdQ8 >> 8] |= std::uint64_t{1} << ((kGranularReach - o.dz) * kWindow + kGranularReach - o.dx);
    towardsCentreAtLeast_ = towardsCentreByWhole_;
    for (int whole = maxDrop_ - 1; whole >= 0; --whole)
        towardsCentreAtLeast_[std::size_t(whole)] |= towardsCentreAtLeast_[std::size_t(whole) + 1];
    // Who may gain from an EMPTY cell c, by layer above c (see wakeMask): in c's layer and the one
    // above, every grain of the window; d layers above c, only a grain whose deepest possible
    // need towards c's column reaches d cells, since c lies d cells down that column.
    wakeMasks_.assign(std::size_t(maxDrop_) + 1, 0);
    wakeMasks_[0] = wakeMasks_[1] = (std::uint64_t{1} << (kWindow * kWindow)) - 1;
    for (const Offset& o : offsets_)
        for (int d = 2; d <= maxDrop_; ++d)
            if (int((o.thresholdQ8 + 255) >> 8) >= d) // a grain at -o looks at c's column with offset o
                wakeMasks_[std::size_t(d)] |= std::uint64_t{1} << ((kGranularReach - o.dz) * kWindow + kGranularReach - o.dx);
}

namespace {

// Bit k: offset k's dither (byte k of dithers) carries past the rest of its threshold, dither >
// restComplement[k].
std::uint64_t carriesOf(const std::uint64_t (&dithers)[GranularRules::kOffsets / 8],
                        const std::array<std::uint8_t, GranularRules::kOffsets>& restComplement) {
    static_assert(GranularRules::kOffsets == 48);
#if defined(__SSE2__)
    // The dithers go into the vector registers straight from the general ones: stored and loaded
    // again 16 bytes at a time, each load would wait for two 8-byte stores it cannot be forwarded
    // from.
    std::uint64_t notCarried = 0;
    for (int part = 0; part < 3; ++part) {
        const __m128i dither = _mm_set_epi64x(std::int64_t(dithers[2 * part + 1]), std::int64_t(dithers[2 * part]));
        const __m128i rest = _mm_loadu_si128(reinterpret_cast<const __m128i*>(restComplement.data() + 16 * part));
        // dither - rest saturates at 0 exactly when dither <= rest: no carry
        const __m128i none = _mm_cmpeq_epi8(_mm_subs_epu8(dither, rest), _mm_setzero_si128());
        notCarried |= std::uint64_t(unsigned(_mm_movemask_epi8(none))) << (16 * part);
    }
    return ~notCarried & ((std::uint64_t{1} << GranularRules::kOffsets) - 1);
#else
    std::uint64_t carried = 0;
    for (int k = 0; k < GranularRules::kOffsets; ++k)
        carried |= std::uint64_t((dithers[k >> 3] >> ((k & 7) * 8) & 0xffu) > restComplement[std::size_t(k)]) << k;
    return carried;
#endif
}

// Moves `grain` from cell `from` to cell `to` of the same grid; the outcome carries the offset back
// (in cells) for the record, which the sweep writes or feeds.
GranularOutcome moveGrain(CellGrid& grid, CellValue grain, std::uint32_t from, std::uint32_t to, Int3 back, Int3 toCell) {
    grid[to] = grain;
    grid[from] = kEmpty;
    GranularOutcome outcome{GranularOutcome::Moved, toCell};
    outcome.cameFrom = packMove(back.x, back.y, back.z);
    return outcome;
}

} // namespace

GranularOutcome GranularRules::fall(const GranularContext& on, const GrainCell& at, CellValue grain, bool mayBeMoving) const {
    CellGrid& grid = on.grid;
    const std::span<FallState> falls = on.falls;
    const std::uint32_t from = at.index;
    const auto id = std::size_t(grain);
    const FallState before = mayBeMoving ? falls[id] : FallState{};
    // x(n) = g n^2 / 2 exactly at whole steps: each step advances by the mean speed v + g/2.
    const std::uint64_t travel = std::uint64_t(before.fraction) + before.speed + gravity_ / 2;
    const std::uint32_t speed = std::min(before.speed + gravity_, kMaxFallSpeed);
    const int wanted = int(std::min<std::uint64_t>(travel >> 16, std::uint64_t(at.y)));
    if (wanted == 0) {
        falls[id] = {speed, std::uint16_t(travel)};
        GranularOutcome outcome{GranularOutcome::Waiting, {}};
        outcome.inMotion = (speed | std::uint16_t(travel)) != 0;
        return outcome;
    }
    // Check every cell of the path: the first non-EMPTY one stops the grain above it.
    const std::uint32_t layer = grid.layerSize();
    int fallen = 1; // the cell below is EMPTY
    while (fallen < wanted && grid[from - std::uint32_t(fallen + 1) * layer] == kEmpty) ++fallen;
    const int landedY = at.y - fallen;
    FallState after;
    if (landedY == 0) { // the grid's bottom layer: an outlet keeps the speed, a floor stops it
        after = {on.bottomIsOutlet ? speed : 0, 0};
    } else if (fallen == int(travel >> 16)) { // free flight: nothing touched
        after = {speed, std::uint16_t(travel)};
    } else { // contact: the speed of a grain it lands on (0 when resting), or 0 on a wall
        // A grain it lands on may be a gatherer that sleeps (grid_sweep.hpp): read up to date.
        const CellValue under = grid[from - std::uint32_t(fallen + 1) * layer];
        const std::uint32_t underSpeed = under >= 0 ? caughtUp(falls[std::size_t(under)], on.step).speed : 0;
        // Catching up with a slower grain, it glances off it instead, when it can: the stream
        // spreads rather than piling into a slow, dense column (deflected).
        if (under >= 0 && underSpeed > 0 && underSpeed < speed && landedY >= 1)
            if (const int to = deflected(on, {at.x, landedY, at.z, from - std::uint32_t(fallen) * layer}); to >= 0) {
                falls[id] = {speed, 0};
                const Int3 cell = grid.coordinate(std::uint32_t(to));
                GranularOutcome outcome = moveGrain(grid, grain, from, std::uint32_t(to), {at.x - cell.x, at.y - cell.y, at.z - cell.z}, cell);
                outcome.inMotion = true;
                return outcome;
            }
        after = {under >= 0 ? std::min(speed, underSpeed) : 0, 0};
    }
    falls[id] = after;
    GranularOutcome outcome = moveGrain(grid, grain, from, from - std::uint32_t(fallen) * layer, {0, fallen, 0}, {at.x, landedY, at.z});
    outcome.inMotion = (after.speed | after.fraction) != 0;
    return outcome;
}

// The cells beside the grain a falling grain has caught up with, one layer under the cell where it
// would stop (`landing`, its layer >= 1): an EMPTY one, passing beside that grain (the cell beside
// the landing cell not the vessel), drawn by a counter hash; -1 when there is none. Read as the
// cells are: they lie in the layers below the falling grain's, rows z - 1..z + 1 (R6).
int GranularRules::deflected(const GranularContext& on, const GrainCell& landing) const {
    const CellGrid& grid = on.grid;
    const Int3 size = grid.size();
    const std::uint32_t layer = grid.layerSize();
    std::array<std::uint32_t, 8> free{};
    std::uint32_t count = 0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dx = -1; dx <= 1; ++dx) {
            const int bx = landing.x + dx, bz = landing.z + dz;
            if ((dx == 0 && dz == 0) || bx < 0 || bx >= size.x || bz < 0 || bz >= size.z) continue;
            const std::uint32_t beside = grid.index(bx, landing.y, bz);
            if (grid[beside] != kInvalid && grid[beside - layer] == kEmpty) free[count++] = beside - layer;
        }
    if (count == 0) return -1;
    return int(free[pickBelow(counterRandomFromKey(on.stepKey, on.stream ^ kDeflectStream, landing.index), count)]);
}

std::uint64_t GranularRules::carriedSlides(const ThresholdDither& dither, int x, int z) const {
    std::uint64_t dithers[kOffsets / 8];
    for (int group = 0; group < kOffsets / 8; ++group) dithers[group] = dither.group(x, z, group);
    return carriesOf(dithers, restComplement_);
}

GranularOutcome GranularRules::slide(const GranularContext& on, const GrainCell& at, CellValue grain, bool onVessel) const {
    CellGrid& grid = on.grid;
    const int x = at.x, y = at.y, z = at.z;
    const std::uint32_t from = at.index;
    const std::int64_t row = grid.size().x, layer = grid.layerSize();
    // The 7x7 windows of EMPTY cells in the grain's layer (paths) and the layers below (targets,
    // columns) as bit masks, bit (dz + 3) * 7 + (dx + 3); cells outside the grid count as taken.
    auto emptyWindow = [&](int dy) { return on.empty.window<kGranularReach>(x, y + dy, z); };
    // Every slide ends over an EMPTY cell of the layer below: when none is there, nothing can move.
    const std::uint64_t emptyBelow = emptyWindow(-1);
    // Window bits to slide bits (bit k for offset k: the window's centre has none, bits above it shift down).
    constexpr std::uint64_t kBelowCentre = (std::uint64_t{1} << (kOffsets / 2)) - 1;
    const std::uint64_t targets = (emptyBelow & kBelowCentre) | ((emptyBelow >> 1) & ~kBelowCentre);
    if (!targets) return {};
    // The slides open at the grain's level: no taken cell on the path (7 look-ups), except that a
    // slide into one of the 8 columns next to the grain (a *dive*) passes under a grain in its
    // path cell: that grain lies over the EMPTY target, so it carries nothing and is falling or
    // about to; only the vessel blocks a dive. So a grain beside a falling column or a void takes
    // its place, and sand flows sideways into a draining column, not only from its top.
    const std::uint64_t emptyHere = emptyWindow(0);
    std::uint64_t blocked = blockedIn(blockedBy_, emptyHere);
    for (std::uint64_t dives = blocked & targets & divesMask_; dives; dives &= dives - 1) {
        const Offset& o = offsets_[std::size_t(std::countr_zero(dives))];
        if (grid[std::uint32_t(std::int64_t(from) + o.dz * row + o.dx)] != kInvalid) blocked &= ~(dives & (~dives + 1));
    }
    std::uint64_t open = targets & ~blocked;
    // On the glass (smoother than the sand) one free cell down is enough; on sand the column under
    // the path's end must be `need` deep, need = max(1, floor((T|e| + dither) / 256)) with a fixed
    // dither per column and offset (8 bits each, 8 offsets to a word). The slides that need d cells
    // are a mask; layer by layer down, those whose column ends above it drop out.
    if (!onVessel && (open & (wholeAtLeast_[2] | wholeExactly_[1]))) {
        const std::uint64_t carry = carriedSlides(on.dither, x, z);
        std::uint64_t deep = ~std::uint64_t{0}; // columns EMPTY from layer y - 2 down to layer y - d
        for (int d = 2; d <= maxDrop_; ++d) {
            const std::uint64_t needing = (wholeAtLeast_[std::size_t(d)] | (wholeExactly_[std::size_t(d - 1)] & carry)) & open;
            if (!needing) break; // who needs d + 1 needs d too
            if (d > y) {         // the column is not that deep inside this grid
                open &= ~needing;
                break;
            }
            const std::uint64_t emptyThere = emptyWindow(-d);
            deep &= (emptyThere & kBelowCentre) | ((emptyThere >> 1) & ~kBelowCentre);
            open &= ~(needing & ~deep);
        }
    }
    if (!open) return {};
    // The n-th possible slide in ascending offset order, n drawn by a counter hash (R3).
    const auto count = std::uint32_t(setBitCount(open));
    for (std::uint32_t n = pickBelow(counterRandomFromKey(on.stepKey, on.stream, from), count); n > 0; --n) open &= open - 1;
    const Offset& o = offsets_[std::size_t(std::countr_zero(open))];
    const std::uint32_t to = std::uint32_t(std::int64_t(from) - layer + o.dz * row + o.dx);
    return moveGrain(grid, grain, from, to, {-o.dx, 1, -o.dz}, {x + o.dx, y - 1, z + o.dz});
}

} // namespace sandcore
