// SPDX-License-Identifier: MIT
// Hourglasses of the three framed kinds: thick glass in a frame, a single wall, open bulbs
// closed by stacked plates.
#include "class_builders.hpp"
#include "glass_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace sandglass::wild {

std::string pick(Rng& rng, std::initializer_list<const char*> names) {
    return *(names.begin() + uniformInt(rng, 0, int(names.size()) - 1));
}

std::vector<ProfileSample> raised(std::vector<ProfileSample> profile, double bottom) {
    for (ProfileSample& s : profile) s.height += bottom;
    return profile;
}

double widest(const std::vector<ProfileSample>& profile) {
    double radius = 0.0;
    for (const ProfileSample& s : profile) radius = std::max(radius, s.radius);
    return radius;
}

Part merged(const std::vector<Part>& parts, std::string name) {
    Part all{std::move(name), {}};
    for (const Part& part : parts) all.mesh.append(part.mesh);
    return all;
}

std::vector<Part> randomFrame(Rng& rng, const FrameRequest& request) {
    const int segments = randomSegments(rng);
    const bool boxes = chance(rng, 0.4);
    const int postCount = uniformInt(rng, 3, 4);
    const double postRadius = uniform(rng, 0.012, 0.03);
    const double postRing = request.clearRadius + postRadius + uniform(rng, 0.01, 0.04);
    const double half = postRing + postRadius + uniform(rng, 0.01, 0.05);
    const double overlap = request.postsInside ? uniform(rng, 0.002, 0.6 * request.plate) : 0.0;
    std::vector<Part> parts;
    auto plate = [&](double y0, double y1) {
        return boxes ? boxMesh({-half, y0, -half}, {half, y1, half}) : cylinderMesh(half, y0, y1, 0.0, 0.0, segments);
    };
    const bool blenderNames = chance(rng, 0.5);
    parts.push_back({blenderNames ? "Plate_bottom" : "BottomPlate", plate(0.0, request.plate)});
    parts.push_back({blenderNames ? "Plate_top" : "TopPlate", plate(request.height - request.plate, request.height)});
    if (request.posts) {
        const int postSegments = uniformInt(rng, 6, 16);
        const double turn = uniform(rng, 0.0, 1.0);
        for (int i = 0; i < postCount; ++i) {
            const double angle = 2.0 * std::numbers::pi * (i + turn) / postCount;
            const double x = postRing * std::cos(angle), z = postRing * std::sin(angle);
            const double y0 = request.plate - overlap, y1 = request.height - request.plate + overlap;
            TriangleMesh post = boxes && chance(rng, 0.7) ? boxMesh({x - postRadius, y0, z - postRadius}, {x + postRadius, y1, z + postRadius})
                                                          : cylinderMesh(postRadius, y0, y1, x, z, postSegments);
            char name[32];
            std::snprintf(name, sizeof name, blenderNames ? "Post.%03d" : "Pillar_%d", i + 1);
            parts.push_back({name, std::move(post)});
        }
    }
    if (chance(rng, 0.5)) return {merged(parts, pick(rng, {"Frame", "Wood", "Stand", "frame_wood"}))};
    return parts;
}

namespace {

// Rims overlap into the plate, touch it, or stop short of it by less than a cell at resolution 64.
double rimGap(Rng& rng) {
    switch (uniformInt(rng, 0, 2)) {
    case 0: return -uniform(rng, 0.0, 0.01);
    case 1: return 0.0;
    default: return uniform(rng, 0.0, 0.012);
    }
}

std::string glassName(Rng& rng) { return pick(rng, {"Glass", "glass", "Glass_Mesh", "Cylinder.002", "Sphere.001"}); }

// The glass and the frame as separate objects, or (as some exports have it) all in one.
std::vector<Part> withFrame(Rng& rng, Part glass, std::vector<Part> frame, double sameObject) {
    frame.insert(frame.begin(), std::move(glass));
    if (chance(rng, sameObject)) return {merged(frame, pick(rng, {"Hourglass", "hourglass", "Sandglass_001"}))};
    return frame;
}

} // namespace

CanonicalModel buildThickFramed(Rng& rng) {
    const int segments = randomSegments(rng);
    const double plate = uniform(rng, 0.03, 0.08), wall = uniform(rng, 0.004, 0.015);
    HourglassRequest request{.neckRadius = uniform(rng, 0.012, 0.04), .neckTube = uniform(rng, 0.005, 0.04)};
    CanonicalModel model;
    GroundTruth& truth = model.truth;
    Part glass{glassName(rng), {}};
    bool postsInside = false;
    if (chance(rng, 0.5)) {
        // One closed surface: a tube wall with rims, its open ends covered by the plates.
        const double gapBottom = rimGap(rng), gapTop = rimGap(rng);
        postsInside = gapBottom < 0;
        truth.bottom = plate + std::max(0.0, gapBottom);
        truth.openBelow = std::max(0.0, gapBottom);
        truth.openAbove = std::max(0.0, gapTop);
        request.innerHeight = 1.0 - plate - std::max(0.0, gapTop) - truth.bottom;
        truth.profile = hourglassProfile(rng, request, truth.neckHeight);
        const std::vector<ProfileSample> inner = raised(truth.profile, truth.bottom);
        std::vector<ProfileSample> loop;
        if (gapBottom < 0) loop.push_back({plate + gapBottom, inner.front().radius + wall});
        for (const ProfileSample& s : inner) loop.push_back({s.height, s.radius + wall});
        if (gapTop < 0) loop.push_back({1.0 - plate - gapTop, inner.back().radius + wall});
        if (gapTop < 0) loop.push_back({1.0 - plate - gapTop, inner.back().radius});
        for (auto s = inner.rbegin(); s != inner.rend(); ++s) loop.push_back(*s);
        if (gapBottom < 0) loop.push_back({plate + gapBottom, inner.front().radius});
        glass.mesh = revolveLoop(loop, segments);
    } else {
        // Two closed shells, the outer one and the inner one facing the cavity.
        request.closedEnds = chance(rng, 0.5);
        const double liftBottom = uniform(rng, 0.0, 0.01), liftTop = uniform(rng, 0.0, 0.01);
        truth.bottom = plate + liftBottom + wall;
        request.innerHeight = 1.0 - plate - liftTop - wall - truth.bottom;
        truth.profile = hourglassProfile(rng, request, truth.neckHeight);
        const std::vector<ProfileSample> inner = raised(truth.profile, truth.bottom);
        std::vector<ProfileSample> outer{{inner.front().height - wall, inner.front().radius + wall}};
        for (const ProfileSample& s : inner) outer.push_back({s.height, s.radius + wall});
        outer.push_back({inner.back().height + wall, inner.back().radius + wall});
        glass.mesh = closedLathe(outer, segments);
        TriangleMesh cavity = closedLathe(inner, segments);
        glass.mesh.append(chance(rng, 0.7) ? reversed(std::move(cavity)) : cavity);
    }
    const FrameRequest frame{.plate = plate, .clearRadius = widest(truth.profile) + wall, .posts = true, .postsInside = postsInside};
    model.parts = withFrame(rng, std::move(glass), randomFrame(rng, frame), 0.3);
    return model;
}

CanonicalModel buildSingleWall(Rng& rng) {
    const int segments = randomSegments(rng);
    const double plate = uniform(rng, 0.03, 0.07);
    const bool closed = chance(rng, 0.5), frame = chance(rng, 0.6);
    HourglassRequest request{.neckRadius = uniform(rng, 0.012, 0.04), .neckTube = uniform(rng, 0.005, 0.04)};
    CanonicalModel model;
    GroundTruth& truth = model.truth;
    Part glass{glassName(rng), {}};
    double top = 1.0;
    if (closed) {
        // A closed surface of revolution whose inside is the sand space.
        request.closedEnds = chance(rng, 0.5);
        truth.bottom = frame ? plate + uniform(rng, 0.0, 0.01) : 0.0;
        top = frame ? 1.0 - plate - uniform(rng, 0.0, 0.01) : 1.0;
    } else {
        // Open at both ends and covered by plates, with a gap under a cell.
        truth.bottom = plate + uniform(rng, 0.0, 0.012);
        top = 1.0 - plate - uniform(rng, 0.0, 0.012);
        truth.openBelow = truth.bottom - plate;
        truth.openAbove = 1.0 - plate - top;
    }
    request.innerHeight = top - truth.bottom;
    truth.profile = hourglassProfile(rng, request, truth.neckHeight);
    const std::vector<ProfileSample> inner = raised(truth.profile, truth.bottom);
    glass.mesh = closed ? closedLathe(inner, segments) : lathe(inner, segments);
    if (closed && !frame) {
        model.parts.push_back(std::move(glass));
        return model;
    }
    const FrameRequest frameRequest{.plate = plate, .clearRadius = widest(truth.profile), .posts = frame};
    model.parts = withFrame(rng, std::move(glass), randomFrame(rng, frameRequest), 0.2);
    return model;
}

CanonicalModel buildOpenBulbsPlates(Rng& rng) {
    const int segments = randomSegments(rng);
    const double plate = uniform(rng, 0.03, 0.06), cap = uniform(rng, 0.01, 0.03);
    const double neckGap = uniform(rng, 0.0, 0.006);
    CanonicalModel model;
    GroundTruth& truth = model.truth;
    truth.bottom = plate + cap + uniform(rng, 0.0, 0.012);
    const double top = 1.0 - plate - cap - uniform(rng, 0.0, 0.012);
    truth.openBelow = truth.bottom - (plate + cap);
    truth.openAbove = 1.0 - plate - cap - top;
    const HourglassRequest request{.innerHeight = top - truth.bottom, .neckRadius = uniform(rng, 0.012, 0.04),
                                   .neckTube = std::max(uniform(rng, 0.005, 0.03), neckGap + 0.004)};
    truth.profile = hourglassProfile(rng, request, truth.neckHeight);
    const double upperRim = truth.neckHeight + 0.5 * neckGap, lowerRim = truth.neckHeight - 0.5 * neckGap;
    const double innerHeight = truth.profile.back().height;
    // Each bulb is open at its plate and at the neck, where the two openings nearly meet.
    Part upper{pick(rng, {"Bulb_top", "UpperBulb", "Sphere.001"}),
               lathe(raised(profileBetween(truth.profile, upperRim, innerHeight), truth.bottom), segments)};
    Part lower{pick(rng, {"Bulb_bottom", "LowerBulb", "Sphere.002"}),
               lathe(raised(profileBetween(truth.profile, 0.0, lowerRim), truth.bottom), segments)};
    const double plateRadius = widest(truth.profile) * uniform(rng, 0.9, 1.3);
    const int plateSegments = randomSegments(rng);
    auto disc = [&](double radius, double y0, double y1) { return cylinderMesh(radius, y0, y1, 0.0, 0.0, plateSegments); };
    const double topCapRadius = std::min(plateRadius, truth.profile.back().radius * uniform(rng, 1.05, 1.3));
    const double bottomCapRadius = std::min(plateRadius, truth.profile.front().radius * uniform(rng, 1.05, 1.3));
    Part topCap{"Cap_top", disc(topCapRadius, 1.0 - plate - cap, 1.0 - plate)};
    Part topPlate{"Plate_top", disc(std::max(plateRadius, topCapRadius * 1.1), 1.0 - plate, 1.0)};
    Part bottomCap{"Cap_bottom", disc(bottomCapRadius, plate, plate + cap)};
    Part bottomPlate{"Plate_bottom", disc(std::max(plateRadius, bottomCapRadius * 1.1), 0.0, plate)};
    model.parts = {std::move(upper), std::move(lower), std::move(topPlate), std::move(topCap)};
    if (chance(rng, 0.5)) {
        model.parts.push_back(merged({bottomPlate, bottomCap}, "Base"));
    } else {
        model.parts.push_back(std::move(bottomPlate));
        model.parts.push_back(std::move(bottomCap));
    }
    return model;
}

} // namespace sandglass::wild
