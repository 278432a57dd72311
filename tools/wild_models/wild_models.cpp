// SPDX-License-Identifier: MIT
// generate(): a class's canonical model, damaged, turned to its up axis, scaled and moved; and
// the ground truth queries, which undo that.
#include "wild_models/wild_models.hpp"

#include "class_builders.hpp"
#include "glass_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <stdexcept>

namespace sandglass::wild {

namespace {

using Rotation = std::array<std::array<int, 3>, 3>;

// model = rotation * canonical: a quarter turn taking canonical +y onto the up axis.
Rotation rotationFor(int upAxis) {
    switch (upAxis) {
    case 0: return {{{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}};  // +x: a quarter turn about z
    case 1: return {{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};  // -x
    case 3: return {{{1, 0, 0}, {0, -1, 0}, {0, 0, -1}}}; // -y: a half turn about x
    case 4: return {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}};  // +z: a quarter turn about x
    case 5: return {{{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}};  // -z
    default: return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    }
}

CanonicalModel buildCanonical(ModelClass modelClass, Rng& rng) {
    switch (modelClass) {
    case ModelClass::ThickFramed: return buildThickFramed(rng);
    case ModelClass::SingleWall: return buildSingleWall(rng);
    case ModelClass::OpenBulbsPlates: return buildOpenBulbsPlates(rng);
    case ModelClass::OneObjectAsset: return buildOneObjectAsset(rng);
    case ModelClass::ConesRingsPost: return buildConesRingsPost(rng);
    case ModelClass::Funnel: return buildFunnel(rng);
    case ModelClass::Character: return buildCharacter(rng);
    case ModelClass::Keyboard: return buildKeyboard(rng);
    }
    throw std::invalid_argument("unknown model class");
}

int randomUpAxis(ModelClass modelClass, Rng& rng) {
    switch (modelClass) {
    case ModelClass::Funnel: return chance(rng, 0.7) ? 4 : uniformInt(rng, 0, 5); // Rhino and CAD models are mostly Z up
    case ModelClass::Character: return chance(rng, 0.5) ? 2 : 4;
    default: return uniformInt(rng, 0, 5);
    }
}

double capsuleDistance(const Capsule& capsule, Point c) {
    Point axis{}, rel{};
    double span = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
        axis[k] = capsule.b[k] - capsule.a[k];
        rel[k] = c[k] - capsule.a[k];
        span += axis[k] * axis[k];
    }
    span = std::sqrt(span);
    const double along = (rel[0] * axis[0] + rel[1] * axis[1] + rel[2] * axis[2]) / span;
    auto distanceTo = [&](const Point& q) { return std::hypot(c[0] - q[0], c[1] - q[1], c[2] - q[2]); };
    if (along < 0.0 && capsule.roundA) return distanceTo(capsule.a) - capsule.radius;
    if (along > span && capsule.roundB) return distanceTo(capsule.b) - capsule.radius;
    const double radial = std::sqrt(std::max(0.0, rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2] - along * along));
    const double outward = std::max(0.0, radial - capsule.radius), beyond = std::max({0.0, -along, along - span});
    if (outward == 0.0 && beyond == 0.0) return radial - capsule.radius;
    return std::hypot(outward, beyond);
}

} // namespace

const char* className(ModelClass modelClass) {
    switch (modelClass) {
    case ModelClass::ThickFramed: return "thick-framed";
    case ModelClass::SingleWall: return "single-wall";
    case ModelClass::OpenBulbsPlates: return "open-bulbs-plates";
    case ModelClass::OneObjectAsset: return "one-object-asset";
    case ModelClass::ConesRingsPost: return "cones-rings-post";
    case ModelClass::Funnel: return "funnel";
    case ModelClass::Character: return "character";
    case ModelClass::Keyboard: return "keyboard";
    }
    return "unknown";
}

WildModel generate(ModelClass modelClass, std::uint64_t seed) {
    // One stream per class and seed, so a class's models do not change when another class's do.
    Rng rng(seed * 0x9E3779B97F4A7C15ull + std::uint64_t(modelClass) + 1);
    CanonicalModel canonical = buildCanonical(modelClass, rng);
    WildModel model;
    model.modelClass = modelClass;
    model.seed = seed;
    model.truth = canonical.truth;
    model.damage.removedFaces = canonical.removedFaces;
    damageParts(rng, canonical.parts, model.damage);
    model.upAxis = randomUpAxis(modelClass, rng);
    model.rotation = rotationFor(model.upAxis);
    model.unitScale = logUniform(rng, 1e-3, 1e3);
    if (chance(rng, 0.5))
        for (double& o : model.offset) o = uniform(rng, -2.0, 2.0) * model.unitScale;
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (Part& part : canonical.parts) {
        for (sandcore::Vec3& v : part.mesh.vertices) {
            low = std::min(low, double(v.y));
            high = std::max(high, double(v.y));
            const Point p = model.modelOf({v.x, v.y, v.z});
            v = {float(p[0]), float(p[1]), float(p[2])};
        }
        model.objects.push_back({std::move(part.name), std::move(part.mesh)});
    }
    model.height = high - low;
    return model;
}

Point WildModel::modelOf(Point canonical) const {
    Point p{};
    for (std::size_t r = 0; r < 3; ++r) {
        double sum = 0.0;
        for (std::size_t k = 0; k < 3; ++k) sum += rotation[r][k] * canonical[k];
        p[r] = sum * unitScale + offset[r];
    }
    return p;
}

Point WildModel::canonicalOf(Point p) const {
    Point c{};
    for (std::size_t k = 0; k < 3; ++k) {
        double sum = 0.0;
        for (std::size_t r = 0; r < 3; ++r) sum += rotation[r][k] * (p[r] - offset[r]); // the transpose undoes the turn
        c[k] = sum / unitScale;
    }
    return c;
}

bool WildModel::insideGlass(sandcore::Vec3 p, double tolerance) const {
    const Point c = canonicalOf({p.x, p.y, p.z});
    const double band = tolerance / unitScale;
    if (!truth.profile.empty()) {
        const double h = c[1] - truth.bottom, d = std::hypot(c[0], c[2]);
        if (distanceToProfile(truth.profile, h, d) <= band) return true;
        const ProfileSample &bottom = truth.profile.front(), &top = truth.profile.back();
        const bool underOpening = h < 0 && h >= -truth.openBelow - band && d <= bottom.radius + band;
        const bool overOpening = h > top.height && h <= top.height + truth.openAbove + band && d <= top.radius + band;
        return underOpening || overOpening;
    }
    for (const Ellipsoid& e : truth.ellipsoids) {
        double sum = 0.0;
        for (std::size_t k = 0; k < 3; ++k) sum += std::pow((c[k] - e.centre[k]) / e.radii[k], 2);
        // The normalised radius changes by at most 1 / (smallest radius) per unit of distance.
        if (std::sqrt(sum) <= 1.0 + band / std::min({e.radii[0], e.radii[1], e.radii[2]})) return true;
    }
    for (const Capsule& capsule : truth.capsules)
        if (capsuleDistance(capsule, c) <= band) return true;
    for (const Box& box : truth.boxes) {
        double sum = 0.0;
        for (std::size_t k = 0; k < 3; ++k) sum += std::pow(std::max({0.0, box.min[k] - c[k], c[k] - box.max[k]}), 2);
        if (std::sqrt(sum) <= band) return true;
    }
    return false;
}

bool WildModel::inUpperBulb(sandcore::Vec3 p) const {
    if (!insideGlass(p, 0.0)) return false;
    return truth.neckHeight < 0 || axisPositionOf({p.x, p.y, p.z}).height > neckHeight();
}

bool WildModel::inLowerBulb(sandcore::Vec3 p) const {
    return truth.neckHeight >= 0 && insideGlass(p, 0.0) && axisPositionOf({p.x, p.y, p.z}).height < neckHeight();
}

double WildModel::upperBulbVolume() const {
    if (truth.profile.empty()) return 0.0;
    const double from = truth.neckHeight < 0 ? 0.0 : truth.neckHeight;
    return volumeBetween(truth.profile, from, truth.profile.back().height) * unitScale * unitScale * unitScale;
}

double WildModel::neckRadius() const {
    if (truth.profile.empty()) return 0.0;
    return (truth.neckHeight < 0 ? truth.profile.front().radius : radiusAt(truth.profile, truth.neckHeight)) * unitScale;
}

Point WildModel::axisBottom() const { return modelOf({0.0, truth.bottom, 0.0}); }

Point WildModel::upDirection() const { return {double(rotation[0][1]), double(rotation[1][1]), double(rotation[2][1])}; }

AxisPosition WildModel::axisPositionOf(Point p) const {
    const Point c = canonicalOf(p);
    return {(c[1] - truth.bottom) * unitScale, std::hypot(c[0], c[2]) * unitScale};
}

Point WildModel::modelPointAt(double height, double distance, double angle) const {
    const double d = distance / unitScale;
    return modelOf({d * std::cos(angle), truth.bottom + height / unitScale, d * std::sin(angle)});
}

double WildModel::innerHeight() const { return truth.profile.empty() ? 0.0 : truth.profile.back().height * unitScale; }

double WildModel::neckHeight() const { return truth.neckHeight < 0 ? -1.0 : truth.neckHeight * unitScale; }

double WildModel::innerRadiusAt(double height) const {
    const double r = radiusAt(truth.profile, height / unitScale);
    return r < 0 ? -1.0 : r * unitScale;
}

double WildModel::smallestPartExtent() const {
    double smallest = std::numeric_limits<double>::infinity();
    for (const Object& object : objects) {
        const sandcore::MeshBounds bounds = sandcore::boundsOf(object.mesh);
        for (int axis = 0; axis < 3; ++axis) smallest = std::min(smallest, bounds.extent(axis));
    }
    return smallest;
}

double WildModel::largestExtent() const {
    sandcore::TriangleMesh all;
    for (const Object& object : objects) all.append(object.mesh);
    const sandcore::MeshBounds bounds = sandcore::boundsOf(all);
    return std::max({bounds.extent(0), bounds.extent(1), bounds.extent(2)});
}

std::size_t WildModel::triangleCount() const {
    std::size_t count = 0;
    for (const Object& object : objects) count += object.mesh.triangles.size();
    return count;
}

sandcore::TriangleMesh subdivided(const sandcore::TriangleMesh& mesh, int times) {
    sandcore::TriangleMesh out = mesh;
    for (int round = 0; round < times; ++round) {
        sandcore::TriangleMesh finer;
        finer.vertices = out.vertices;
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto [it, added] = midpoints.try_emplace({std::min(a, b), std::max(a, b)}, std::uint32_t(finer.vertices.size()));
            if (added) {
                const sandcore::Vec3 p = out.vertices[a], q = out.vertices[b];
                finer.vertices.push_back({0.5f * (p.x + q.x), 0.5f * (p.y + q.y), 0.5f * (p.z + q.z)});
            }
            return it->second;
        };
        for (const auto& [a, b, c] : out.triangles) {
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.triangles.push_back({a, ab, ca});
            finer.triangles.push_back({ab, b, bc});
            finer.triangles.push_back({ca, bc, c});
            finer.triangles.push_back({ab, bc, ca});
        }
        out = std::move(finer);
    }
    return out;
}

} // namespace sandglass::wild
