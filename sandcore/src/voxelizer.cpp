// SPDX-License-Identifier: MIT
#include "sandcore/voxelizer.hpp"

#include "mesh_preparation.hpp"

#include "sandcore/cell_grid.hpp"
#include "worker_pool.hpp"

#include <algorithm>
#include <functional>
#include <span>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace sandcore {

namespace {

// Grid coordinates become integers in units of 1/kQuantum cell. With |coordinate| <= 2^14 cells
// every value stays below 2^29, a difference below 2^30, and a 2x2 determinant below 2^61: the
// orientation predicates are exact in int64.
constexpr std::int64_t kQuantum = std::int64_t{1} << 15;
constexpr double kMaxGridCoordinate = 2.0 * kMaxVoxelResolution;

const char* const kAxisNames[3] = {"x", "y", "z"};

// Stored in 32 bits (half the memory the rays read), widened to 64 for the predicates.
using Point = std::array<std::int32_t, 3>;

std::int64_t floorDiv(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// Sign of orient(a, b, p) in the row plane (v, w), for p moved by (eps, eps^2) (simulation of
// simplicity). Only an edge of zero length gives 0. Two triangles sharing an edge see it with
// opposite orientation, so a perturbed point on a shared edge lies in exactly one of them.
int perturbedSide(std::int64_t av, std::int64_t aw, std::int64_t bv, std::int64_t bw, std::int64_t pv,
                  std::int64_t pw, std::int64_t& det) {
    det = (bv - av) * (pw - aw) - (bw - aw) * (pv - av);
    if (det != 0) return det > 0 ? 1 : -1;
    // The perturbation adds (bv - av) * eps^2 - (bw - aw) * eps.
    if (bw != aw) return bw < aw ? 1 : -1;
    if (bv != av) return bv > av ? 1 : -1;
    return 0;
}

struct RayFrame {
    int u, v, w; // the ray runs along u; rows are indexed by (v, w)
};

// Where the ray through row point (pv, pw) along +u crosses triangle (a, b, c), in cells along u;
// false when it misses. A triangle whose projection has zero area is never hit. `entering` is
// +1 when the triangle faces against the ray (the ray enters a solid wound counter-clockwise
// seen from outside), -1 when it faces along it: the step of the winding number.
bool crossRay(const Point& a, const Point& b, const Point& c, RayFrame f, std::int64_t pv, std::int64_t pw,
              double& crossing, int& entering) {
    std::int64_t weightC = 0, weightA = 0, weightB = 0;
    const int s0 = perturbedSide(a[f.v], a[f.w], b[f.v], b[f.w], pv, pw, weightC);
    if (s0 == 0) return false;
    if (perturbedSide(b[f.v], b[f.w], c[f.v], c[f.w], pv, pw, weightA) != s0) return false;
    if (perturbedSide(c[f.v], c[f.w], a[f.v], a[f.w], pv, pw, weightB) != s0) return false;
    const double total = double(weightA) + double(weightB) + double(weightC);
    // Relative to a, so a face of constant u gives that u exactly.
    const double offset = (double(weightB) * double(std::int64_t(b[f.u]) - a[f.u]) + double(weightC) * double(std::int64_t(c[f.u]) - a[f.u])) / total;
    crossing = (double(a[f.u]) + offset) / double(kQuantum);
    entering = -s0; // s0 is the sign of the normal's u component (frames are right-handed)
    return true;
}

// Row entries ahead of the one being tested whose corners are asked for early (their triangle
// twice as far ahead).
constexpr std::uint64_t kEntriesAhead = 8;

// Triangle ids per row, in compressed rows: row r owns ids[first[r] .. first[r + 1]).
struct RowBins {
    std::vector<std::uint64_t> first;
    std::vector<std::uint32_t> ids;
};

// Most row entries binning may make (4 bytes each): a finely fanned sheet at a high resolution
// could otherwise ask for more memory than the grid itself.
constexpr std::uint64_t kMaxBinEntries = std::uint64_t{1} << 30;

// Row index range [lo, hi] whose centres (2j + 1) * kQuantum / 2 lie within [minValue, maxValue].
void rowRange(std::int64_t minValue, std::int64_t maxValue, int rows, int& lo, int& hi) {
    const std::int64_t half = kQuantum / 2;
    const std::int64_t first = -floorDiv(-(minValue - half), kQuantum); // ceil
    const std::int64_t last = floorDiv(maxValue - half, kQuantum);
    lo = int(std::max<std::int64_t>(first, 0));
    hi = int(std::min<std::int64_t>(last, rows - 1));
}

// A stable counting sort of the triangles into the rows they span, in parallel over chunks of
// triangles (each row lists its triangles in index order, whatever the number of chunks).
RowBins binTriangles(std::span<const Point> points, std::span<const MeshTriangle> triangles,
                     RayFrame f, Int3 rows, WorkerPool& pool) {
    const int rowsV = rows.x, rowsW = rows.y;
    const std::size_t rowCount = std::size_t(rowsV) * std::size_t(rowsW);
    auto forEachRow = [&](const std::array<std::uint32_t, 3>& t, auto&& visit) {
        const Point &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
        int vLo, vHi, wLo, wHi;
        rowRange(std::min({a[f.v], b[f.v], c[f.v]}), std::max({a[f.v], b[f.v], c[f.v]}), rowsV, vLo, vHi);
        rowRange(std::min({a[f.w], b[f.w], c[f.w]}), std::max({a[f.w], b[f.w], c[f.w]}), rowsW, wLo, wHi);
        for (int k = wLo; k <= wHi; ++k)
            for (int j = vLo; j <= vHi; ++j) visit(std::size_t(j) + std::size_t(rowsV) * std::size_t(k));
    };
    // A count per row and chunk: at most four chunks, one where the rows alone take 128 MiB.
    const std::size_t chunks = rowCount > (std::size_t{1} << 24) ? 1 : std::size_t(std::min(pool.threadCount(), 4));
    const auto chunkBegin = [&](std::size_t c) { return triangles.size() * c / chunks; };
    // place[c * rowCount + row]: entries of chunk c in the row, then where its next one goes.
    std::vector<std::uint64_t> place(chunks * rowCount, 0);
    // Most triangles of a fine mesh lie between rows: the second pass visits only the others.
    std::vector<std::vector<std::uint32_t>> spanning(chunks);
    pool.parallelFor(int(chunks), [&](int c) {
        std::uint64_t* counts = place.data() + std::size_t(c) * rowCount;
        for (std::size_t i = chunkBegin(std::size_t(c)); i < chunkBegin(std::size_t(c) + 1); ++i) {
            bool any = false;
            forEachRow(triangles[i], [&](std::size_t row) { ++counts[row], any = true; });
            if (any) spanning[std::size_t(c)].push_back(std::uint32_t(i));
        }
    });
    RowBins bins;
    bins.first.assign(rowCount + 1, 0);
    std::uint64_t running = 0;
    for (std::size_t row = 0; row < rowCount; ++row) {
        bins.first[row] = running;
        for (std::size_t c = 0; c < chunks; ++c) running += std::exchange(place[c * rowCount + row], running);
    }
    bins.first[rowCount] = running;
    if (running > kMaxBinEntries)
        throw std::invalid_argument("the mesh's triangles span too many rows at this resolution (" +
                                    std::to_string(running) + " row entries); use a lower resolution");
    bins.ids.resize(std::size_t(running));
    pool.parallelFor(int(chunks), [&](int c) {
        std::uint64_t* next = place.data() + std::size_t(c) * rowCount;
        for (const std::uint32_t i : spanning[std::size_t(c)])
            forEachRow(triangles[i], [&](std::size_t row) { bins.ids[next[row]++] = i; });
    });
    return bins;
}

// Grid coordinates of every vertex as fixed-point integers.
std::vector<Point> quantize(const std::vector<std::array<double, 3>>& grid) {
    std::vector<Point> points(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i)
        for (std::size_t a = 0; a < 3; ++a) {
            const double g = grid[i][a];
            if (!std::isfinite(g) || std::abs(g) > kMaxGridCoordinate)
                throw std::invalid_argument("vertex coordinate outside the voxel grid's range");
            points[i][a] = std::int32_t(std::llround(g * double(kQuantum)));
        }
    return points;
}

// One pass of rays along axis f.u. Plain mode writes inside cells between pairs of crossings
// into `mask`; robust mode adds, per cell, one vote for a non-zero winding number counted from
// each end of the row (the mesh is oriented outward first, so overlapping closed parts are a
// union and a closed mesh gives the same count from both ends).
// `alongside`, when given, runs as one more task of the rows' loop, on whichever thread takes it.
void castRays(std::span<const Point> points, std::span<const MeshTriangle> triangles, RayFrame f, Int3 size,
              const VoxelizeSettings& settings, WorkerPool& pool, std::span<std::uint8_t> out, bool votes,
              const std::function<void()>* alongside = nullptr) {
    const int sizes[3] = {size.x, size.y, size.z};
    const int rowsV = sizes[f.v], rowsW = sizes[f.w], length = sizes[f.u];
    const std::size_t stride[3] = {1, std::size_t(size.x) * std::size_t(size.z), std::size_t(size.x)};
    RowBins bins;
    if (settings.binning) bins = binTriangles(points, triangles, f, {rowsV, rowsW, 0}, pool);

    const int first = alongside ? 1 : 0;
    pool.parallelFor(rowsW + first, [&](int task) {
        if (task < first) return (*alongside)();
        const int k = task - first;
        std::vector<std::pair<double, int>> crossings; // position along u, winding step
        // The rows of a task list their triangles one after the other, at scattered ids whose
        // corners lie scattered too: ask for the triangle a few entries ahead, and for the
        // corners of a nearer one (its triangle asked for earlier).
        const std::uint64_t taskEnd = settings.binning ? bins.first[std::size_t(rowsV) * std::size_t(k + 1)] : 0;
        const auto prefetchEntry = [&](std::uint64_t n) {
            if (n + 2 * kEntriesAhead < taskEnd) __builtin_prefetch(&triangles[bins.ids[n + 2 * kEntriesAhead]]);
            if (n + kEntriesAhead < taskEnd)
                for (const std::uint32_t i : triangles[bins.ids[n + kEntriesAhead]]) __builtin_prefetch(&points[i]);
        };
        for (int j = 0; j < rowsV; ++j) {
            const std::int64_t pv = (2 * std::int64_t(j) + 1) * (kQuantum / 2);
            const std::int64_t pw = (2 * std::int64_t(k) + 1) * (kQuantum / 2);
            crossings.clear();
            auto test = [&](std::uint32_t id) {
                const auto& t = triangles[id];
                double at;
                int entering;
                if (crossRay(points[t[0]], points[t[1]], points[t[2]], f, pv, pw, at, entering))
                    crossings.push_back({at, entering});
            };
            if (settings.binning) {
                const std::size_t row = std::size_t(j) + std::size_t(rowsV) * std::size_t(k);
                for (std::uint64_t n = bins.first[row]; n < bins.first[row + 1]; ++n) {
                    prefetchEntry(n);
                    test(bins.ids[n]);
                }
            } else {
                for (std::uint32_t id = 0; id < triangles.size(); ++id) test(id);
            }
            if (crossings.empty()) continue;
            std::sort(crossings.begin(), crossings.end());
            const std::size_t base = std::size_t(j) * stride[f.v] + std::size_t(k) * stride[f.w];
            // Cell i counts a crossing at x when its centre i + 0.5 >= x: the first such i is ceil(x - 0.5).
            auto firstCellFrom = [&](double x) {
                return int(std::clamp(std::ceil(x - 0.5), 0.0, double(length)));
            };
            if (!votes) {
                // An unpaired last crossing (open mesh) does not open a run to the grid's end.
                for (std::size_t n = 0; n + 1 < crossings.size(); n += 2) {
                    const int from = firstCellFrom(crossings[n].first), to = firstCellFrom(crossings[n + 1].first);
                    if (stride[f.u] == 1)
                        std::fill(out.begin() + std::ptrdiff_t(base + std::size_t(from)), out.begin() + std::ptrdiff_t(base + std::size_t(to)), std::uint8_t{1});
                    else
                        for (int i = from; i < to; ++i) out[base + std::size_t(i) * stride[f.u]] = 1;
                }
                continue;
            }
            const std::size_t total = crossings.size();
            int windingTotal = 0;
            for (const auto& crossing : crossings) windingTotal += crossing.second;
            std::size_t passed = 0;
            int windingFromLow = 0; // counted from the row's low end; from the high end it is windingTotal - this
            for (int i = 0; i < length; ++i) {
                while (passed < total && crossings[passed].first <= i + 0.5) windingFromLow += crossings[passed++].second;
                const int vote = int(windingFromLow != 0) + int(windingTotal - windingFromLow != 0);
                out[base + std::size_t(i) * stride[f.u]] += std::uint8_t(vote);
            }
        }
    });
}

// An all-outside mask, each thread clearing one contiguous share: the mask is the largest fresh
// array of a first voxelization, and the kernel clears a fresh page for whichever thread touches
// it first, so one thread clearing all of it would leave the others waiting.
InsideMask emptyMaskInParallel(Int3 size, WorkerPool& pool) {
    validateGridSize(size);
    InsideMask mask;
    mask.size = size;
    const std::size_t cells = std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z);
    mask.inside.resize(cells); // unset until the shares below clear it
    const int shares = pool.threadCount();
    pool.parallelFor(shares, [&](int s) {
        std::fill(mask.inside.begin() + std::ptrdiff_t(cells * std::size_t(s) / std::size_t(shares)),
                  mask.inside.begin() + std::ptrdiff_t(cells * std::size_t(s + 1) / std::size_t(shares)), std::uint8_t{0});
    });
    return mask;
}

// The inside test on quantized grid points: plain parity along x, or S5's vote over three axes.
// In plain mode `alongside` (if given) runs during the casting, in robust mode before it.
InsideMask insideFromPoints(std::span<const Point> points, std::span<const MeshTriangle> triangles, Int3 size,
                            const VoxelizeSettings& settings, WorkerPool& pool,
                            const std::function<void()>* alongside = nullptr) {
    InsideMask mask = emptyMaskInParallel(size, pool);
    if (!settings.robust) {
        castRays(points, triangles, {0, 1, 2}, size, settings, pool, mask.inside, false, alongside);
        return mask;
    }
    if (alongside) (*alongside)();
    // S5: each axis gives two votes (parity counted from either end); they agree on a closed mesh.
    MaskCells votes(mask.inside.size(), 0);
    castRays(points, triangles, {0, 1, 2}, size, settings, pool, votes, true);
    castRays(points, triangles, {1, 2, 0}, size, settings, pool, votes, true);
    castRays(points, triangles, {2, 0, 1}, size, settings, pool, votes, true);
    for (std::size_t n = 0; n < votes.size(); ++n) mask.inside[n] = votes[n] >= 4 ? 1 : 0;
    return mask;
}

InsideMask insideFromGridPoints(const std::vector<std::array<double, 3>>& grid,
                                const std::vector<std::array<std::uint32_t, 3>>& triangles, Int3 size,
                                const VoxelizeSettings& settings) {
    if (settings.threads < 1) throw std::invalid_argument("voxelize needs at least one thread");
    validateGridSize(size); // a bad size is refused before the vertices are looked at
    for (const auto& t : triangles)
        for (std::uint32_t i : t)
            if (i >= grid.size()) throw std::invalid_argument("a triangle refers to a missing vertex");
    const std::vector<Point> points = quantize(grid);
    WorkerPool pool(settings.threads);
    return insideFromPoints(points, triangles, size, settings, pool);
}

// Inside cells, counted by slabs of layers in parallel.
std::int64_t countInside(const InsideMask& mask, WorkerPool& pool) {
    constexpr int kSlabs = 64;
    const std::size_t cells = mask.inside.size();
    std::vector<std::int64_t> perSlab(kSlabs, 0);
    pool.parallelFor(kSlabs, [&](int s) {
        const auto first = mask.inside.begin() + std::ptrdiff_t(cells * std::size_t(s) / kSlabs);
        const auto last = mask.inside.begin() + std::ptrdiff_t(cells * std::size_t(s + 1) / kSlabs);
        perSlab[std::size_t(s)] = std::count(first, last, std::uint8_t{1});
    });
    std::int64_t total = 0;
    for (const std::int64_t n : perSlab) total += n;
    return total;
}

// The prepared mesh's vertices in grid coordinates, quantized (as quantize of the double grid
// coordinates), in parallel.
LargePageVector<Point> quantizedGridPoints(std::span<const Vec3> vertices, const VoxelPlacement& p, WorkerPool& pool) {
    constexpr int kChunks = 64;
    LargePageVector<Point> points(vertices.size());
    pool.parallelFor(kChunks, [&](int c) {
        for (std::size_t i = vertices.size() * std::size_t(c) / kChunks; i < vertices.size() * std::size_t(c + 1) / kChunks; ++i) {
            const Vec3 v = vertices[i];
            const double model[3] = {v.x, v.y, v.z};
            for (std::size_t a = 0; a < 3; ++a) {
                const double g = (model[a] - p.modelMin[a]) * p.scale[a] + p.padding[a];
                if (!std::isfinite(g) || std::abs(g) > kMaxGridCoordinate)
                    throw std::invalid_argument("vertex coordinate outside the voxel grid's range");
                points[i][a] = std::int32_t(std::llround(g * double(kQuantum)));
            }
        }
    });
    return points;
}

// What the rays see: a face written twice counts once, and faces are oriented outward for the
// winding number of robust mode (parity ignores orientation).
TriangleMesh preparedForRays(const TriangleMesh& mesh) {
    WorkerPool pool(1);
    return turnedOutward(weldAndWalk(mesh, pool), pool);
}

} // namespace

double VoxelizeResult::relativeError() const {
    return meshVolume > 0.0 && volumeMeaningful ? (double(cellsInside) - meshVolume) / meshVolume : 0.0;
}

namespace {

void checkResolution(const VoxelizeSettings& settings) {
    if (settings.resolution < 1 || settings.resolution > kMaxVoxelResolution)
        throw std::invalid_argument("resolution must lie in 1.." + std::to_string(kMaxVoxelResolution) + ", got " +
                                    std::to_string(settings.resolution));
}

VoxelPlacement placementFor(const MeshBounds& bounds, const VoxelizeSettings& settings) {
    VoxelPlacement placement;
    double largest = 0.0;
    for (int a = 0; a < 3; ++a) {
        const double extent = bounds.extent(a);
        if (!std::isfinite(extent) || !std::isfinite(bounds.min[std::size_t(a)]))
            throw std::invalid_argument("the model has a non-finite coordinate");
        if (extent <= 0.0) throw std::invalid_argument(std::string("the model has zero extent along ") + kAxisNames[a]);
        largest = std::max(largest, extent);
    }
    const double resolution = settings.resolution;
    int sizes[3];
    for (std::size_t a = 0; a < 3; ++a) {
        const double extent = bounds.extent(int(a));
        const double scale = settings.stretch ? resolution / extent : resolution / largest;
        // The largest axis maps to exactly `resolution` cells; rounding must not add a cell.
        const double cells = extent * scale;
        sizes[a] = std::max(1, int(std::ceil(cells * (1.0 - 1e-12))));
        placement.modelMin[a] = bounds.min[a];
        placement.scale[a] = scale;
        placement.padding[a] = 0.5 * (sizes[a] - cells); // centred; never below y = 0
    }
    placement.size = {sizes[0], sizes[1], sizes[2]};
    validateGridSize(placement.size);
    return placement;
}

} // namespace

VoxelPlacement placeInGrid(const TriangleMesh& mesh, const VoxelizeSettings& settings) {
    checkResolution(settings);
    return placementFor(boundsOf(mesh), settings);
}

VoxelizeResult voxelize(const TriangleMesh& mesh, const VoxelizeSettings& settings) {
    VoxelizeResult result;
    checkResolution(settings);
    WorkerPool pool(std::max(settings.threads, 1));
    const MeshBounds bounds = boundsInParallel(mesh, pool);
    result.placement = placementFor(bounds, settings); // placeInGrid, its errors in the same order
    const VoxelPlacement& p = result.placement;
    if (settings.threads < 1) throw std::invalid_argument("voxelize needs at least one thread");
    // Welded once; one walk over the edges measures closedness and links the faces the outward
    // orientation flips (a second walk only when repeated faces had to go).
    WalkedMesh walked = weldAndWalk(mesh, pool);
    result.closedness = walked.closedness;
    // Parity does not depend on the faces' orientation: in plain mode one thread orients the
    // faces and sums the volume while the others cast rays. The winding numbers of robust
    // mode need the orientation first.
    Orientation orientation;
    double signedVolume = 0.0;
    const std::function<void()> orient = [&] {
        orientation = orientationOf(walked, bounds);
        signedVolume = orientation.signedVolume ? *orientation.signedVolume : signedVolumeOf(walked, orientation.flipped, bounds);
        if (settings.robust) applyOrientation(walked, orientation, pool);
    };
    // Robust mode flips triangles in place before the rays read them: they must be its own copy
    // by the time the rays are given their span.
    if (settings.robust) walked.changeableTriangles();
    const LargePageVector<Point> points = quantizedGridPoints(walked.vertices, p, pool);
    result.mask = insideFromPoints(points, walked.triangles, p.size, settings, pool, &orient);
    result.cellsInside = countInside(result.mask, pool);
    // The volume of the outward-oriented mesh: a model with some faces flipped keeps its
    // volume; where orientation cannot be made consistent (a non-orientable or non-manifold
    // surface) the volume means nothing and is not reported as if it did.
    result.volumeMeaningful = result.closedness.closed && orientation.inconsistentAfter == 0;
    result.meshVolume = std::abs(signedVolume) * p.scale[0] * p.scale[1] * p.scale[2];
    return result;
}

InsideMask voxelizeGridSpace(const TriangleMesh& gridMesh, Int3 size, const VoxelizeSettings& settings) {
    if (gridMesh.triangles.empty()) return insideFromGridPoints({}, {}, size, settings);
    const TriangleMesh prepared = preparedForRays(gridMesh);
    std::vector<std::array<double, 3>> grid(prepared.vertices.size());
    for (std::size_t i = 0; i < grid.size(); ++i)
        grid[i] = {prepared.vertices[i].x, prepared.vertices[i].y, prepared.vertices[i].z};
    return insideFromGridPoints(grid, prepared.triangles, size, settings);
}

} // namespace sandcore
