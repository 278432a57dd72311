// SPDX-License-Identifier: MIT
// The granular cost of the bench report (PH6) on a small hourglass: stepping the two drains in
// turns measures them without changing them.
#include "bench/granular_report.hpp"

#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <numeric>

using namespace sandbench;

namespace {

// The same drain on its own, as a user's scene would run it.
sandcore::Scene drainAlone(int height, sandcore::StepSettings step, sandcore::PhysicsLevel level) {
    step.physics.level = level;
    sandcore::Scene scene = sandcore::makeHourglassScene(
        sandcore::makeHourglassMask({height, sandcore::defaultNeckRadius(height), 0.0f}), {}, step);
    while (!scene.settled()) scene.step();
    return scene;
}

} // namespace

TEST_CASE("the cost in turns drains both levels exactly as each drains alone") {
    constexpr int height = 40;
    sandcore::StepSettings step;
    step.threads = 2;
    const std::array<DrainCost, 2> costs = drainCostInTurns(height, step);
    const sandcore::PhysicsLevel levels[] = {sandcore::PhysicsLevel::Classic, sandcore::PhysicsLevel::Granular};
    for (std::size_t i = 0; i < costs.size(); ++i) {
        CAPTURE(i);
        const DrainCost& cost = costs[i];
        const sandcore::Scene alone = drainAlone(height, step, levels[i]);
        CHECK(cost.conserved);
        CHECK(cost.grains == alone.grainCount());
        CHECK(cost.grains > 1000);
        CHECK(cost.steps == alone.counters().stepsDone);
        CHECK(cost.hash == alone.stateHash());
        // Every step is timed and its discharge recorded: the series sums to the sand that passed.
        REQUIRE(cost.discharge.grainsPerStep.size() == cost.steps);
        const std::int64_t passed =
            std::accumulate(cost.discharge.grainsPerStep.begin(), cost.discharge.grainsPerStep.end(), std::int64_t{0});
        CHECK(passed == alone.counters().grainsLower);
        CHECK(cost.discharge.grainsAtStart == cost.grains); // the hourglass starts with all its sand above
        CHECK(cost.msPerStep > 0.0);
        CHECK(cost.movesPerStep > 0.0);
    }
    CHECK(costs[0].neckModelRate == 0.0);
    CHECK(costs[1].neckModelRate > 0.0);
    CHECK(costs[0].hash != costs[1].hash); // two sets of rules, two end states
}

TEST_CASE("classic drains in turns without a granular one run to their end") {
    sandcore::StepSettings step;
    const sandcore::PhysicsLevel levels[] = {sandcore::PhysicsLevel::Classic, sandcore::PhysicsLevel::Classic};
    const std::vector<DrainCost> costs = drainsInTurns(32, step, levels);
    const sandcore::Scene alone = drainAlone(32, step, sandcore::PhysicsLevel::Classic);
    for (const DrainCost& cost : costs) {
        CHECK(cost.level == sandcore::PhysicsLevel::Classic);
        CHECK(cost.steps == alone.counters().stepsDone);
        CHECK(cost.hash == alone.stateHash());
    }
}
