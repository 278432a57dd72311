// SPDX-License-Identifier: MIT
#include "glass_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace sandglass::wild {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSamplesPerBulb = 36;

// Radius at d in [0, cut] from the neck: the superellipse, never narrower than the neck until
// the far half, where a closed bulb must come down to its pole.
double bulbRadius(const BulbShape& shape, double neckRadius, double d) {
    const double e = std::pow(d, shape.skew);
    const double u = std::abs(2.0 * e - 1.0);
    const double curve = u >= 1.0 ? 0.0 : shape.radius * std::pow(1.0 - std::pow(u, shape.exponent), 1.0 / shape.exponent);
    const double neckFloor = neckRadius * std::clamp(2.0 - 2.0 * d, 0.0, 1.0);
    return std::max(curve, neckFloor);
}

double segmentDistance(double h, double d, ProfileSample a, ProfileSample b) {
    const double dh = b.height - a.height, dr = b.radius - a.radius;
    const double lengthSquared = dh * dh + dr * dr;
    const double t = lengthSquared > 0 ? std::clamp(((h - a.height) * dh + (d - a.radius) * dr) / lengthSquared, 0.0, 1.0) : 0.0;
    return std::hypot(h - (a.height + t * dh), d - (a.radius + t * dr));
}

} // namespace

BulbShape randomBulb(Rng& rng, double length, bool closed) {
    BulbShape shape;
    switch (uniformInt(rng, 0, 2)) {
    case 0: // sphere-like, or an ellipsoid tall or squat
        shape.exponent = 2.0;
        shape.radius = length * uniform(rng, 0.28, 0.95);
        break;
    case 1: // cone-like
        shape.exponent = uniform(rng, 1.0, 1.3);
        shape.radius = length * uniform(rng, 0.35, 0.8);
        break;
    default: // rounded cylinder
        shape.exponent = uniform(rng, 3.0, 6.0);
        shape.radius = length * uniform(rng, 0.3, 0.6);
        break;
    }
    shape.skew = uniform(rng, 0.8, 1.25);
    shape.cut = closed ? 1.0 : uniform(rng, 0.75, 0.92);
    return shape;
}

BulbShape nearlyTheSame(Rng& rng, BulbShape shape) {
    shape.radius *= uniform(rng, 0.93, 1.07);
    shape.exponent *= uniform(rng, 0.92, 1.08);
    shape.skew = std::clamp(shape.skew * uniform(rng, 0.95, 1.05), 0.8, 1.25);
    if (shape.cut < 1.0) shape.cut = std::clamp(shape.cut + uniform(rng, -0.03, 0.03), 0.75, 0.92);
    return shape;
}

std::vector<ProfileSample> hourglassProfile(Rng& rng, const HourglassRequest& request, double& neckHeight) {
    const double height = request.innerHeight;
    neckHeight = height * uniform(rng, 0.45, 0.55);
    const double lowerLength = neckHeight - 0.5 * request.neckTube, upperLength = height - neckHeight - 0.5 * request.neckTube;
    const BulbShape upper = randomBulb(rng, upperLength, request.closedEnds);
    const BulbShape lower = nearlyTheSame(rng, upper);
    // Samples crowd towards both ends of a bulb, where the radius changes fastest.
    auto share = [](int j) { return 0.5 - 0.5 * std::cos(kPi * j / kSamplesPerBulb); };
    std::vector<ProfileSample> profile;
    for (int j = kSamplesPerBulb; j >= 0; --j) {
        const double d = lower.cut * share(j);
        profile.push_back({lowerLength * (1.0 - share(j)), bulbRadius(lower, request.neckRadius, d)});
    }
    for (int j = 0; j <= kSamplesPerBulb; ++j) {
        const double d = upper.cut * share(j);
        profile.push_back({height - upperLength * (1.0 - share(j)), bulbRadius(upper, request.neckRadius, d)});
    }
    profile.front().height = 0.0;
    profile.back().height = height;
    return profile;
}

double radiusAt(const std::vector<ProfileSample>& profile, double h) {
    if (profile.empty() || h < profile.front().height || h > profile.back().height) return -1.0;
    double radius = -1.0;
    for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
        const ProfileSample a = profile[i], b = profile[i + 1];
        if (h < a.height || h > b.height) continue;
        const double t = b.height > a.height ? (h - a.height) / (b.height - a.height) : 0.0;
        radius = std::max({radius, a.radius + t * (b.radius - a.radius), b.height > a.height ? -1.0 : b.radius});
    }
    return radius;
}

double volumeBetween(const std::vector<ProfileSample>& profile, double h0, double h1) {
    double volume = 0.0;
    for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
        const ProfileSample a = profile[i], b = profile[i + 1];
        const double low = std::max(h0, a.height), high = std::min(h1, b.height);
        if (high <= low) continue;
        auto at = [&](double h) { return a.radius + (h - a.height) / (b.height - a.height) * (b.radius - a.radius); };
        const double ra = at(low), rb = at(high);
        volume += kPi * (high - low) * (ra * ra + ra * rb + rb * rb) / 3.0;
    }
    return volume;
}

double heightForVolume(const std::vector<ProfileSample>& profile, double h0, double volume) {
    double low = h0, high = profile.back().height;
    for (int i = 0; i < 100; ++i) {
        const double middle = 0.5 * (low + high);
        (volumeBetween(profile, h0, middle) < volume ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

double distanceToProfile(const std::vector<ProfileSample>& profile, double h, double d) {
    if (profile.empty()) return std::numeric_limits<double>::infinity();
    if (d <= radiusAt(profile, h)) return 0.0;
    const ProfileSample bottomAxis{profile.front().height, 0.0}, topAxis{profile.back().height, 0.0};
    double nearest = std::min(segmentDistance(h, d, bottomAxis, profile.front()), segmentDistance(h, d, topAxis, profile.back()));
    for (std::size_t i = 0; i + 1 < profile.size(); ++i) nearest = std::min(nearest, segmentDistance(h, d, profile[i], profile[i + 1]));
    return nearest;
}

std::vector<ProfileSample> profileBetween(const std::vector<ProfileSample>& profile, double h0, double h1) {
    std::vector<ProfileSample> part{{h0, radiusAt(profile, h0)}};
    for (const ProfileSample& s : profile)
        if (s.height > h0 && s.height < h1) part.push_back(s);
    part.push_back({h1, radiusAt(profile, h1)});
    return part;
}

} // namespace sandglass::wild
