// SPDX-License-Identifier: MIT
// The hourglass as a timer on the command line: turning over and a drain of a chosen duration.
#include "support/run_process.hpp"

#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

using namespace cli;

namespace {
nlohmann::json simulate(const std::string& args) {
    const ProcessResult r = runSandglass("simulate " + args + " --json");
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    return nlohmann::json::parse(r.out);
}
} // namespace

TEST_CASE("simulate --flip-at: two turns after the last step give the same state as none") {
    const auto straight = simulate("--res 48 --steps 150");
    const auto twice = simulate("--res 48 --steps 150 --flip-at 150 --flip-at 150");
    CHECK(twice["hash"] == straight["hash"]);
    CHECK(twice["flips"] == 2);
}

TEST_CASE("simulate --flip-at 400: every grain kept, the sand goes back up and drains again, any vessel") {
    for (const char* model : {"models/hourglass.obj", "models/shelf_hourglass.obj", "models/slim_hourglass.obj"}) {
        CAPTURE(model);
        const auto turned = simulate(std::string("--model ") + SANDGLASS_SOURCE_DIR + "/" + model +
                                     " --steps 400 --flip-at 400");
        CHECK(turned["grains_upper"].get<long>() > 0); // the drained sand is on top again
        const auto drained = simulate(std::string("--model ") + SANDGLASS_SOURCE_DIR + "/" + model +
                                      " --steps 4000 --flip-at 400");
        CHECK(drained["settled"] == true);
        CHECK(drained["grains_upper"] == 0);
        CHECK(drained["grains"] == drained["grains_initial"]);
    }
    const ProcessResult canvas = runSandglass("simulate --scene canvas --steps 10 --flip-at 5");
    CHECK(canvas.exitCode == 2);
    CHECK(lineCount(canvas.err) == 1);
}

TEST_CASE("simulate --duration: the predicted drain runs exactly, at the rate that makes it last the duration") {
    const auto timed = simulate("--res 64 --duration 60 --until-settled");
    const double drainSteps = timed["drain_steps"].get<double>();
    CHECK(timed["steps"].get<double>() == doctest::Approx(drainSteps).epsilon(0.01));
    CHECK(timed["steps_per_second_set"].get<double>() == doctest::Approx(drainSteps / 60.0));
    CHECK(timed["drain_seconds"].get<double>() == doctest::Approx(60.0).epsilon(0.01));
    const ProcessResult bad = runSandglass("simulate --duration -3");
    CHECK(bad.exitCode == 2);
    CHECK(bad.err.find("--duration") != std::string::npos);
}
