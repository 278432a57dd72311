// SPDX-License-Identifier: MIT
// R9: the fixed-rate clock.
#include "sandcore/sim_clock.hpp"

#include <doctest/doctest.h>

using sandcore::SimClock;

TEST_CASE("the clock is paused by default and produces steps at its rate once running") {
    SimClock clock({30.0, 4});
    CHECK(!clock.running());
    CHECK(clock.advance(1.0) == 0);
    clock.setRunning(true);
    int steps = 0;
    for (int frame = 0; frame < 60; ++frame) steps += clock.advance(1.0 / 60.0); // one second at 60 fps
    CHECK(steps >= 29);
    CHECK(steps <= 30);
    steps = 0;
    for (int frame = 0; frame < 600; ++frame) steps += clock.advance(1.0 / 600.0); // one second at 600 fps
    CHECK(steps >= 29);
    CHECK(steps <= 31);
}

TEST_CASE("the step fraction grows within a step interval") {
    SimClock clock({10.0, 4});
    clock.setRunning(true);
    CHECK(clock.advance(0.025) == 0);
    CHECK(clock.stepFraction() == doctest::Approx(0.25));
    CHECK(clock.advance(0.05) == 0);
    CHECK(clock.stepFraction() == doctest::Approx(0.75));
    CHECK(clock.advance(0.05) == 1);
    CHECK(clock.stepFraction() == doctest::Approx(0.25));
    CHECK(clock.stepFraction() < 1.0);
}

TEST_CASE("a slow frame drops steps beyond the per-frame limit") {
    SimClock clock({30.0, 4});
    clock.setRunning(true);
    CHECK(clock.advance(10.0) == 4);
    CHECK(clock.stepFraction() < 1.0);
}

TEST_CASE("single step works while paused, and bad rates are ignored") {
    SimClock clock;
    clock.requestSingleStep();
    CHECK(clock.advance(0.0) == 1);
    CHECK(clock.advance(1.0) == 0);
    clock.setStepsPerSecond(-5.0);
    clock.setStepsPerSecond(0.0);
    CHECK(clock.stepsPerSecond() == 30.0);
    clock.setStepsPerSecond(120.0);
    CHECK(clock.stepsPerSecond() == 120.0);
}

TEST_CASE("sim clock: slow frames run several steps up to the cap, and say when the cap dropped steps") {
    sandcore::SimClock clock({30.0, 64});
    clock.setRunning(true);
    CHECK(clock.advance(1.0 / 3.0) == 10); // 3 frames per second: 10 steps each keep 30 steps/s
    CHECK_FALSE(clock.capped());
    CHECK(clock.advance(3.0) == 64); // a 3 s stall: 90 due, 64 run
    CHECK(clock.capped());
    clock.setMaxStepsPerFrame(0);
    CHECK(clock.maxStepsPerFrame() == 1);
}
