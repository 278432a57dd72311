// SPDX-License-Identifier: MIT
#include "mesh_preparation.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace sandcore {

namespace {

template <class T> using BigVector = LargePageVector<T>;
using Triangle = MeshTriangle;
using Key = std::array<std::uint32_t, 3>;

// Vertex ranges the parallel passes split into: fixed, so nothing depends on the thread count.
constexpr std::size_t kRanges = 64;
// Batches of vertices the edge walk files its uses in (at most; fewer for small meshes).
constexpr std::size_t kUseBatches = 4;

std::size_t rangeBegin(std::size_t count, std::size_t ranges, std::size_t r) { return count * r / ranges; }

// Chunks of a parallel counting sort: one per thread, at most four (each has a count per
// bucket). The sorts are stable, so the result does not depend on it.
std::size_t countingChunks(const WorkerPool& pool) { return std::size_t(std::min(pool.threadCount(), 4)); }

// -0.0 and +0.0 are the same position; everything else is compared bit for bit.
std::uint32_t bitsOf(float value) { return std::bit_cast<std::uint32_t>(value == 0.0f ? 0.0f : value); }
Key keyOf(Vec3 v) { return {bitsOf(v.x), bitsOf(v.y), bitsOf(v.z)}; }
std::uint64_t hashOf(const Key& key) {
    std::uint64_t h = key[0];
    h = h * 0x9E3779B97F4A7C15ull ^ key[1];
    h = h * 0x9E3779B97F4A7C15ull ^ key[2];
    return h * 0x9E3779B97F4A7C15ull;
}

// firstAtSamePosition on one thread: one table over all the vertices. The partitions below pay
// for their counting sort only when threads share them.
BigVector<std::uint32_t> firstAtSamePositionOnOneThread(const std::vector<Vec3>& vertices) {
    const std::size_t count = vertices.size();
    std::size_t capacity = 16;
    while (capacity < 2 * count) capacity *= 2;
    constexpr std::uint32_t kFree = ~std::uint32_t{0};
    std::vector<std::uint32_t> slots(capacity, kFree); // the first vertex at a position
    BigVector<std::uint32_t> first(count);
    for (std::size_t i = 0; i < count; ++i) {
        const Key key = keyOf(vertices[i]);
        std::size_t slot = std::size_t(hashOf(key) >> 32) & (capacity - 1);
        while (slots[slot] != kFree && keyOf(vertices[slots[slot]]) != key) slot = (slot + 1) & (capacity - 1);
        if (slots[slot] == kFree) slots[slot] = std::uint32_t(i);
        first[i] = slots[slot];
    }
    return first;
}

// Per vertex, the first vertex at the same position. The vertices are partitioned by the top
// bits of their hash (a stable counting sort, so each partition lists them in index order) and
// every partition is welded with a hash table small enough to stay in cache; a slot holds the
// position's hash bits and its place in the partition, whose entries carry their keys (reading
// the vertices again in partition order would miss the cache at every one).
BigVector<std::uint32_t> firstAtSamePosition(const std::vector<Vec3>& vertices, WorkerPool& pool) {
    if (pool.threadCount() == 1) return firstAtSamePositionOnOneThread(vertices);
    const std::size_t count = vertices.size();
    int partitionBits = 0;
    while (partitionBits < 16 && (count >> partitionBits) > 2048) ++partitionBits;
    const std::size_t partitions = std::size_t{1} << partitionBits;
    const auto partitionOf = [&](std::uint64_t h) { return partitionBits == 0 ? 0 : std::size_t(h >> (64 - partitionBits)); };
    const std::size_t chunks = countingChunks(pool);
    std::vector<std::uint32_t> place(chunks * partitions, 0); // counts, then where each chunk's next vertex goes
    pool.parallelFor(int(chunks), [&](int c) {
        std::uint32_t* counts = place.data() + std::size_t(c) * partitions;
        for (std::size_t i = rangeBegin(count, chunks, c); i < rangeBegin(count, chunks, c + 1); ++i)
            ++counts[partitionOf(hashOf(keyOf(vertices[i])))];
    });
    std::vector<std::size_t> partitionStart(partitions + 1);
    std::size_t running = 0;
    for (std::size_t p = 0; p < partitions; ++p) {
        partitionStart[p] = running;
        for (std::size_t c = 0; c < chunks; ++c) running += std::exchange(place[c * partitions + p], std::uint32_t(running));
    }
    partitionStart[partitions] = running;
    struct KeyedVertex {
        Key key;
        std::uint32_t index;
    };
    BigVector<KeyedVertex> byPartition(count);
    pool.parallelFor(int(chunks), [&](int c) {
        std::uint32_t* next = place.data() + std::size_t(c) * partitions;
        for (std::size_t i = rangeBegin(count, chunks, c); i < rangeBegin(count, chunks, c + 1); ++i) {
            const Key key = keyOf(vertices[i]);
            byPartition[next[partitionOf(hashOf(key))]++] = {key, std::uint32_t(i)};
        }
    });
    BigVector<std::uint32_t> first(count);
    const std::size_t groups = std::min(partitions, kRanges);
    pool.parallelFor(int(groups), [&](int g) {
        constexpr std::uint64_t kFree = ~std::uint64_t{0};
        std::vector<std::uint64_t> table; // hash bits << 32 | place of the first vertex in the partition
        for (std::size_t p = rangeBegin(partitions, groups, g); p < rangeBegin(partitions, groups, g + 1); ++p) {
            const std::size_t size = partitionStart[p + 1] - partitionStart[p];
            std::size_t capacity = 16;
            while (capacity < 2 * size) capacity *= 2;
            table.assign(capacity, kFree);
            const KeyedVertex* part = byPartition.data() + partitionStart[p];
            for (std::uint32_t j = 0; j < size; ++j) {
                const std::uint64_t h = hashOf(part[j].key), tag = h >> 32; // j < 2^32 - 1: no entry is kFree
                std::size_t slot = std::size_t(h >> 16) & (capacity - 1);
                while (table[slot] != kFree &&
                       ((table[slot] >> 32) != tag || part[std::uint32_t(table[slot])].key != part[j].key))
                    slot = (slot + 1) & (capacity - 1);
                if (table[slot] == kFree) table[slot] = tag << 32 | j;
                first[part[j].index] = part[std::uint32_t(table[slot])].index;
            }
        }
    });
    return first;
}

bool isDegenerate(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }

void checkIndices(const Triangle& t, std::size_t vertices) {
    if (t[0] >= vertices || t[1] >= vertices || t[2] >= vertices)
        throw std::invalid_argument("a triangle refers to a missing vertex");
}

// Positions in the order of their first use, triangles renumbered. Where no two
// vertices share a position the result is the mesh itself, and nothing is copied: fresh memory
// is what costs most here (the kernel clears every page), and meshes that were welded on
// loading are the common case. Their indices are checked by the edge walk that follows (it reads
// every triangle anyway); renumbered triangles are checked here, before their indices are used.
void weld(const TriangleMesh& mesh, WalkedMesh& out, WorkerPool& pool) {
    const std::size_t count = mesh.vertices.size();
    if (count > std::numeric_limits<std::uint32_t>::max()) throw std::invalid_argument("the mesh has too many vertices");
    const BigVector<std::uint32_t> first = firstAtSamePosition(mesh.vertices, pool);
    std::vector<std::uint32_t> firstsBefore(kRanges + 1, 0);
    pool.parallelFor(int(kRanges), [&](int r) {
        std::uint32_t n = 0;
        for (std::size_t i = rangeBegin(count, kRanges, r); i < rangeBegin(count, kRanges, r + 1); ++i) n += first[i] == i;
        firstsBefore[std::size_t(r) + 1] = n;
    });
    for (std::size_t r = 0; r < kRanges; ++r) firstsBefore[r + 1] += firstsBefore[r];
    const std::size_t triangles = mesh.triangles.size();
    if (firstsBefore[kRanges] == count) {
        out.vertices = mesh.vertices;
        out.triangles = mesh.triangles;
        return;
    }
    out.weldedVertices.resize(firstsBefore[kRanges]);
    BigVector<std::uint32_t> remap(count);
    pool.parallelFor(int(kRanges), [&](int r) {
        std::uint32_t n = firstsBefore[std::size_t(r)];
        for (std::size_t i = rangeBegin(count, kRanges, r); i < rangeBegin(count, kRanges, r + 1); ++i)
            if (first[i] == i) {
                out.weldedVertices[n] = mesh.vertices[i];
                remap[i] = n++;
            }
    });
    pool.parallelFor(int(kRanges), [&](int r) {
        for (std::size_t i = rangeBegin(count, kRanges, r); i < rangeBegin(count, kRanges, r + 1); ++i)
            if (first[i] != i) remap[i] = remap[first[i]];
    });
    out.ownTriangles.resize(triangles);
    pool.parallelFor(int(kRanges), [&](int r) {
        for (std::size_t n = rangeBegin(triangles, kRanges, r); n < rangeBegin(triangles, kRanges, r + 1); ++n) {
            const Triangle& t = mesh.triangles[n];
            checkIndices(t, count);
            out.ownTriangles[n] = {remap[t[0]], remap[t[1]], remap[t[2]]};
        }
    });
    out.vertices = out.weldedVertices;
    out.triangles = out.ownTriangles;
}

// One use of an edge by a triangle, filed under the edge's smaller vertex: the larger vertex,
// and the triangle, which of its edges this is and whether it runs from the smaller vertex to
// the larger one (triangle << 3 | edge << 1 | forward).
struct EdgeUse {
    std::uint32_t other;
    std::uint32_t use;
    std::uint32_t triangle() const { return use >> 3; }
    std::uint32_t slot() const { return 3 * triangle() + ((use >> 1) & 3u); }
    bool forward() const { return use & 1u; }
};

struct WalkCounts {
    MeshClosedness closedness;
    std::vector<std::uint32_t> suspects; // triangles that might repeat another: they share an edge the same way
};

// The walk over the edges: the uses are filed under their smaller
// vertex by a stable counting sort (the chunks of triangles in order), then each vertex range
// groups its uses by edge. Fills `neighbours`; the counts are sums, so the order of ranges does not matter.
WalkCounts walkEdges(std::span<const Triangle> meshTriangles, std::size_t vertices, BigVector<std::uint32_t>& neighbours, WorkerPool& pool) {
    const std::size_t triangles = meshTriangles.size();
    if (triangles >= (std::size_t{1} << 29)) throw std::invalid_argument("the mesh has too many triangles");
    const std::size_t chunks = countingChunks(pool);
    // place[c * vertices + v]: the uses of chunk c filed under v, then where the next one goes.
    // Every array here is written once, each part by the thread that uses it: a serial fill of
    // fresh memory would leave the other threads idle while the kernel clears its pages.
    BigVector<std::uint32_t> place(chunks * vertices);
    neighbours.clear();
    neighbours.resize(3 * triangles); // every slot is written below: by the walk, or here for a degenerate face
    pool.parallelFor(int(chunks), [&](int c) {
        std::uint32_t* counts = place.data() + std::size_t(c) * vertices;
        std::fill(counts, counts + vertices, 0u);
        for (std::size_t n = rangeBegin(triangles, chunks, c); n < rangeBegin(triangles, chunks, c + 1); ++n) {
            const Triangle& t = meshTriangles[n];
            checkIndices(t, vertices);
            if (isDegenerate(t)) {
                std::fill_n(neighbours.begin() + std::ptrdiff_t(3 * n), 3, kNoNeighbour);
                continue;
            }
            for (std::size_t e = 0; e < 3; ++e) ++counts[std::min(t[e], t[(e + 1) % 3])];
        }
    });
    std::vector<std::uint32_t> rangeStart(kRanges + 1, 0);
    pool.parallelFor(int(kRanges), [&](int r) {
        std::uint32_t sum = 0;
        for (std::size_t v = rangeBegin(vertices, kRanges, r); v < rangeBegin(vertices, kRanges, r + 1); ++v)
            for (std::size_t c = 0; c < chunks; ++c) sum += place[c * vertices + v];
        rangeStart[std::size_t(r) + 1] = sum;
    });
    for (std::size_t r = 0; r < kRanges; ++r) rangeStart[r + 1] += rangeStart[r];
    BigVector<std::uint32_t> start(vertices + 1);
    start[vertices] = rangeStart[kRanges];
    pool.parallelFor(int(kRanges), [&](int r) {
        std::uint32_t running = rangeStart[std::size_t(r)];
        for (std::size_t v = rangeBegin(vertices, kRanges, r); v < rangeBegin(vertices, kRanges, r + 1); ++v) {
            start[v] = running;
            for (std::size_t c = 0; c < chunks; ++c) running += std::exchange(place[c * vertices + v], running);
        }
    });
    // The uses are filed and walked in batches of vertices, so the buffer that holds them is a
    // fraction of all uses: fresh memory is what costs most here (the kernel clears every page).
    const std::size_t totalUses = start[vertices];
    const std::size_t batches = std::max<std::size_t>(1, std::min<std::size_t>(kUseBatches, totalUses / 4096));
    std::vector<std::size_t> batchStart(batches + 1, vertices); // first vertex of each batch
    for (std::size_t b = 0; b < batches; ++b)
        batchStart[b] = std::size_t(std::lower_bound(start.begin(), start.begin() + std::ptrdiff_t(vertices),
                                                     std::uint32_t(totalUses * b / batches)) - start.begin());
    batchStart[0] = 0;
    std::size_t largestBatch = 0;
    for (std::size_t b = 0; b < batches; ++b)
        largestBatch = std::max<std::size_t>(largestBatch, start[batchStart[b + 1]] - start[batchStart[b]]);
    BigVector<EdgeUse> uses(largestBatch);
    std::vector<WalkCounts> perRange(kRanges * batches);
    for (std::size_t b = 0; b < batches; ++b) {
        const std::uint32_t low = std::uint32_t(batchStart[b]), high = std::uint32_t(batchStart[b + 1]);
        const std::uint32_t base = start[low];
        pool.parallelFor(int(chunks), [&](int c) {
            std::uint32_t* next = place.data() + std::size_t(c) * vertices;
            for (std::size_t n = rangeBegin(triangles, chunks, c); n < rangeBegin(triangles, chunks, c + 1); ++n) {
                const Triangle& t = meshTriangles[n];
                if (isDegenerate(t)) continue;
                for (std::uint32_t e = 0; e < 3; ++e) {
                    const std::uint32_t p = t[e], q = t[(e + 1) % 3], filedUnder = std::min(p, q);
                    if (filedUnder < low || filedUnder >= high) continue;
                    uses[next[filedUnder]++ - base] = {std::max(p, q), std::uint32_t(n) << 3 | e << 1 | std::uint32_t(p < q)};
                }
            }
        });
        pool.parallelFor(int(kRanges), [&](int r) {
            WalkCounts& counts = perRange[b * kRanges + std::size_t(r)];
            for (std::size_t v = low + rangeBegin(high - low, kRanges, r); v < low + rangeBegin(high - low, kRanges, r + 1); ++v) {
                EdgeUse* first = uses.data() + (start[v] - base);
                EdgeUse* last = uses.data() + (start[v + 1] - base);
                // Stable, so the uses of one edge stay in triangle order; a fan of many triangles
                // around one vertex (a cone's apex) takes the O(n log n) sort.
                const auto byOther = [](const EdgeUse& p, const EdgeUse& q) { return p.other < q.other; };
                if (last - first > 32)
                    std::stable_sort(first, last, byOther);
                else
                    for (EdgeUse* i = first + 1; i < last; ++i)
                        for (EdgeUse* j = i; j > first && byOther(*j, j[-1]); --j) std::swap(j[-1], *j);
                while (first < last) {
                    EdgeUse* group = first;
                    while (first < last && first->other == group->other) ++first;
                    const std::size_t n = std::size_t(first - group);
                    if (n % 2 == 1) ++counts.closedness.boundaryEdges;
                    if (n > 2) ++counts.closedness.nonManifoldEdges;
                    if (n != 2)
                        for (const EdgeUse* u = group; u < first; ++u) neighbours[u->slot()] = kNoNeighbour;
                    if (n == 2) {
                        const bool flip = group[0].forward() == group[1].forward();
                        neighbours[group[0].slot()] = group[1].triangle() << 1 | std::uint32_t(flip);
                        neighbours[group[1].slot()] = group[0].triangle() << 1 | std::uint32_t(flip);
                        if (!flip) continue;
                        ++counts.closedness.inconsistentEdges;
                    }
                    // A face written twice the same way runs along each of its edges in the same
                    // direction as its copy: two uses of this edge the same way.
                    std::size_t forward = 0;
                    for (const EdgeUse* u = group; u < first; ++u) forward += u->forward();
                    if (forward >= 2 || n - forward >= 2)
                        for (const EdgeUse* u = group; u < first; ++u) counts.suspects.push_back(u->triangle());
                }
            }
        });
    }
    WalkCounts total;
    for (WalkCounts& counts : perRange) {
        total.closedness.boundaryEdges += counts.closedness.boundaryEdges;
        total.closedness.nonManifoldEdges += counts.closedness.nonManifoldEdges;
        total.closedness.inconsistentEdges += counts.closedness.inconsistentEdges;
        total.suspects.insert(total.suspects.end(), counts.suspects.begin(), counts.suspects.end());
    }
    total.closedness.closed = total.closedness.boundaryEdges == 0;
    return total;
}

// Per triangle, 1 when it stays: of the faces that are equal once rotated so their smallest
// index comes first (the same face with the same orientation), the first one. Empty when every
// one stays. Looks only at the triangles that can repeat another: a repeated face and its first
// copy are both suspects (or degenerate), so every group of equal faces lies among them.
std::vector<char> trianglesToKeepAmong(std::span<const Triangle> triangles, std::vector<std::uint32_t> candidates) {
    for (std::size_t n = 0; n < triangles.size(); ++n)
        if (isDegenerate(triangles[n])) candidates.push_back(std::uint32_t(n));
    using Keyed = std::pair<Triangle, std::uint32_t>;
    std::vector<Keyed> keyed;
    keyed.reserve(candidates.size());
    for (const std::uint32_t n : candidates) {
        Triangle t = triangles[n];
        while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
        keyed.push_back({t, n});
    }
    std::sort(keyed.begin(), keyed.end());
    keyed.erase(std::unique(keyed.begin(), keyed.end()), keyed.end()); // a suspect can be listed twice
    std::vector<char> keep;
    for (std::size_t n = 1; n < keyed.size(); ++n)
        if (keyed[n].first == keyed[n - 1].first) {
            if (keep.empty()) keep.assign(triangles.size(), 1);
            keep[keyed[n].second] = 0;
        }
    return keep;
}

} // namespace

std::span<MeshTriangle> WalkedMesh::changeableTriangles() {
    if (ownTriangles.data() != triangles.data() || ownTriangles.size() != triangles.size()) {
        ownTriangles.assign(triangles.begin(), triangles.end());
        triangles = ownTriangles;
    }
    return ownTriangles;
}

void WalkedMesh::keepFirstTriangles(std::size_t count) {
    changeableTriangles();
    ownTriangles.resize(count);
    triangles = ownTriangles;
}

TriangleMesh WalkedMesh::copy() const {
    TriangleMesh mesh;
    mesh.vertices.assign(vertices.begin(), vertices.end());
    mesh.triangles.assign(triangles.begin(), triangles.end());
    return mesh;
}

const char* widenBoundsByCorners(std::span<const Vec3> vertices, std::span<const MeshTriangle> triangles, std::size_t first,
                                 std::size_t end, MeshBounds& bounds) {
    // The running bounds in locals: through the reference the compiler would store them at every
    // corner (they might alias the vertices).
    std::array<double, 3> low = bounds.min, high = bounds.max;
    const char* error = nullptr;
    for (std::size_t n = first; n < end && !error; ++n)
        for (std::uint32_t i : triangles[n]) {
            if (i >= vertices.size()) {
                error = "a triangle refers to a missing vertex";
                break;
            }
            const Vec3 v = vertices[i];
            const double c[3] = {v.x, v.y, v.z};
            if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) {
                error = "the model has a non-finite coordinate (NaN or infinity)";
                break;
            }
            for (std::size_t a = 0; a < 3; ++a) {
                low[a] = std::min(low[a], c[a]);
                high[a] = std::max(high[a], c[a]);
            }
        }
    bounds.min = low;
    bounds.max = high;
    return error;
}

MeshBounds boundsInParallel(const TriangleMesh& mesh, WorkerPool& pool) {
    if (mesh.triangles.empty()) throw std::invalid_argument("the mesh has no triangles");
    struct Part {
        MeshBounds bounds;
        const char* error = nullptr; // the first one in triangle order
    };
    std::vector<Part> parts(kRanges);
    const std::size_t count = mesh.triangles.size();
    pool.parallelFor(int(kRanges), [&](int r) {
        Part& part = parts[std::size_t(r)];
        part.bounds.min.fill(std::numeric_limits<double>::infinity());
        part.bounds.max.fill(-std::numeric_limits<double>::infinity());
        part.error = widenBoundsByCorners(mesh.vertices, mesh.triangles, rangeBegin(count, kRanges, r), rangeBegin(count, kRanges, r + 1), part.bounds);
    });
    MeshBounds bounds;
    bounds.min.fill(std::numeric_limits<double>::infinity());
    bounds.max.fill(-std::numeric_limits<double>::infinity());
    // In range order, so a tie between -0.0 and +0.0 keeps the one met first, as boundsOf does.
    for (const Part& part : parts) {
        if (part.error) throw std::invalid_argument(part.error);
        for (std::size_t a = 0; a < 3; ++a) {
            bounds.min[a] = std::min(bounds.min[a], part.bounds.min[a]);
            bounds.max[a] = std::max(bounds.max[a], part.bounds.max[a]);
        }
    }
    return bounds;
}

WalkedMesh weldedVertices(const TriangleMesh& mesh, WorkerPool& pool) {
    WalkedMesh welded;
    weld(mesh, welded, pool);
    return welded;
}

WalkedMesh weldAndWalk(const TriangleMesh& mesh, WorkerPool& pool, RepeatedFaces repeated) {
    WalkedMesh walked;
    weld(mesh, walked, pool);
    WalkCounts asLoaded = walkEdges(walked.triangles, walked.vertices.size(), walked.neighbours, pool);
    walked.closedness = asLoaded.closedness;
    if (repeated == RepeatedFaces::Keep) return walked;
    const std::vector<char> keep = trianglesToKeepAmong(walked.triangles, std::move(asLoaded.suspects));
    if (keep.empty()) return walked;
    // Faces written twice go; the walk over what is left links the faces anew.
    const std::span<Triangle> triangles = walked.changeableTriangles();
    std::size_t kept = 0;
    for (std::size_t n = 0; n < triangles.size(); ++n)
        if (keep[n]) triangles[kept++] = triangles[n];
    walked.keepFirstTriangles(kept);
    walkEdges(walked.triangles, walked.vertices.size(), walked.neighbours, pool);
    return walked;
}

TriangleMesh turnedOutward(WalkedMesh walked, WorkerPool& pool) {
    // The bounds of the corners the faces use. A non-finite coordinate stops them short, but then
    // no volume sum is finite either, so the orientation falls back to its search, which measures
    // each part itself.
    MeshBounds bounds;
    bounds.min.fill(std::numeric_limits<double>::infinity());
    bounds.max.fill(-std::numeric_limits<double>::infinity());
    (void)widenBoundsByCorners(walked.vertices, walked.triangles, 0, walked.triangles.size(), bounds);
    applyOrientation(walked, orientationOf(walked, bounds), pool);
    return walked.copy();
}

void applyOrientation(WalkedMesh& walked, const Orientation& orientation, WorkerPool& pool) {
    const std::span<Triangle> triangles = walked.changeableTriangles();
    const std::size_t count = triangles.size();
    pool.parallelFor(int(kRanges), [&](int r) {
        for (std::size_t t = rangeBegin(count, kRanges, r); t < rangeBegin(count, kRanges, r + 1); ++t)
            if (orientation.flipped[t]) std::swap(triangles[t][1], triangles[t][2]);
    });
}

} // namespace sandcore
