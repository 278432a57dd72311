// SPDX-License-Identifier: MIT
// The outward orientation of a walked mesh (mesh_preparation.hpp): which faces to turn over so
// that neighbours agree and every part encloses a positive volume, and that volume.
#include "mesh_preparation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace sandcore {

namespace {

template <class T> using BigVector = LargePageVector<T>;
using Triangle = MeshTriangle;

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
                if (entry == kNoNeighbour) continue;
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
            if (entry != kNoNeighbour && (entry >> 1) > t && ((entry & 1u) ^ std::uint32_t(flipped[t] != flipped[entry >> 1])))
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
            if (entry == kNoNeighbour || (entry >> 1) < t) continue;
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

double signedVolumeAbout(std::span<const Vec3> vertices, std::span<const MeshTriangle> triangles,
                         std::span<const std::uint8_t> flipped, const MeshBounds& bounds) {
    if (triangles.empty()) return 0.0;
    const double cx = 0.5 * (bounds.min[0] + bounds.max[0]), cy = 0.5 * (bounds.min[1] + bounds.max[1]),
                 cz = 0.5 * (bounds.min[2] + bounds.max[2]);
    double sixTimesVolume = 0.0;
    for (std::size_t n = 0; n < triangles.size(); ++n) {
        const Triangle& t = triangles[n];
        const bool turned = !flipped.empty() && flipped[n];
        const Vec3 a = vertices[t[0]], b = vertices[t[turned ? 2 : 1]], c = vertices[t[turned ? 1 : 2]];
        const double ax = a.x - cx, ay = a.y - cy, az = a.z - cz;
        const double bx = b.x - cx, by = b.y - cy, bz = b.z - cz;
        const double qx = c.x - cx, qy = c.y - cy, qz = c.z - cz;
        sixTimesVolume += ax * (by * qz - bz * qy) - ay * (bx * qz - bz * qx) + az * (bx * qy - by * qx);
    }
    return sixTimesVolume / 6.0;
}

double signedVolumeOf(const WalkedMesh& walked, const LargePageVector<std::uint8_t>& flipped, const MeshBounds& bounds) {
    return signedVolumeAbout(walked.vertices, walked.triangles, flipped, bounds);
}

} // namespace sandcore
