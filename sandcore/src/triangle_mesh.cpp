#include "sandcore/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <bit>
#include <limits>
#include <stdexcept>
#include <unordered_map>

namespace sandcore {

void TriangleMesh::append(const TriangleMesh& other) {
    const auto base = std::uint32_t(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    for (const auto& t : other.triangles) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

MeshBounds boundsOf(const TriangleMesh& mesh) {
    if (mesh.triangles.empty()) throw std::invalid_argument("the mesh has no triangles");
    MeshBounds bounds;
    bounds.min.fill(std::numeric_limits<double>::infinity());
    bounds.max.fill(-std::numeric_limits<double>::infinity());
    for (const auto& t : mesh.triangles)
        for (std::uint32_t i : t) {
            if (i >= mesh.vertices.size()) throw std::invalid_argument("a triangle refers to a missing vertex");
            const Vec3 v = mesh.vertices[i];
            const double c[3] = {v.x, v.y, v.z};
            if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
                throw std::invalid_argument("the model has a non-finite coordinate (NaN or infinity)");
            for (std::size_t a = 0; a < 3; ++a) {
                bounds.min[a] = std::min(bounds.min[a], c[a]);
                bounds.max[a] = std::max(bounds.max[a], c[a]);
            }
        }
    return bounds;
}

namespace {

struct PositionKey {
    std::uint32_t x, y, z;
    friend bool operator==(const PositionKey&, const PositionKey&) = default;
};

struct PositionHash {
    std::size_t operator()(const PositionKey& k) const {
        std::uint64_t h = k.x;
        h = h * 0x9E3779B97F4A7C15ull ^ k.y;
        h = h * 0x9E3779B97F4A7C15ull ^ k.z;
        return std::size_t(h ^ (h >> 29));
    }
};

// -0.0 and +0.0 are the same position; everything else is compared bit for bit.
std::uint32_t bitsOf(float value) { return std::bit_cast<std::uint32_t>(value == 0.0f ? 0.0f : value); }

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    return a < b ? (std::uint64_t(a) << 32 | b) : (std::uint64_t(b) << 32 | a);
}

} // namespace

TriangleMesh weldVertices(const TriangleMesh& mesh) {
    TriangleMesh welded;
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> firstAt;
    firstAt.reserve(mesh.vertices.size());
    std::vector<std::uint32_t> remap(mesh.vertices.size());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Vec3 v = mesh.vertices[i];
        const auto [it, isNew] =
            firstAt.try_emplace({bitsOf(v.x), bitsOf(v.y), bitsOf(v.z)}, std::uint32_t(welded.vertices.size()));
        if (isNew) welded.vertices.push_back(v);
        remap[i] = it->second;
    }
    welded.triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        if (t[0] >= remap.size() || t[1] >= remap.size() || t[2] >= remap.size())
            throw std::invalid_argument("a triangle refers to a missing vertex");
        welded.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
    }
    return welded;
}

MeshClosedness closednessOf(const TriangleMesh& mesh) {
    const TriangleMesh welded = weldVertices(mesh);
    std::vector<std::uint64_t> edges;
    edges.reserve(welded.triangles.size() * 3);
    for (const auto& t : welded.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
        edges.push_back(edgeKey(t[0], t[1]));
        edges.push_back(edgeKey(t[1], t[2]));
        edges.push_back(edgeKey(t[2], t[0]));
    }
    // Sorting groups the uses of each edge; cheaper and more compact than a hash map of counts.
    std::sort(edges.begin(), edges.end());
    MeshClosedness result;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        const std::size_t uses = j - i;
        if (uses % 2 == 1) ++result.boundaryEdges;
        if (uses > 2) ++result.nonManifoldEdges;
        i = j;
    }
    result.closed = result.boundaryEdges == 0;
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
