// SPDX-License-Identifier: MIT
#include "canonical_parts.hpp"

#include "sandcore/mesh_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace sandglass::wild {

namespace {

using sandcore::Vec3;
constexpr double kPi = std::numbers::pi;

Point minus(Point a, Point b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point cross(Point a, Point b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double length(Point a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
Point scaled(Point a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

} // namespace

TriangleMesh lathe(const std::vector<ProfileSample>& radiusAtY, int segments) {
    std::vector<sandcore::ProfilePoint> profile;
    for (const ProfileSample& s : radiusAtY) profile.push_back({float(std::max(0.0, s.radius)), float(s.height)});
    // makeLatheMesh wants three points; a straight open sleeve gets a ring halfway.
    if (profile.size() == 2)
        profile.insert(profile.begin() + 1, {0.5f * (profile[0].radius + profile[1].radius), 0.5f * (profile[0].y + profile[1].y)});
    return sandcore::makeLatheMesh(profile, segments);
}

TriangleMesh closedLathe(std::vector<ProfileSample> radiusAtY, int segments) {
    if (radiusAtY.front().radius > 0) radiusAtY.insert(radiusAtY.begin(), {radiusAtY.front().height, 0.0});
    if (radiusAtY.back().radius > 0) radiusAtY.push_back({radiusAtY.back().height, 0.0});
    return lathe(radiusAtY, segments);
}

TriangleMesh revolveLoop(const std::vector<ProfileSample>& loop, int segments) {
    TriangleMesh mesh;
    const auto n = std::uint32_t(loop.size());
    for (int s = 0; s < segments; ++s) {
        const double angle = 2.0 * kPi * s / segments;
        for (const ProfileSample& p : loop)
            mesh.vertices.push_back({float(p.radius * std::cos(angle)), float(p.height), float(-p.radius * std::sin(angle))});
    }
    for (std::uint32_t s = 0; s < std::uint32_t(segments); ++s) {
        const std::uint32_t t = (s + 1) % std::uint32_t(segments);
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t j = (i + 1) % n;
            const std::uint32_t a = s * n + i, b = t * n + i, c = t * n + j, d = s * n + j;
            // As makeLatheMesh: going up the outside, the quad faces away from the axis.
            mesh.triangles.push_back({a, b, c});
            mesh.triangles.push_back({a, c, d});
        }
    }
    return mesh;
}

TriangleMesh cylinderMesh(double radius, double y0, double y1, double x, double z, int segments) {
    TriangleMesh mesh = closedLathe({{y0, radius}, {y1, radius}}, segments);
    for (Vec3& v : mesh.vertices) v = {v.x + float(x), v.y, v.z + float(z)};
    return mesh;
}

TriangleMesh boxMesh(Point min, Point max) {
    return sandcore::makeBoxMesh({float(min[0]), float(min[1]), float(min[2])}, {float(max[0]), float(max[1]), float(max[2])});
}

TriangleMesh ellipsoidMesh(const Ellipsoid& solid, int rings, int segments, bool cutTop, bool cutBottom) {
    std::vector<ProfileSample> profile;
    for (int i = cutBottom ? 2 : 0; i <= (cutTop ? rings - 2 : rings); ++i) {
        const double polar = kPi * (1.0 - double(i) / rings); // from the south pole up
        profile.push_back({std::cos(polar), i == 0 || i == rings ? 0.0 : std::sin(polar)});
    }
    TriangleMesh mesh = lathe(profile, segments);
    for (Vec3& v : mesh.vertices)
        v = {float(solid.centre[0] + solid.radii[0] * v.x), float(solid.centre[1] + solid.radii[1] * v.y),
             float(solid.centre[2] + solid.radii[2] * v.z)};
    return mesh;
}

TriangleMesh capsuleMesh(const Capsule& solid, int rings, int segments) {
    const Point axis = minus(solid.b, solid.a);
    const double span = length(axis);
    // Built along y from a (y = 0) to b (y = span), then turned onto the segment by a proper rotation.
    std::vector<ProfileSample> profile;
    const int cap = std::max(2, rings / 2);
    if (solid.roundA)
        for (int i = 0; i < cap; ++i) {
            const double polar = 0.5 * kPi * double(i) / cap;
            profile.push_back({-solid.radius * std::cos(polar), i == 0 ? 0.0 : solid.radius * std::sin(polar)});
        }
    profile.push_back({0.0, solid.radius});
    profile.push_back({span, solid.radius});
    if (solid.roundB)
        for (int i = 1; i <= cap; ++i) {
            const double polar = 0.5 * kPi * double(i) / cap;
            profile.push_back({span + solid.radius * std::sin(polar), i == cap ? 0.0 : solid.radius * std::cos(polar)});
        }
    TriangleMesh mesh = lathe(profile, segments);
    const Point up = scaled(axis, 1.0 / span);
    const Point helper = std::abs(up[0]) < 0.9 ? Point{1, 0, 0} : Point{0, 0, 1};
    Point side = cross(up, helper);
    side = scaled(side, 1.0 / length(side));
    const Point front = cross(side, up); // (side, up, front) is right-handed like (x, y, z)
    for (Vec3& v : mesh.vertices) {
        Point p;
        for (int k = 0; k < 3; ++k) p[std::size_t(k)] = solid.a[std::size_t(k)] + side[std::size_t(k)] * v.x + up[std::size_t(k)] * v.y + front[std::size_t(k)] * v.z;
        v = {float(p[0]), float(p[1]), float(p[2])};
    }
    return mesh;
}

TriangleMesh reversed(TriangleMesh mesh) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    return mesh;
}

std::int64_t removeFaces(TriangleMesh& mesh, const std::function<bool(Point)>& cut) {
    const std::size_t before = mesh.triangles.size();
    std::erase_if(mesh.triangles, [&](const std::array<std::uint32_t, 3>& t) {
        Point centroid{};
        for (std::uint32_t index : t) {
            const Vec3 v = mesh.vertices[index];
            centroid = {centroid[0] + v.x / 3.0, centroid[1] + v.y / 3.0, centroid[2] + v.z / 3.0};
        }
        return cut(centroid);
    });
    return std::int64_t(before - mesh.triangles.size());
}

void damageParts(Rng& rng, std::vector<Part>& parts, Damage& damage) {
    // Whether a file has a kind of damage is decided once; which of its objects carry it, per object.
    const bool flip = chance(rng, 0.35), duplicate = chance(rng, 0.25), unweld = chance(rng, 0.15);
    const double flipShare = uniform(rng, 0.02, 0.25), duplicateShare = uniform(rng, 0.01, 0.08);
    for (Part& part : parts) {
        TriangleMesh& mesh = part.mesh;
        if (flip && chance(rng, 0.7))
            for (auto& t : mesh.triangles)
                if (chance(rng, flipShare)) {
                    std::swap(t[1], t[2]);
                    ++damage.flippedFaces;
                }
        if (duplicate && chance(rng, 0.7)) {
            const std::size_t count = mesh.triangles.size();
            for (std::size_t i = 0; i < count; ++i)
                if (chance(rng, duplicateShare)) {
                    auto copy = mesh.triangles[i];
                    if (chance(rng, 0.5)) std::swap(copy[1], copy[2]);
                    mesh.triangles.push_back(copy);
                    ++damage.duplicatedFaces;
                }
        }
        // STL exporters and some OBJ ones write every triangle with its own corners.
        if (unweld && chance(rng, 0.7)) {
            TriangleMesh soup;
            for (const auto& t : mesh.triangles) {
                const auto base = std::uint32_t(soup.vertices.size());
                for (std::uint32_t index : t) soup.vertices.push_back(mesh.vertices[index]);
                soup.triangles.push_back({base, base + 1, base + 2});
            }
            mesh = std::move(soup);
            damage.unwelded = true;
        }
    }
}

} // namespace sandglass::wild
