// SPDX-License-Identifier: MIT
// Models that are not glasses: a character for the sculpture scene and a keyboard of keys too
// small for a coarse grid.
#include "class_builders.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sandglass::wild {

CanonicalModel buildCharacter(Rng& rng) {
    const int segments = uniformInt(rng, 16, 40), rings = uniformInt(rng, 12, 24);
    CanonicalModel model;
    GroundTruth& truth = model.truth;
    const double hip = uniform(rng, 0.42, 0.5), legRadius = uniform(rng, 0.035, 0.055);
    const Ellipsoid torso{{0.0, 0.0, 0.0}, {uniform(rng, 0.12, 0.17), uniform(rng, 0.15, 0.2), uniform(rng, 0.07, 0.1)}};
    const double headRadius = uniform(rng, 0.065, 0.09);
    Ellipsoid head{{0.0, 0.0, 0.0}, {headRadius, headRadius * uniform(rng, 1.05, 1.25), headRadius * uniform(rng, 0.9, 1.05)}};
    head.centre[1] = 1.0 - head.radii[1];
    Ellipsoid body = torso;
    body.centre[1] = hip + 0.85 * torso.radii[1];
    const double torsoTop = body.centre[1] + body.radii[1];
    const Capsule neck{{0.0, torsoTop - 0.03, 0.0}, {0.0, head.centre[1] - 0.5 * head.radii[1], 0.0}, uniform(rng, 0.025, 0.04)};

    // Arms hang out from the shoulders so that the figure is 1.25..1.9 times as tall as wide.
    const double armLength = uniform(rng, 0.3, 0.4), armRadius = uniform(rng, 0.028, 0.042);
    const double shoulderX = 0.85 * body.radii[0], shoulderY = body.centre[1] + 0.6 * body.radii[1];
    const double halfWidth = 0.5 / uniform(rng, 1.25, 1.9);
    const double sine = std::clamp((halfWidth - shoulderX - armRadius) / armLength, 0.05, 0.95);
    const double cosine = std::sqrt(1.0 - sine * sine);
    std::vector<Capsule> limbs;
    for (double side : {-1.0, 1.0}) {
        Capsule arm{{side * shoulderX, shoulderY, 0.0}, {side * (shoulderX + armLength * sine), shoulderY - armLength * cosine, 0.0}, armRadius};
        arm.roundA = chance(rng, 0.7);
        arm.roundB = chance(rng, 0.4); // an open sleeve where the hand would be
        limbs.push_back(arm);
    }
    for (double side : {-1.0, 1.0}) {
        Capsule leg{{side * 0.45 * body.radii[0], hip + 0.03, 0.0}, {side * 0.45 * body.radii[0], legRadius, 0.0}, legRadius};
        leg.roundA = chance(rng, 0.5);
        leg.roundB = chance(rng, 0.7);
        if (!leg.roundB) leg.b[1] = 0.0; // an open end stands on the floor
        limbs.push_back(leg);
    }

    Part torsoPart{"Body", ellipsoidMesh(body, rings, segments, chance(rng, 0.85), false)};
    if (chance(rng, 0.5)) {
        // A few faces missing on the back, as a sculpt export leaves them.
        const double y = body.centre[1] + uniform(rng, -0.5, 0.5) * body.radii[1];
        const double reach = uniform(rng, 0.01, 0.03);
        model.removedFaces += removeFaces(torsoPart.mesh, [&](Point c) {
            return std::hypot(c[0], c[1] - y, c[2] + body.radii[2]) < reach + 0.3 * body.radii[2];
        });
    }
    model.parts.push_back(std::move(torsoPart));
    model.parts.push_back({"Head", ellipsoidMesh(head, rings, segments, false, chance(rng, 0.6))});
    model.parts.push_back({"Neck", capsuleMesh(neck, rings, segments)});
    const char* limbNames[] = {"Arm.R", "Arm.L", "Leg.R", "Leg.L"};
    for (std::size_t i = 0; i < limbs.size(); ++i) model.parts.push_back({limbNames[i], capsuleMesh(limbs[i], rings, segments)});
    if (chance(rng, 0.4)) model.parts = {merged(model.parts, pick(rng, {"Character", "Body", "Mesh", "base_mesh"}))};

    truth.ellipsoids = {body, head};
    truth.capsules = limbs;
    truth.capsules.push_back(neck);
    return model;
}

CanonicalModel buildKeyboard(Rng& rng) {
    // Canonical length 1 along x is 64 cells at resolution 64, whose centres lie at (k + 1/2) / 64
    // from the left end. Each key stays between two centres along x and is under half a cell
    // tall, so no cell centre at resolution 64 lies in a key, while at 512 many do.
    const double cell = 1.0 / 64.0;
    const int columns = 15, rows = 6;
    const double keyHeight = uniform(rng, 0.25, 0.45) * cell;
    const double rowPitch = uniform(rng, 3.0, 4.5) * cell, keyDepth = uniform(rng, 0.6, 2.0) * cell;
    const int skipped = columns + uniformInt(rng, 0, columns * (rows - 1) - 1); // 90 places, 89 keys; the first row is full
    CanonicalModel model;
    int index = 0;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            if (row * columns + column == skipped) continue;
            double x0 = 0.0, x1 = 0.0;
            if (column == 0) {
                x1 = uniform(rng, 0.2, 0.4) * cell;
            } else if (column == columns - 1) {
                x0 = 1.0 - uniform(rng, 0.2, 0.4) * cell;
                x1 = 1.0;
            } else {
                const double left = std::round(column * 62.0 / (columns - 1)), margin = uniform(rng, 0.1, 0.3);
                x0 = (left + 0.5 + margin) * cell;
                x1 = (left + 1.5 - margin) * cell;
            }
            const Box key{{x0 - 0.5, 0.0, row * rowPitch}, {x1 - 0.5, keyHeight, row * rowPitch + keyDepth}};
            char name[16];
            std::snprintf(name, sizeof name, "Key.%03d", ++index);
            model.parts.push_back({name, boxMesh(key.min, key.max)});
            model.truth.boxes.push_back(key);
        }
    return model;
}

} // namespace sandglass::wild
