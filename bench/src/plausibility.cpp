// SPDX-License-Identifier: MIT
#include "bench/plausibility.hpp"

#include "sandcore/normals.hpp"
#include "sandcore/pile_slopes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sandbench {

using sandcore::CellGrid;
using sandcore::GridLevel;

DischargeSeries recordDischarge(sandcore::Scene& scene, std::int64_t maxSteps) {
    DischargeSeries series;
    series.grainsAtStart = scene.counters().grainsUpper;
    for (std::int64_t i = 0; i < maxSteps && !scene.settled(); ++i) {
        const std::int64_t before = scene.counters().grainsLower;
        scene.step();
        series.grainsPerStep.push_back(scene.counters().grainsLower - before);
    }
    return series;
}

std::vector<double> windowedDischargeRates(const DischargeSeries& series, int window, double fromShare,
                                           double toShare) {
    std::vector<double> rates;
    if (series.grainsAtStart <= 0 || window < 1) return rates;
    std::int64_t drained = 0, windowGrains = 0;
    int windowSteps = 0;
    for (std::int64_t passed : series.grainsPerStep) {
        drained += passed;
        const double share = double(drained) / double(series.grainsAtStart);
        if (share < fromShare) continue;
        if (share > toShare) break;
        windowGrains += passed;
        if (++windowSteps == window) {
            rates.push_back(double(windowGrains) / window);
            windowGrains = 0;
            windowSteps = 0;
        }
    }
    return rates;
}

MiddleDischarge middleDischarge(const DischargeSeries& series, int parts, double fromShare, double toShare) {
    MiddleDischarge middle;
    if (series.grainsAtStart <= 0 || parts < 1) return middle;
    // first: the step after the one that reached fromShare; end: the one that reaches toShare, included.
    std::size_t first = series.grainsPerStep.size(), end = series.grainsPerStep.size();
    std::int64_t drained = 0;
    for (std::size_t i = 0; i < series.grainsPerStep.size(); ++i) {
        drained += series.grainsPerStep[i];
        const double share = double(drained) / double(series.grainsAtStart);
        if (first == series.grainsPerStep.size() && share >= fromShare) first = i + 1;
        if (share >= toShare) {
            end = i + 1;
            break;
        }
    }
    if (first >= end || end - first < std::size_t(parts)) return middle;
    middle.steps = std::int64_t(end - first);
    std::int64_t grains = 0;
    for (int part = 0; part < parts; ++part) {
        const std::size_t from = first + (end - first) * std::size_t(part) / std::size_t(parts);
        const std::size_t to = first + (end - first) * std::size_t(part + 1) / std::size_t(parts);
        std::int64_t partGrains = 0;
        for (std::size_t i = from; i < to; ++i) partGrains += series.grainsPerStep[i];
        grains += partGrains;
        middle.partRates.push_back(double(partGrains) / double(to - from));
    }
    middle.rate = double(grains) / double(middle.steps);
    return middle;
}

double coefficientOfVariation(const std::vector<double>& values) {
    if (values.size() < 2) return 0.0;
    const double mean = std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
    double squares = 0.0;
    for (double v : values) squares += (v - mean) * (v - mean);
    const double deviation = std::sqrt(squares / double(values.size() - 1));
    return mean > 0.0 ? deviation / mean : 0.0;
}

namespace {

// True when the column holds an INVALID cell at or above its sand: the pile meets a wall there.
bool blockedColumn(const CellGrid& grid, int x, int z, int height) {
    for (int y = std::max(height - 1, 0); y < grid.size().y; ++y)
        if (grid.at(x, y, z) == sandcore::kInvalid) return true;
    return false;
}

} // namespace

ReposeAngles measureReposeAngles(const CellGrid& grid) {
    const sandcore::Int3 s = grid.size();
    const std::vector<int> heights = sandcore::columnHeights(grid);
    auto heightAt = [&](int x, int z) { return heights[std::size_t(x) + std::size_t(s.x) * std::size_t(z)]; };

    // The centre of the highest plateau is the pile's peak.
    const int top = *std::max_element(heights.begin(), heights.end());
    double sumX = 0, sumZ = 0;
    int count = 0;
    for (int z = 0; z < s.z; ++z)
        for (int x = 0; x < s.x; ++x)
            if (heightAt(x, z) == top) {
                sumX += x;
                sumZ += z;
                ++count;
            }
    ReposeAngles result;
    if (top == 0 || count == 0) return result;
    const int peakX = int(std::lround(sumX / count)), peakZ = int(std::lround(sumZ / count));

    const int directions[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
    double axisSum = 0, diagonalSum = 0;
    int axisCount = 0, diagonalCount = 0;
    for (const auto& d : directions) {
        const double stepLength = (d[0] != 0 && d[1] != 0) ? std::sqrt(2.0) : 1.0;
        std::vector<double> distance, height;
        for (int i = 1;; ++i) {
            const int x = peakX + i * d[0], z = peakZ + i * d[1];
            if (x < 0 || z < 0 || x >= s.x || z >= s.z) break;
            const int h = heightAt(x, z);
            if (h == 0 || blockedColumn(grid, x, z, h)) break; // the floor or a wall ends the flank
            if (h >= top) continue;                            // still on the plateau
            distance.push_back(i * stepLength);
            height.push_back(h);
        }
        if (distance.size() < 3) continue;
        const double angle = std::atan(std::abs(sandcore::leastSquaresSlope(distance, height))) * 180.0 / M_PI;
        if (d[0] != 0 && d[1] != 0) {
            diagonalSum += angle;
            ++diagonalCount;
        } else {
            axisSum += angle;
            ++axisCount;
        }
    }
    result.alongAxes = axisCount ? axisSum / axisCount : 0.0;
    result.alongDiagonals = diagonalCount ? diagonalSum / diagonalCount : 0.0;
    result.flanksMeasured = axisCount + diagonalCount;
    return result;
}

} // namespace sandbench
