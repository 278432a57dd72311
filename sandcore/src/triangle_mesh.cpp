// SPDX-License-Identifier: MIT
#include "sandcore/triangle_mesh.hpp"

#include "welded_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <bit>
#include <limits>
#include <span>
#include <stdexcept>
#include <functional>

namespace sandcore {

// Flips the whole part when, with its current flips, it encloses a negative signed volume about
// its own centre (a centre near the part keeps the sum's rounding small).
void orientPartByVolume(std::span<const Vec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
                        std::span<const std::uint32_t> part, std::span<std::int8_t> flipped) {
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


void TriangleMesh::append(const TriangleMesh& other) {
    const auto base = std::uint32_t(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    for (const auto& t : other.triangles) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

const char* widenBoundsByCorners(const TriangleMesh& mesh, std::size_t first, std::size_t end, MeshBounds& bounds) {
    // The running bounds in locals: through the reference the compiler would store them at every
    // corner (they might alias the vertices), three times slower on a big mesh.
    std::array<double, 3> low = bounds.min, high = bounds.max;
    const char* error = nullptr;
    for (std::size_t n = first; n < end && !error; ++n)
        for (std::uint32_t i : mesh.triangles[n]) {
            if (i >= mesh.vertices.size()) {
                error = "a triangle refers to a missing vertex";
                break;
            }
            const Vec3 v = mesh.vertices[i];
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

MeshBounds boundsOf(const TriangleMesh& mesh) {
    if (mesh.triangles.empty()) throw std::invalid_argument("the mesh has no triangles");
    MeshBounds bounds;
    bounds.min.fill(std::numeric_limits<double>::infinity());
    bounds.max.fill(-std::numeric_limits<double>::infinity());
    if (const char* error = widenBoundsByCorners(mesh, 0, mesh.triangles.size(), bounds)) throw std::invalid_argument(error);
    return bounds;
}

namespace {

// -0.0 and +0.0 are the same position; everything else is compared bit for bit.
std::uint32_t bitsOf(float value) { return std::bit_cast<std::uint32_t>(value == 0.0f ? 0.0f : value); }

// Buckets the items by bucketOf(item) < bucketCount with a counting sort (stable), then sorts
// each bucket with less: the same grouping as one std::sort, in linear time when the buckets
// are small (a vertex's edges, a vertex's triangles).
template <class Item, class BucketOf, class Less>
std::vector<Item> bucketSorted(const std::vector<Item>& items, std::size_t bucketCount, BucketOf bucketOf, Less less) {
    std::vector<std::uint32_t> start(bucketCount + 1, 0);
    for (const Item& item : items) ++start[bucketOf(item) + 1];
    for (std::size_t b = 0; b < bucketCount; ++b) start[b + 1] += start[b];
    std::vector<Item> sorted(items.size());
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (const Item& item : items) sorted[next[bucketOf(item)]++] = item;
    for (std::size_t b = 0; b < bucketCount; ++b)
        if (start[b + 1] - start[b] > 1) std::sort(sorted.begin() + start[b], sorted.begin() + start[b + 1], less);
    return sorted;
}

} // namespace

// An open-addressing table of the distinct positions (a power-of-two size at most half full):
// several times faster than std::unordered_map on a million vertices. Vertices keep the order
// of their first use, as before.
TriangleMesh weldVertices(const TriangleMesh& mesh) {
    TriangleMesh welded;
    const std::size_t count = mesh.vertices.size();
    std::size_t capacity = 16;
    while (capacity < 2 * count) capacity *= 2;
    constexpr std::uint32_t kFree = ~std::uint32_t{0};
    std::vector<std::uint32_t> slots(capacity, kFree);
    std::vector<std::array<std::uint32_t, 3>> keys; // bits of each welded vertex
    keys.reserve(count);
    welded.vertices.reserve(count);
    std::vector<std::uint32_t> remap(count);
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 v = mesh.vertices[i];
        const std::array<std::uint32_t, 3> key{bitsOf(v.x), bitsOf(v.y), bitsOf(v.z)};
        std::uint64_t h = key[0];
        h = h * 0x9E3779B97F4A7C15ull ^ key[1];
        h = h * 0x9E3779B97F4A7C15ull ^ key[2];
        h *= 0x9E3779B97F4A7C15ull;
        std::size_t slot = std::size_t(h >> 32) & (capacity - 1);
        while (slots[slot] != kFree && keys[slots[slot]] != key) slot = (slot + 1) & (capacity - 1);
        if (slots[slot] == kFree) {
            slots[slot] = std::uint32_t(welded.vertices.size());
            welded.vertices.push_back(v);
            keys.push_back(key);
        }
        remap[i] = slots[slot];
    }
    welded.triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        if (t[0] >= remap.size() || t[1] >= remap.size() || t[2] >= remap.size())
            throw std::invalid_argument("a triangle refers to a missing vertex");
        welded.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
    }
    return welded;
}

namespace {

// One use of an edge by a triangle, filed under the edge's smaller vertex: the larger vertex,
// the triangle, and whether the triangle runs along the edge from the smaller vertex to the larger.
struct EdgeUse {
    std::uint32_t other;
    std::uint32_t triangleAndForward; // triangle << 1 | forward
    std::uint32_t triangle() const { return triangleAndForward >> 1; }
    bool forward() const { return triangleAndForward & 1u; }
};

// Calls visit(uses, count) once per edge of the non-degenerate triangles with the uses of that
// edge, edges in ascending (smaller vertex, larger vertex) order, the uses of one edge in
// triangle order. The uses are filed under their edge's smaller vertex by a counting sort (two
// passes over the triangles) and each vertex's few uses put in order by insertion sort: linear
// time, and half the memory of sorting 64-bit edge keys.
template <class Visit> void forEachEdge(const TriangleMesh& welded, Visit&& visit) {
    if (welded.triangles.size() >= (std::size_t{1} << 31)) throw std::invalid_argument("the mesh has too many triangles");
    const auto degenerate = [](const std::array<std::uint32_t, 3>& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; };
    std::vector<std::uint32_t> start(welded.vertices.size() + 1, 0);
    for (const auto& t : welded.triangles)
        if (!degenerate(t))
            for (std::size_t e = 0; e < 3; ++e) ++start[std::size_t(std::min(t[e], t[(e + 1) % 3])) + 1];
    for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
    std::vector<EdgeUse> uses(start.back());
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t n = 0; n < welded.triangles.size(); ++n) {
        const auto& t = welded.triangles[n];
        if (degenerate(t)) continue;
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t a = t[e], b = t[(e + 1) % 3];
            uses[next[std::min(a, b)]++] = {std::max(a, b), std::uint32_t(n) << 1 | std::uint32_t(a < b)};
        }
    }
    for (std::size_t v = 0; v + 1 < start.size(); ++v) {
        EdgeUse* first = uses.data() + start[v];
        EdgeUse* last = uses.data() + start[v + 1];
        // Stable, so the uses of one edge stay in triangle order; a fan of many triangles around one
        // vertex (a cone's apex) takes the O(n log n) sort.
        const auto byOther = [](const EdgeUse& p, const EdgeUse& q) { return p.other < q.other; };
        if (last - first > 32)
            std::stable_sort(first, last, byOther);
        else
            for (EdgeUse* i = first + 1; i < last; ++i)
                for (EdgeUse* j = i; j > first && byOther(*j, j[-1]); --j) std::swap(j[-1], *j);
        while (first < last) {
            EdgeUse* group = first;
            while (first < last && first->other == group->other) ++first;
            visit(group, std::size_t(first - group));
        }
    }
}

} // namespace

MeshClosedness closednessOfWelded(const TriangleMesh& welded) {
    MeshClosedness result;
    forEachEdge(welded, [&](const EdgeUse* uses, std::size_t count) {
        if (count % 2 == 1) ++result.boundaryEdges;
        if (count > 2) ++result.nonManifoldEdges;
        if (count == 2 && uses[0].forward() == uses[1].forward()) ++result.inconsistentEdges;
    });
    result.closed = result.boundaryEdges == 0;
    return result;
}

MeshClosedness closednessOf(const TriangleMesh& mesh) { return closednessOfWelded(weldVertices(mesh)); }

std::vector<char> trianglesToKeep(const TriangleMesh& welded) {
    // Each triangle rotated so its smallest index comes first: the same face with the same
    // orientation gives the same triple. Of equal triples the first triangle stays.
    using Keyed = std::pair<std::array<std::uint32_t, 3>, std::uint32_t>;
    std::vector<Keyed> keyed;
    keyed.reserve(welded.triangles.size());
    for (std::size_t n = 0; n < welded.triangles.size(); ++n) {
        auto t = welded.triangles[n];
        while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
        keyed.push_back({t, std::uint32_t(n)});
    }
    keyed = bucketSorted(keyed, welded.vertices.size(), [](const Keyed& k) { return std::size_t(k.first[0]); },
                         std::less<Keyed>());
    std::vector<char> keep(welded.triangles.size(), 1);
    bool any = false;
    for (std::size_t n = 1; n < keyed.size(); ++n)
        if (keyed[n].first == keyed[n - 1].first) keep[keyed[n].second] = 0, any = true;
    if (!any) keep.clear();
    return keep;
}

TriangleMesh keptTriangles(TriangleMesh welded, const std::vector<char>& keep) {
    if (keep.empty()) return welded;
    std::vector<std::array<std::uint32_t, 3>> kept;
    kept.reserve(welded.triangles.size());
    for (std::size_t n = 0; n < welded.triangles.size(); ++n)
        if (keep[n]) kept.push_back(welded.triangles[n]);
    welded.triangles = std::move(kept);
    return welded;
}

TriangleMesh withoutRepeatedTriangles(const TriangleMesh& mesh) {
    TriangleMesh welded = weldVertices(mesh);
    const std::vector<char> keep = trianglesToKeep(welded);
    return keptTriangles(std::move(welded), keep);
}

TriangleMesh orientedOutward(const TriangleMesh& mesh) { return orientedOutwardWelded(weldVertices(mesh)).mesh; }

OrientedMesh orientedOutwardWelded(TriangleMesh out) {
    OrientedMesh result;
    const std::size_t count = out.triangles.size();
    // Neighbours across edges used by exactly two triangles, at most one per edge, so at most 3
    // per triangle, in ascending edge order; `flip` says whether the two must differ in flipping
    // (they run along the edge in the same direction) to agree.
    // Each neighbour is other << 1 | flip; kNone ends a list. The same pass measures closedness.
    constexpr std::uint32_t kNone = ~std::uint32_t{0};
    std::vector<std::array<std::uint32_t, 3>> neighbours(count, {kNone, kNone, kNone});
    const auto add = [&](std::uint32_t t, std::uint32_t other, bool flip) {
        auto& list = neighbours[t];
        *std::find(list.begin(), list.end(), kNone) = other << 1 | std::uint32_t(flip);
    };
    MeshClosedness& closedness = result.closedness;
    forEachEdge(out, [&](const EdgeUse* uses, std::size_t n) {
        if (n % 2 == 1) ++closedness.boundaryEdges;
        if (n > 2) ++closedness.nonManifoldEdges;
        if (n != 2 || uses[0].triangle() == uses[1].triangle()) return;
        const bool flip = uses[0].forward() == uses[1].forward();
        if (flip) ++closedness.inconsistentEdges;
        add(uses[0].triangle(), uses[1].triangle(), flip);
        add(uses[1].triangle(), uses[0].triangle(), flip);
    });
    closedness.closed = closedness.boundaryEdges == 0;
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
            for (const std::uint32_t entry : neighbours[t]) {
                if (entry == kNone) break;
                const std::uint32_t other = entry >> 1;
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
    for (std::size_t t = 0; t < count; ++t)
        for (const std::uint32_t entry : neighbours[t])
            if (entry != kNone && (entry >> 1) > t && ((entry & 1u) ^ std::uint32_t(flipped[t] != flipped[entry >> 1])))
                ++result.inconsistentAfter;
    for (std::size_t t = 0; t < count; ++t)
        if (flipped[t]) std::swap(out.triangles[t][1], out.triangles[t][2]);
    result.mesh = std::move(out);
    return result;
}

double signedVolume(const TriangleMesh& mesh) {
    if (mesh.triangles.empty()) return 0.0;
    const MeshBounds bounds = boundsOf(mesh);
    const double cx = 0.5 * (bounds.min[0] + bounds.max[0]);
    const double cy = 0.5 * (bounds.min[1] + bounds.max[1]);
    const double cz = 0.5 * (bounds.min[2] + bounds.max[2]);
    double sixTimesVolume = 0.0;
    for (const auto& t : mesh.triangles) {
        const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
        const double ax = a.x - cx, ay = a.y - cy, az = a.z - cz;
        const double bx = b.x - cx, by = b.y - cy, bz = b.z - cz;
        const double qx = c.x - cx, qy = c.y - cy, qz = c.z - cz;
        sixTimesVolume += ax * (by * qz - bz * qy) - ay * (bx * qz - bz * qx) + az * (bx * qy - by * qx);
    }
    return sixTimesVolume / 6.0;
}

} // namespace sandcore
