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

constexpr std::uint32_t kNone = ~std::uint32_t{0};
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

// Per vertex, the first vertex at the same position. The vertices are partitioned by the top
// bits of their hash (a stable counting sort, so each partition lists them in index order) and
// every partition is welded with a hash table small enough to stay in cache; a slot holds the
// position's hash bits and its place in the partition, whose entries carry their keys (reading
// the vertices again in partition order would miss the cache at every one).
BigVector<std::uint32_t> firstAtSamePosition(const std::vector<Vec3>& vertices, WorkerPool& pool) {
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
    if (count > kNone) throw std::invalid_argument("the mesh has too many vertices");
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
                std::fill_n(neighbours.begin() + std::ptrdiff_t(3 * n), 3, kNone);
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
                        for (const EdgeUse* u = group; u < first; ++u) neighbours[u->slot()] = kNone;
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

namespace {

// Flips the whole part when, with its current flips, it encloses a negative signed volume about
// its own centre (a centre near the part keeps the sum's rounding small).
void orientPartByVolume(std::span<const Vec3> vertices, std::span<const Triangle> triangles, std::span<const std::uint32_t> part,
                        std::span<std::int8_t> flipped) {
    std::array<double, 3> low, high;
    low.fill(std::numeric_limits<double>::infinity());
    high.fill(-std::numeric_limits<double>::infinity());
    for (std::uint32_t t : part)
        for (std::uint32_t i : triangles[t]) {
            const Vec3 v = vertices[i];
            const double c[3] = {v.x, v.y, v.z};
            for (std::size_t a = 0; a < 3; ++a) {
                low[a] = std::min(low[a], c[a]);
                high[a] = std::max(high[a], c[a]);
            }
        }
    double sixTimesVolume = 0.0;
    for (std::uint32_t t : part) {
        auto tri = triangles[t];
        if (flipped[t]) std::swap(tri[1], tri[2]);
        double p[3][3];
        for (std::size_t k = 0; k < 3; ++k) {
            const Vec3 v = vertices[tri[k]];
            p[k][0] = v.x - 0.5 * (low[0] + high[0]);
            p[k][1] = v.y - 0.5 * (low[1] + high[1]);
            p[k][2] = v.z - 0.5 * (low[2] + high[2]);
        }
        sixTimesVolume += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                          p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                          p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    }
    if (sixTimesVolume < 0.0)
        for (std::uint32_t t : part) flipped[t] ^= 1;
}

// orientFaces by a depth-first search from each part's first triangle, summing each part's
// volume in the order the search reaches its triangles: the definition, and the way for
// surfaces whose faces cannot all agree (the flips then depend on the search order).
Orientation orientationBySearch(const WalkedMesh& out) {
    const std::size_t count = out.triangles.size();
    const auto& neighbours = out.neighbours;
    std::vector<std::int8_t> flipped(count, -1); // -1: not reached yet
    std::vector<std::uint32_t> part, queue;
    for (std::size_t seed = 0; seed < count; ++seed) {
        if (flipped[seed] >= 0) continue;
        part.clear();
        queue.assign(1, std::uint32_t(seed));
        flipped[seed] = 0;
        while (!queue.empty()) {
            const std::uint32_t t = queue.back();
            queue.pop_back();
            part.push_back(t);
            // The neighbours in ascending order of their edge (smaller vertex, then larger), as the
            // walk over the edges met them: the same search order, so the same flips.
            const Triangle& tri = out.triangles[t];
            std::pair<std::uint64_t, std::uint32_t> links[3];
            int linkCount = 0;
            for (std::size_t e = 0; e < 3; ++e) {
                const std::uint32_t entry = neighbours[3 * std::size_t(t) + e];
                if (entry == kNone) continue;
                const std::uint32_t a = tri[e], b = tri[(e + 1) % 3];
                links[linkCount++] = {std::uint64_t(std::min(a, b)) << 32 | std::max(a, b), entry};
            }
            std::sort(links, links + linkCount);
            for (int l = 0; l < linkCount; ++l) {
                const std::uint32_t entry = links[l].second, other = entry >> 1;
                if (flipped[other] < 0) {
                    flipped[other] = std::int8_t(flipped[t] ^ int(entry & 1u));
                    queue.push_back(other);
                }
            }
        }
        // Orient the part as a whole so its signed volume about its own centre is positive.
        orientPartByVolume(out.vertices, out.triangles, part, flipped);
    }
    // A pair still inconsistent after the flips: it needed different flips and got the same, or the other way.
    Orientation result;
    std::int64_t& inconsistentAfter = result.inconsistentAfter;
    for (std::size_t t = 0; t < count; ++t)
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t entry = neighbours[3 * t + e];
            if (entry != kNone && (entry >> 1) > t && ((entry & 1u) ^ std::uint32_t(flipped[t] != flipped[entry >> 1])))
                ++inconsistentAfter;
        }
    result.flipped.assign(flipped.begin(), flipped.end());
    return result;
}


// Parts and relative flips by a union-find with parity over the links, in triangle order (the
// memory is read in order, not in the order of a search). The root of a part is its smallest
// triangle, the search's seed, so the flips relative to it are the search's wherever every link
// can be satisfied. Each part's volume is summed in triangle order; where that sum could have
// a different sign in the search's order (within rounding of zero), or a link cannot be
// satisfied, the search decides. Returns false then, with nothing changed.
bool orientationByParts(const WalkedMesh& out, const MeshBounds& bounds, Orientation& result) {
    const std::size_t count = out.triangles.size();
    const auto& neighbours = out.neighbours;
    BigVector<std::uint32_t> parent(count);
    BigVector<std::uint8_t> parity(count, 0); // flipped relative to the parent
    for (std::size_t t = 0; t < count; ++t) parent[t] = std::uint32_t(t);
    const auto find = [&](std::uint32_t t) {
        std::uint32_t root = t, toRoot = 0;
        while (parent[root] != root) toRoot ^= parity[root], root = parent[root];
        // Path compression: every node on the way points at the root with its parity to it.
        for (std::uint32_t at = t, p = toRoot; parent[at] != root && at != root;) {
            const std::uint32_t next = parent[at], nextParity = p ^ parity[at];
            parent[at] = root, parity[at] = std::uint8_t(p);
            at = next, p = nextParity;
        }
        return std::pair<std::uint32_t, std::uint32_t>{root, toRoot};
    };
    for (std::size_t t = 0; t < count; ++t)
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t entry = neighbours[3 * t + e];
            if (entry == kNone || (entry >> 1) < t) continue;
            const auto [rootA, parityA] = find(std::uint32_t(t));
            const auto [rootB, parityB] = find(entry >> 1);
            const std::uint32_t relative = parityA ^ parityB ^ (entry & 1u);
            if (rootA == rootB) {
                if (relative != 0) return false; // a link no choice of flips satisfies
                continue;
            }
            const std::uint32_t low = std::min(rootA, rootB), high = std::max(rootA, rootB);
            parent[high] = low, parity[high] = std::uint8_t(relative);
        }
    // Parts numbered by their first triangle (a root is its part's smallest triangle); flips
    // relative to it. A mesh of one part, the common case, needs no part numbers.
    std::uint32_t parts = 0;
    for (std::size_t t = 0; t < count; ++t) parts += parent[t] == t;
    const bool onePart = parts == 1;
    BigVector<std::uint32_t> partOf(onePart ? 0 : count);
    for (std::uint32_t t = 0, next = 0; t < count; ++t) {
        const auto [root, toRoot] = find(t);
        if (!onePart) partOf[t] = root == t ? next++ : partOf[root];
        parity[t] = std::uint8_t(toRoot);
    }
    struct PartSums {
        std::array<double, 3> low{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                                  std::numeric_limits<double>::infinity()};
        std::array<double, 3> high{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity()};
        double sixTimesVolume = 0.0, magnitude = 0.0;
        std::size_t terms = 0;
    };
    std::vector<PartSums> sums(parts);
    // One part uses every vertex the mesh as loaded uses (welding and dropping repeated faces
    // keep each position a kept face uses; only the sign of a zero may differ, and the centre,
    // half the sum of the bounds, does not): its bounds are the mesh's, with no pass over its
    // corners, and its volume is the mesh's (signedVolumeOf, the same terms in the same order).
    if (onePart) {
        sums[0].low = bounds.min;
        sums[0].high = bounds.max;
    } else {
        for (std::size_t t = 0; t < count; ++t) {
            PartSums& part = sums[partOf[t]];
            for (std::uint32_t i : out.triangles[t]) {
                const Vec3 v = out.vertices[i];
                const double c[3] = {v.x, v.y, v.z};
                for (std::size_t a = 0; a < 3; ++a) {
                    part.low[a] = std::min(part.low[a], c[a]);
                    part.high[a] = std::max(part.high[a], c[a]);
                }
            }
        }
    }
    // Six times the signed volume of face t about `centre`, flipped as its parity says.
    const auto volumeTerm = [&](std::size_t t, const double* centre) {
        auto tri = out.triangles[t];
        if (parity[t]) std::swap(tri[1], tri[2]);
        double p[3][3];
        for (std::size_t k = 0; k < 3; ++k) {
            const Vec3 v = out.vertices[tri[k]];
            p[k][0] = v.x - centre[0];
            p[k][1] = v.y - centre[1];
            p[k][2] = v.z - centre[2];
        }
        return p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
               p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    };
    const auto centreOf = [](const PartSums& part, double* centre) {
        for (std::size_t a = 0; a < 3; ++a) centre[a] = 0.5 * (part.low[a] + part.high[a]);
    };
    if (onePart) {
        // The sums in locals: through a reference into `sums` they would be stored at every face.
        double centre[3], sixTimesVolume = 0.0, magnitude = 0.0;
        centreOf(sums[0], centre);
        for (std::size_t t = 0; t < count; ++t) {
            const double term = volumeTerm(t, centre);
            sixTimesVolume += term;
            magnitude += std::abs(term);
        }
        sums[0].sixTimesVolume = sixTimesVolume;
        sums[0].magnitude = magnitude;
        sums[0].terms = count;
    } else {
        for (std::size_t t = 0; t < count; ++t) {
            PartSums& part = sums[partOf[t]];
            double centre[3];
            centreOf(part, centre);
            const double term = volumeTerm(t, centre);
            part.sixTimesVolume += term;
            part.magnitude += std::abs(term);
            ++part.terms;
        }
    }
    // Summed in any order, n terms stay within n * 2^-53 * sum |term| of their exact sum: a sum
    // farther from zero than twice that (with a margin) has the sign of every order's sum.
    std::vector<std::uint8_t> flipPart(parts);
    for (std::size_t n = 0; n < parts; ++n) {
        const PartSums& part = sums[n];
        const double bound = 4.0 * double(part.terms + 1) * 0x1p-53 * part.magnitude;
        if (!(std::abs(part.sixTimesVolume) > bound)) return false;
        flipPart[n] = part.sixTimesVolume < 0.0;
    }
    result.flipped.resize(count);
    for (std::size_t t = 0; t < count; ++t) result.flipped[t] = parity[t] ^ flipPart[onePart ? 0 : partOf[t]];
    result.inconsistentAfter = 0; // every link satisfied
    // Turning every face over negates each term exactly, and so the sum.
    if (onePart) result.signedVolume = (flipPart[0] ? -sums[0].sixTimesVolume : sums[0].sixTimesVolume) / 6.0;
    return true;
}

} // namespace

Orientation orientationOf(const WalkedMesh& walked, const MeshBounds& bounds) {
    Orientation orientation;
    if (orientationByParts(walked, bounds, orientation)) return orientation;
    return orientationBySearch(walked);
}

double signedVolumeOf(const WalkedMesh& walked, const LargePageVector<std::uint8_t>& flipped, const MeshBounds& bounds) {
    // signedVolume's loops, on the triangles as they will be after the flips.
    if (walked.triangles.empty()) return 0.0;
    const double cx = 0.5 * (bounds.min[0] + bounds.max[0]), cy = 0.5 * (bounds.min[1] + bounds.max[1]),
                 cz = 0.5 * (bounds.min[2] + bounds.max[2]);
    double sixTimesVolume = 0.0;
    for (std::size_t n = 0; n < walked.triangles.size(); ++n) {
        const Triangle& t = walked.triangles[n];
        const Vec3 a = walked.vertices[t[0]], b = walked.vertices[t[flipped[n] ? 2 : 1]],
                   c = walked.vertices[t[flipped[n] ? 1 : 2]];
        const double ax = a.x - cx, ay = a.y - cy, az = a.z - cz;
        const double bx = b.x - cx, by = b.y - cy, bz = b.z - cz;
        const double qx = c.x - cx, qy = c.y - cy, qz = c.z - cz;
        sixTimesVolume += ax * (by * qz - bz * qy) - ay * (bx * qz - bz * qx) + az * (bx * qy - by * qx);
    }
    return sixTimesVolume / 6.0;
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
