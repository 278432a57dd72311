// SPDX-License-Identifier: MIT
#include "sandcore/mesh_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace sandcore {

namespace {

using Index = std::uint32_t;

Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 operator*(float s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec3 normalized(Vec3 a) {
    const float length = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    return length > 0 ? (1.0f / length) * a : a;
}

// Two triangles for the quad a-b-c-d (counter-clockwise seen from the side it faces).
void addQuad(TriangleMesh& mesh, Index a, Index b, Index c, Index d) {
    mesh.triangles.push_back({a, b, c});
    mesh.triangles.push_back({a, c, d});
}

} // namespace

TriangleMesh makeBoxMesh(Vec3 min, Vec3 max) {
    TriangleMesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.vertices.push_back({(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z});
    addQuad(mesh, 0, 4, 6, 2); // -x
    addQuad(mesh, 1, 3, 7, 5); // +x
    addQuad(mesh, 0, 1, 5, 4); // -y
    addQuad(mesh, 2, 6, 7, 3); // +y
    addQuad(mesh, 0, 2, 3, 1); // -z
    addQuad(mesh, 4, 5, 7, 6); // +z
    return mesh;
}

TriangleMesh makeIcosphereMesh(int subdivisions, float radius) {
    if (subdivisions < 0 || subdivisions > 8) throw std::invalid_argument("icosphere subdivisions must lie in 0..8");
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    TriangleMesh mesh;
    mesh.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                     {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    mesh.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (Vec3& v : mesh.vertices) v = normalized(v);
    for (int level = 0; level < subdivisions; ++level) {
        std::map<std::pair<Index, Index>, Index> midpoints; // shared edges get one midpoint
        auto midpoint = [&](Index a, Index b) {
            const auto key = std::minmax(a, b);
            const auto [it, isNew] = midpoints.try_emplace(key, Index(mesh.vertices.size()));
            if (isNew) mesh.vertices.push_back(normalized(mesh.vertices[a] + mesh.vertices[b]));
            return it->second;
        };
        std::vector<std::array<Index, 3>> finer;
        finer.reserve(mesh.triangles.size() * 4);
        for (const auto& tri : mesh.triangles) {
            const Index ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]), ca = midpoint(tri[2], tri[0]);
            finer.push_back({tri[0], ab, ca});
            finer.push_back({tri[1], bc, ab});
            finer.push_back({tri[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        mesh.triangles = std::move(finer);
    }
    for (Vec3& v : mesh.vertices) v = radius * v;
    return mesh;
}

TriangleMesh makeTorusMesh(float major, float minor, int rings, int sides) {
    if (rings < 3 || sides < 3 || !(minor > 0 && minor < major))
        throw std::invalid_argument("torus needs rings, sides >= 3 and 0 < minor < major");
    TriangleMesh mesh;
    const double tau = 2.0 * std::numbers::pi;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < sides; ++j) {
            const double u = tau * i / rings, v = tau * j / sides;
            const double r = major + minor * std::cos(v);
            mesh.vertices.push_back({float(r * std::cos(u)), float(minor * std::sin(v)), float(r * std::sin(u))});
        }
    auto at = [&](int i, int j) { return Index((i % rings) * sides + (j % sides)); };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < sides; ++j) addQuad(mesh, at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
    return mesh;
}

TriangleMesh makeLatheMesh(const std::vector<ProfilePoint>& profile, int segments) {
    if (profile.size() < 3 || segments < 3) throw std::invalid_argument("a lathe needs 3 profile points and 3 segments");
    TriangleMesh mesh;
    const double tau = 2.0 * std::numbers::pi;
    std::vector<Index> ringStart; // first vertex of each profile point's ring (a pole has one vertex)
    for (const ProfilePoint& p : profile) {
        ringStart.push_back(Index(mesh.vertices.size()));
        if (p.radius <= 0.0f) {
            mesh.vertices.push_back({0.0f, p.y, 0.0f});
            continue;
        }
        for (int s = 0; s < segments; ++s) {
            const double angle = tau * s / segments;
            mesh.vertices.push_back({float(p.radius * std::cos(angle)), p.y, float(-p.radius * std::sin(angle))});
        }
    }
    auto vertex = [&](std::size_t ring, int s) {
        return profile[ring].radius <= 0.0f ? ringStart[ring] : ringStart[ring] + Index(s % segments);
    };
    for (std::size_t ring = 0; ring + 1 < profile.size(); ++ring)
        for (int s = 0; s < segments; ++s) {
            const Index a = vertex(ring, s), b = vertex(ring, s + 1);
            const Index c = vertex(ring + 1, s + 1), d = vertex(ring + 1, s);
            // Rings wind counter-clockwise seen from above; going up the profile the quad faces outward.
            if (a != b) mesh.triangles.push_back({a, b, c});
            if (c != d) mesh.triangles.push_back({a, c, d});
        }
    return mesh;
}

TriangleMesh makeTubeMesh(const std::vector<Vec3>& loop, float radius, int sides) {
    const int count = int(loop.size());
    if (count < 3 || sides < 3 || !(radius > 0)) throw std::invalid_argument("a tube needs 3 points, 3 sides and a radius");
    TriangleMesh mesh;
    const double tau = 2.0 * std::numbers::pi;
    // A frame per point from the tangent and a fixed helper axis; fine for curves that never run along it.
    Vec3 helper{0.3f, 1.0f, 0.2f};
    for (int i = 0; i < count; ++i) {
        const Vec3 tangent = normalized(loop[std::size_t((i + 1) % count)] - loop[std::size_t((i + count - 1) % count)]);
        const Vec3 side = normalized(cross(tangent, helper));
        const Vec3 up = cross(side, tangent);
        for (int j = 0; j < sides; ++j) {
            const double angle = tau * j / sides;
            const Vec3 offset = float(std::cos(angle)) * side + float(std::sin(angle)) * up;
            mesh.vertices.push_back(loop[std::size_t(i)] + radius * offset);
        }
    }
    auto at = [&](int i, int j) { return Index((i % count) * sides + (j % sides)); };
    for (int i = 0; i < count; ++i)
        for (int j = 0; j < sides; ++j) addQuad(mesh, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    return mesh;
}

} // namespace sandcore
