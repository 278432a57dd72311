// SPDX-License-Identifier: MIT
#include "scene/hourglass_timer.hpp"
#include "scene/scene_host.hpp"

#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <thread>

using namespace sandglass;

namespace {
sandcore::Scene hourglass() { return sandcore::makeHourglassScene(sandcore::makeHourglassMask({40, 2.0f, 0.0f})); }

void waitForPrediction(HourglassTimer& timer, const sandcore::Scene& scene, std::optional<double>& rate) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (timer.phase() == HourglassTimer::Phase::Predicting && std::chrono::steady_clock::now() < deadline) {
        rate = timer.update(scene);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}
} // namespace

TEST_CASE("timer: the predicted drain is exactly the drain, and the rate makes it last the duration") {
    sandcore::Scene scene = hourglass();
    const std::int64_t predicted = predictDrainSteps(scene);
    CHECK(scene.counters().stepsDone == 0); // the prediction ran on a copy
    HourglassTimer timer;
    timer.start(scene, 90.0);
    std::optional<double> rate;
    waitForPrediction(timer, scene, rate);
    REQUIRE(timer.phase() == HourglassTimer::Phase::Running);
    REQUIRE(rate);
    CHECK(*rate == doctest::Approx(double(predicted) / 90.0));
    CHECK(timer.remainingSeconds(scene) == doctest::Approx(90.0));
    std::int64_t steps = 0;
    while (!scene.settled()) {
        scene.step();
        ++steps;
        timer.update(scene);
    }
    CHECK(steps == predicted);
    CHECK(timer.phase() == HourglassTimer::Phase::Finished);
    CHECK(timer.elapsedSeconds(scene) == doctest::Approx(90.0));
    CHECK(timer.remainingSeconds(scene) == 0.0);
    CHECK_THROWS_AS(timer.start(scene, 0.0), std::invalid_argument);
}

TEST_CASE("timer: after a turn the remaining time is that of the sand now on top, at the same rate") {
    sandcore::Scene scene = hourglass();
    HourglassTimer timer;
    timer.start(scene, 60.0);
    std::optional<double> rate;
    waitForPrediction(timer, scene, rate);
    REQUIRE(rate);
    for (int i = 0; i < 100; ++i) scene.step();
    REQUIRE(scene.flip());
    timer.sceneTurned(scene);
    std::optional<double> after;
    waitForPrediction(timer, scene, after);
    REQUIRE(after);
    CHECK(*after == *rate); // the rate stays
    const double expected = double(predictDrainSteps(scene)) / *rate;
    CHECK(timer.remainingSeconds(scene) == doctest::Approx(expected));
    CHECK(timer.remainingSeconds(scene) < 60.0); // only the sand that had run through is on top
}
