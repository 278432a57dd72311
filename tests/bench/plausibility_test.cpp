// SPDX-License-Identifier: MIT
// The B2 plausibility measurements on piles and discharges with known answers.
#include "bench/plausibility.hpp"

#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include "support/height_field.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sandcore;
using namespace sandbench;

TEST_CASE("a stepped pyramid stands at 45 degrees along the axes and 35.26 along the diagonals") {
    const CellGrid grid = support::heightField(
        {41, 22, 41}, [](int x, int z) { return std::max(0, 20 - std::max(std::abs(x - 20), std::abs(z - 20))); });
    const ReposeAngles angles = measureReposeAngles(grid);
    CHECK(angles.flanksMeasured == 8);
    CHECK(angles.alongAxes == doctest::Approx(45.0).epsilon(1e-9));
    CHECK(angles.alongDiagonals == doctest::Approx(std::atan(1.0 / std::sqrt(2.0)) * 180.0 / M_PI).epsilon(1e-9));
}

TEST_CASE("a round cone of 30 degrees measures 30 degrees within a degree in every direction") {
    const double slope = std::tan(30.0 * M_PI / 180.0);
    const CellGrid grid = support::heightField({81, 30, 81}, [&](int x, int z) {
        const double r = std::hypot(x - 40, z - 40);
        return std::max(0, int(std::lround(24.0 - r * slope)));
    });
    const ReposeAngles angles = measureReposeAngles(grid);
    CHECK(angles.alongAxes == doctest::Approx(30.0).epsilon(1.0 / 30.0));
    CHECK(angles.alongDiagonals == doctest::Approx(30.0).epsilon(1.0 / 30.0));
}

TEST_CASE("a flank ends at a wall: INVALID columns are not part of the pile") {
    CellGrid grid = support::heightField(
        {41, 22, 41}, [](int x, int z) { return std::max(0, 20 - std::max(std::abs(x - 20), std::abs(z - 20))); });
    // A wall at x >= 30 would cut the +x flank after 9 cells; the fit still sees 45 degrees.
    for (int y = 0; y < 22; ++y)
        for (int z = 0; z < 41; ++z)
            for (int x = 30; x < 41; ++x) grid[grid.index(x, y, z)] = kInvalid;
    CHECK(measureReposeAngles(grid).alongAxes == doctest::Approx(45.0));
}

TEST_CASE("discharge rates and their variation") {
    DischargeSeries series;
    series.grainsAtStart = 1000;
    series.grainsPerStep.assign(100, 10); // a perfectly steady drain of 10 grains per step
    const auto steady = windowedDischargeRates(series, 5, 0.1, 0.9);
    CHECK(steady.size() == 16); // steps 10..90 of 100 hold the middle 80%
    CHECK(coefficientOfVariation(steady) == 0.0);
    CHECK(coefficientOfVariation({1.0, 3.0}) == doctest::Approx(std::sqrt(2.0) / 2.0));
}

TEST_CASE("the procedural hourglass drains at a steady rate") {
    Scene scene = makeHourglassScene(makeHourglassMask({64, 3.0f, 0.0f}));
    const DischargeSeries series = recordDischarge(scene, 100000);
    CHECK(scene.settled());
    std::int64_t total = 0;
    for (auto g : series.grainsPerStep) total += g;
    CHECK(total == series.grainsAtStart); // every grain passed the neck exactly once
    const double variation = coefficientOfVariation(windowedDischargeRates(series, 10, 0.1, 0.9));
    CHECK(variation > 0.0);
    CHECK(variation < 0.15);
}
