// SPDX-License-Identifier: MIT
// SPEC B1: the GPU time of the frames drawn, by timer queries. Every timed draw is counted once,
// also when more frames are drawn than the timer keeps in flight, each with some time; with
// timing off nothing is counted.
#include "support/app_test_support.hpp"

#include "app/application.hpp"

#include <doctest/doctest.h>

#include <optional>

using namespace sandglass;

TEST_CASE("B1: the GPU frame timer counts each timed draw once, with time, and nothing when off") {
    if (!testing::requireDisplay("the GPU frame timer")) return;
    ApplicationOptions options = testing::proceduralHourglassOptions(96, 96, 24, "sandglass gpu frame timer test");
    options.initial.simulationRunning = false;
    std::optional<Application> app = testing::openApplication(std::move(options), "the GPU frame timer");
    if (!app) return;
    SceneRenderer& renderer = app->renderer();

    renderer.timeGpu(true);
    for (int frames : {1, 3, 11}) { // 11: more than the queries kept in flight
        CAPTURE(frames);
        for (int i = 0; i < frames; ++i) app->renderFrame(0.0);
        const GpuTime time = renderer.takeGpuTime();
        CHECK(time.frames == frames);
        CHECK(time.milliseconds > 0.0);
        CHECK(time.perFrame() == doctest::Approx(time.milliseconds / frames));
    }
    CHECK(renderer.takeGpuTime().frames == 0); // taken: counting starts afresh

    renderer.timeGpu(false);
    for (int i = 0; i < 3; ++i) app->renderFrame(0.0);
    const GpuTime off = renderer.takeGpuTime();
    CHECK(off.frames == 0);
    CHECK(off.milliseconds == 0.0);
    CHECK(off.perFrame() == 0.0);
}
