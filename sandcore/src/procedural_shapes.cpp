// SPDX-License-Identifier: MIT
#include "sandcore/procedural_shapes.hpp"

#include "ball_cells.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sandcore {

namespace {
void requireResolution(int resolution, int minimum) {
    if (resolution < minimum)
        throw std::invalid_argument("resolution must be at least " + std::to_string(minimum) + ", got " +
                                    std::to_string(resolution));
}
} // namespace

InsideMask ballCells(int diameter, double slackSquared) {
    InsideMask mask = InsideMask::empty({diameter, diameter, diameter});
    const double centre = diameter / 2.0, radius = diameter / 2.0;
    for (int y = 0; y < diameter; ++y)
        for (int z = 0; z < diameter; ++z)
            for (int x = 0; x < diameter; ++x) {
                const double dx = x + 0.5 - centre, dy = y + 0.5 - centre, dz = z + 0.5 - centre;
                mask.set(x, y, z, dx * dx + dy * dy + dz * dz <= radius * radius + slackSquared);
            }
    return mask;
}

InsideMask makeSphereMask(int resolution) {
    requireResolution(resolution, 2);
    return ballCells(resolution, 0.0);
}

InsideMask makeCubeMask(int resolution) {
    requireResolution(resolution, 3);
    InsideMask mask = InsideMask::empty({resolution, resolution, resolution});
    for (int y = 1; y < resolution - 1; ++y)
        for (int z = 1; z < resolution - 1; ++z)
            for (int x = 1; x < resolution - 1; ++x) mask.set(x, y, z, true);
    return mask;
}

// Radius of the hourglass at distance d (cells) from the neck, for a bulb of half-height h:
// a sine shoulder from the neck out to the widest radius, then a rounded cap.
static double hourglassRadius(double d, double h, double neck, double bulb) {
    const double shoulderEnd = 0.6 * h, capStart = 0.78 * h;
    if (d <= shoulderEnd) return neck + (bulb - neck) * std::sin(0.5 * M_PI * d / shoulderEnd);
    if (d <= capStart) return bulb;
    const double t = std::min((d - capStart) / (h - capStart), 1.0);
    return std::max(bulb * std::sqrt(1.0 - t * t * 0.75), neck);
}

float defaultNeckRadius(int height) { return std::max(1.5f, float(height) / 24.0f); }

namespace {
double bulbRadiusOf(const HourglassShape& shape) {
    return shape.bulbRadius > 0 ? shape.bulbRadius : 0.27 * shape.height;
}
} // namespace

Int3 hourglassMaskSize(const HourglassShape& shape) {
    const int width = 2 * int(std::ceil(bulbRadiusOf(shape))) + 2; // one cell of glass all round
    return {width, shape.height, width};
}

InsideMask makeHourglassMask(const HourglassShape& shape) {
    requireResolution(shape.height, 8);
    const double bulb = bulbRadiusOf(shape);
    if (shape.neckRadius < 0.5f || shape.neckRadius >= bulb)
        throw std::invalid_argument("hourglass neck radius must be at least 0.5 cells and below the bulb radius");
    const Int3 size = hourglassMaskSize(shape);
    const int width = size.x;
    InsideMask mask = InsideMask::empty(size);
    const double centre = width / 2.0, neckY = shape.height / 2.0, half = shape.height / 2.0;
    for (int y = 0; y < shape.height; ++y) {
        const double d = std::abs(y + 0.5 - neckY);
        const double r = hourglassRadius(d, half, shape.neckRadius, bulb);
        for (int z = 0; z < width; ++z)
            for (int x = 0; x < width; ++x) {
                const double dx = x + 0.5 - centre, dz = z + 0.5 - centre;
                mask.set(x, y, z, dx * dx + dz * dz <= r * r);
            }
    }
    return mask;
}

} // namespace sandcore
