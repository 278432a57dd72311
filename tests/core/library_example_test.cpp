// SPDX-License-Identifier: MIT
// The example at the top of docs/engine.md, kept compiling and working (README's own example is
// compiled from README itself: tests/CMakeLists.txt).
#include <sandcore/sandcore.hpp>

#include <doctest/doctest.h>

#include <vector>

TEST_CASE("the documented library example drains sand at 30 steps per second of wall time") {
    sandcore::StepSettings step;
    step.threads = 2;
    sandcore::Scene scene = sandcore::makeHourglassScene(sandcore::makeHourglassMask({128, 4.0f}), {}, step);
    sandcore::SimClock clock;
    clock.setRunning(true);
    std::vector<sandcore::Vec3> positions(std::size_t(scene.grainCount()));
    const double frameSeconds = 1.0 / 60.0;
    for (int frame = 0; frame < 120; ++frame) { // two seconds of frames
        for (int due = clock.advance(frameSeconds); due > 0; --due) scene.step();
        sandcore::writeDisplayPositions(scene, float(clock.stepFraction()), {}, positions);
    }
    CHECK(scene.counters().stepsDone >= 59);
    CHECK(scene.counters().stepsDone <= 60);
    CHECK(scene.counters().grainsLower > 0);
    CHECK(scene.grainCount() == std::int64_t(positions.size()));
}
