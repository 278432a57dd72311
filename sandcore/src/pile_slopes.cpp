// SPDX-License-Identifier: MIT
#include "sandcore/pile_slopes.hpp"

#include "sandcore/normals.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sandcore {

double PileSlopes::meanDegrees() const {
    return degrees.empty() ? 0.0 : std::accumulate(degrees.begin(), degrees.end(), 0.0) / double(degrees.size());
}
double PileSlopes::minDegrees() const { return degrees.empty() ? 0.0 : *std::min_element(degrees.begin(), degrees.end()); }
double PileSlopes::maxDegrees() const { return degrees.empty() ? 0.0 : *std::max_element(degrees.begin(), degrees.end()); }

double leastSquaresSlope(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.empty()) return 0.0;
    const double n = double(x.size());
    const double meanX = std::accumulate(x.begin(), x.end(), 0.0) / n;
    const double meanY = std::accumulate(y.begin(), y.end(), 0.0) / n;
    double covariance = 0.0, variance = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        covariance += (x[i] - meanX) * (y[i] - meanY);
        variance += (x[i] - meanX) * (x[i] - meanX);
    }
    return variance > 0.0 ? covariance / variance : 0.0;
}

PileSlopes measurePileSlopes(const CellGrid& grid, const PileSlopeSettings& settings) {
    const Int3 s = grid.size();
    const std::vector<int> heights = columnHeights(grid);
    auto heightAt = [&](int x, int z) {
        x = std::clamp(x, 0, s.x - 1);
        z = std::clamp(z, 0, s.z - 1);
        return double(heights[std::size_t(x) + std::size_t(s.x) * std::size_t(z)]);
    };
    PileSlopes result;
    result.peakHeight = *std::max_element(heights.begin(), heights.end());
    if (result.peakHeight == 0) return result;
    double sumX = 0, sumZ = 0;
    int count = 0;
    for (int z = 0; z < s.z; ++z)
        for (int x = 0; x < s.x; ++x)
            if (int(heightAt(x, z)) == result.peakHeight) {
                sumX += x + 0.5;
                sumZ += z + 0.5;
                ++count;
            }
    result.peakX = sumX / count;
    result.peakZ = sumZ / count;
    // Bilinear between column centres, so a direction between the grid's axes sees a smooth flank.
    auto sample = [&](double px, double pz) {
        const double fx = px - 0.5, fz = pz - 0.5;
        const int x0 = int(std::floor(fx)), z0 = int(std::floor(fz));
        const double tx = fx - x0, tz = fz - z0;
        return (1 - tx) * (1 - tz) * heightAt(x0, z0) + tx * (1 - tz) * heightAt(x0 + 1, z0) +
               (1 - tx) * tz * heightAt(x0, z0 + 1) + tx * tz * heightAt(x0 + 1, z0 + 1);
    };
    const double low = settings.fromShare * result.peakHeight, high = settings.toShare * result.peakHeight;
    // The least-squares angle of the heights along the ray at angle phi (0 if too few points).
    auto rayDegrees = [&](double phi) {
        const double ux = std::cos(phi), uz = std::sin(phi);
        std::vector<double> distance, height;
        for (double r = 0.5;; r += 0.5) {
            const double px = result.peakX + r * ux, pz = result.peakZ + r * uz;
            if (px < 0 || pz < 0 || px > s.x || pz > s.z) break;
            const double h = sample(px, pz);
            if (h < low) break;
            if (h > high) continue;
            distance.push_back(r);
            height.push_back(h);
        }
        if (distance.size() < 3) return 0.0;
        return std::atan(std::abs(leastSquaresSlope(distance, height))) * 180.0 / M_PI;
    };
    const int rays = std::max(settings.raysPerDirection, 1);
    for (int d = 0; d < settings.directions; ++d) {
        double sum = 0;
        for (int i = 0; i < rays; ++i) sum += rayDegrees(2.0 * M_PI * (d + ((i + 0.5) / rays - 0.5)) / settings.directions);
        result.degrees.push_back(sum / rays);
    }
    return result;
}

} // namespace sandcore
