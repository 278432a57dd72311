// SPDX-License-Identifier: MIT
#include "sandcore/mesh_shells.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <unordered_set>

namespace sandcore {

namespace {

// Union-find over vertices: a shell is a set of vertices joined by triangle edges.
struct VertexSets {
    std::vector<std::uint32_t> parent;
    explicit VertexSets(std::size_t count) : parent(count) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t root(std::uint32_t v) {
        while (parent[v] != v) {
            parent[v] = parent[parent[v]]; // path halving keeps the trees flat
            v = parent[v];
        }
        return v;
    }
    void join(std::uint32_t a, std::uint32_t b) {
        a = root(a);
        b = root(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

} // namespace

std::vector<TriangleMesh> splitIntoShells(const TriangleMesh& mesh) {
    VertexSets sets(mesh.vertices.size());
    for (const auto& t : mesh.triangles) {
        sets.join(t[0], t[1]);
        sets.join(t[1], t[2]);
    }
    std::vector<std::uint32_t> shellOfRoot(mesh.vertices.size(), UINT32_MAX);
    std::vector<std::uint32_t> localIndex(mesh.vertices.size(), UINT32_MAX);
    std::vector<TriangleMesh> shells;
    for (const auto& t : mesh.triangles) {
        const std::uint32_t root = sets.root(t[0]);
        if (shellOfRoot[root] == UINT32_MAX) {
            shellOfRoot[root] = std::uint32_t(shells.size());
            shells.emplace_back();
        }
        TriangleMesh& shell = shells[shellOfRoot[root]];
        std::array<std::uint32_t, 3> local{};
        for (std::size_t c = 0; c < 3; ++c) {
            std::uint32_t& index = localIndex[t[c]];
            if (index == UINT32_MAX) {
                index = std::uint32_t(shell.vertices.size());
                shell.vertices.push_back(mesh.vertices[t[c]]);
            }
            local[c] = index;
        }
        shell.triangles.push_back(local);
    }
    return shells;
}

TriangleMesh withoutDoubledFaces(const TriangleMesh& mesh) {
    struct SortedHash {
        std::size_t operator()(const std::array<std::uint32_t, 3>& t) const {
            return (std::size_t(t[0]) * 73856093u) ^ (std::size_t(t[1]) * 19349663u) ^ (std::size_t(t[2]) * 83492791u);
        }
    };
    std::unordered_set<std::array<std::uint32_t, 3>, SortedHash> seen;
    seen.reserve(mesh.triangles.size());
    TriangleMesh out;
    out.vertices = mesh.vertices;
    for (const auto& t : mesh.triangles) {
        std::array<std::uint32_t, 3> key = t;
        std::sort(key.begin(), key.end());
        if (seen.insert(key).second) out.triangles.push_back(t);
    }
    return out;
}

} // namespace sandcore
