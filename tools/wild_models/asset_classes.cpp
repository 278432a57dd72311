// SPDX-License-Identifier: MIT
// Models as asset stores sell them: a one-object hourglass with modelled sand, a glass of cones
// and discs with a hair-thin neck, and a funnel.
#include "class_builders.hpp"
#include "glass_profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sandglass::wild {

CanonicalModel buildOneObjectAsset(Rng& rng) {
    const int segments = randomSegments(rng);
    const double plate = uniform(rng, 0.03, 0.07);
    CanonicalModel model;
    GroundTruth& truth = model.truth;
    truth.bottom = plate + (chance(rng, 0.5) ? 0.0 : uniform(rng, 0.0, 0.012));
    const double top = 1.0 - plate - (chance(rng, 0.5) ? 0.0 : uniform(rng, 0.0, 0.012));
    truth.openBelow = truth.bottom - plate;
    truth.openAbove = 1.0 - plate - top;
    const HourglassRequest request{.innerHeight = top - truth.bottom, .neckRadius = uniform(rng, 0.012, 0.04),
                                   .neckTube = uniform(rng, 0.005, 0.04)};
    truth.profile = hourglassProfile(rng, request, truth.neckHeight);
    std::vector<Part> parts{{"glass", lathe(raised(truth.profile, truth.bottom), segments)}};

    // Sand in the upper bulb from the neck up to a flat top, a little inside the glass.
    truth.sandFraction = uniform(rng, 0.5, 0.8);
    const double innerHeight = truth.profile.back().height;
    const double sandTop = heightForVolume(truth.profile, truth.neckHeight,
                                           truth.sandFraction * volumeBetween(truth.profile, truth.neckHeight, innerHeight));
    std::vector<ProfileSample> sand = profileBetween(truth.profile, truth.neckHeight, sandTop);
    for (ProfileSample& s : sand) s.radius *= 0.97;
    parts.push_back({"sand_top", closedLathe(raised(sand, truth.bottom), segments)});

    // A cone heap on the bottom of the lower bulb, narrower than the glass at every height.
    const double base = 0.003 * innerHeight;
    double heapRadius = 0.9 * radiusAt(truth.profile, base);
    const double slope = uniform(rng, 0.4, 0.7);
    for (int tries = 0; tries < 50; ++tries) {
        bool fits = true;
        for (int i = 0; i <= 20; ++i) {
            const double h = base + heapRadius * slope * i / 20.0;
            fits = fits && h < truth.neckHeight && heapRadius * (1.0 - i / 20.0) <= 0.95 * radiusAt(truth.profile, h);
        }
        if (fits) break;
        heapRadius *= 0.9;
    }
    const std::vector<ProfileSample> heap{{base, 0.0}, {base, heapRadius}, {base + heapRadius * slope, 0.0}};
    parts.push_back({"sand_bottom", lathe(raised(heap, truth.bottom), segments)});

    const FrameRequest frame{.plate = plate, .clearRadius = widest(truth.profile), .posts = true};
    const std::vector<Part> frameParts = randomFrame(rng, frame);
    parts.insert(parts.end(), frameParts.begin(), frameParts.end());
    model.parts = {merged(parts, pick(rng, {"Hourglass_low", "hourglass_lowpoly", "SM_Hourglass", "Sandglass"}))};
    return model;
}

CanonicalModel buildConesRingsPost(Rng& rng) {
    const int segments = randomSegments(rng);
    CanonicalModel model;
    GroundTruth& truth = model.truth;
    // The neck is narrower than half a cell at resolution 64: its diameter is 0.2..0.6 of one.
    const double neckRadius = 0.5 * uniform(rng, 0.2, 0.6) / 64.0;
    const double disc = uniform(rng, 0.02, 0.06), discRadius = uniform(rng, 0.25, 0.4);
    const double coneBottom = discRadius * uniform(rng, 0.5, 0.9), coneTop = coneBottom * uniform(rng, 0.93, 1.07);
    const double discTop = discRadius * uniform(rng, 0.97, 1.03);
    truth.neckHeight = uniform(rng, 0.45, 0.55);
    // One closed surface: a disc, a cone down to the neck, a cone up to the other disc.
    truth.profile = {{0.0, discRadius},          {disc, discRadius}, {disc, coneBottom}, {truth.neckHeight, neckRadius},
                     {1.0 - disc, coneTop},      {1.0 - disc, discTop}, {1.0, discTop}};
    model.parts.push_back({pick(rng, {"Glass", "Cone_glass", "Hourglass"}), closedLathe(truth.profile, segments)});
    const double postRadius = uniform(rng, 0.015, 0.04), postHeight = uniform(rng, 0.6, 1.0);
    const double postDistance = std::max(discRadius, discTop) + postRadius + uniform(rng, 0.005, 0.05);
    const double angle = uniform(rng, 0.0, 2.0 * std::numbers::pi);
    model.parts.push_back({pick(rng, {"Post", "Cylinder", "Pillar.001"}),
                           cylinderMesh(postRadius, 0.0, postHeight, postDistance * std::cos(angle), postDistance * std::sin(angle),
                                        uniformInt(rng, 8, 24))});
    return model;
}

CanonicalModel buildFunnel(Rng& rng) {
    const int segments = randomSegments(rng);
    CanonicalModel model;
    GroundTruth& truth = model.truth;
    const double outlet = uniform(rng, 0.02, 0.06), mouth = uniform(rng, 0.25, 0.5);
    // An open cone, with a cylindrical spout below it or without.
    truth.profile = {{0.0, outlet}};
    if (chance(rng, 0.6)) truth.profile.push_back({uniform(rng, 0.1, 0.3), outlet});
    const double coneStart = truth.profile.back().height;
    const int rings = uniformInt(rng, 1, 8);
    for (int i = 1; i <= rings; ++i) {
        const double t = double(i) / rings;
        truth.profile.push_back({coneStart + (1.0 - coneStart) * t, outlet + (mouth - outlet) * t});
    }
    truth.neckHeight = -1.0;
    model.parts.push_back({pick(rng, {"Funnel", "Hopper", "funnel_mesh", "Mesh"}), lathe(truth.profile, segments)});
    return model;
}

} // namespace sandglass::wild
