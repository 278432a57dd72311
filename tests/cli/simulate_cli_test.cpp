// SPDX-License-Identifier: MIT
// SPEC C1 through the real executable.
#include "support/run_process.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

using cli::lineCount;
using cli::requireOneLineRefusals;
using cli::runSandglass;

TEST_CASE("simulate --json prints one object with every C1 key") {
    const auto r = runSandglass("simulate --scene hourglass --res 24 --steps 50 --seed 3 --json");
    REQUIRE(r.exitCode == 0);
    const auto json = nlohmann::json::parse(r.out);
    for (const char* key : {"scene", "grains_initial", "grains", "steps", "moves", "hash", "seconds",
                            "steps_per_second", "threads", "settled"})
        CHECK_MESSAGE(json.contains(key), key);
    CHECK(json["scene"] == "hourglass");
    CHECK(json["steps"] == 50);
    CHECK(json["grains"] == json["grains_initial"]);
    CHECK(json["hash"].get<std::string>().size() == 16);
    CHECK(json["moves"].get<long long>() > 0);
}

TEST_CASE("simulate gives the same hash for 1 and 2 threads and with --full-sweep") {
    const std::string base = "simulate --scene sculpture --res 16 --until-settled --seed 5 --json";
    const auto one = nlohmann::json::parse(runSandglass(base).out);
    const auto two = nlohmann::json::parse(runSandglass(base + " --threads 2").out);
    const auto full = nlohmann::json::parse(runSandglass(base + " --full-sweep").out);
    CHECK(one["settled"] == true);
    CHECK(one["hash"] == two["hash"]);
    CHECK(one["hash"] == full["hash"]);
    CHECK(one["steps"] == full["steps"]);
    CHECK(two["threads"] == 2);
}

TEST_CASE("simulate gives the same granular hash for 1 and 2 threads and with --full-sweep") {
    const std::string base = "simulate --res 32 --physics granular --gravity 0.1 --steps 300 --json";
    const auto one = nlohmann::json::parse(runSandglass(base).out);
    const auto two = nlohmann::json::parse(runSandglass(base + " --threads 2").out);
    const auto full = nlohmann::json::parse(runSandglass(base + " --full-sweep").out);
    CHECK(one["moves"].get<long long>() > 0);
    CHECK(one["hash"] == two["hash"]);
    CHECK(one["hash"] == full["hash"]);
    CHECK_FALSE(one.contains("sweep_code")); // one build of the sweep: nothing to name
}

TEST_CASE("simulate --pour releases one grain per step on the canvas") {
    const auto r = runSandglass("simulate --scene canvas --res 24 --pour 200 --until-settled --json");
    REQUIRE(r.exitCode == 0);
    const auto json = nlohmann::json::parse(r.out);
    CHECK(json["grains_initial"] == 0);
    CHECK(json["grains"] == 200);
    CHECK(json["settled"] == true);
}

TEST_CASE("every procedural shape drains as a vessel and collapses as a sculpture") {
    for (const char* scene : {"hourglass", "sculpture"})
    for (const char* shape : {"sphere", "cube", "hourglass"}) {
        CAPTURE(scene);
        CAPTURE(shape);
        const auto r = runSandglass(std::string("simulate --scene ") + scene + " --shape " + shape +
                                    " --res 32 --until-settled --json");
        REQUIRE(r.exitCode == 0);
        const auto json = nlohmann::json::parse(r.out);
        CHECK(json["settled"] == true);
        CHECK(json["grains_upper"] == 0);
    }
}

TEST_CASE("bad arguments give a one-line error and a non-zero exit") {
    requireOneLineRefusals({
        "simulate --scene volcano",            // unknown scene
        "simulate --shape pyramid",            // unknown shape
        "simulate --res 5000",                 // grid too large
        "simulate --res -4",                   // negative size
        "simulate --res 0",                    // zero size
        "simulate --steps -5",                 // negative steps
        "simulate --neck -1",                  // negative neck
        "simulate --scene canvas --shape cube", // the canvas has no shape
        "simulate --scene canvas --model models/ball.obj", // nor a model
        "simulate --scene canvas --res 2000",  // a canvas over 2^31 cells
        "simulate --threads 0",                // no threads
        "simulate --steps 10 --until-settled", // exclusive options
        "simulate --frobnicate",               // unknown flag
        "simulate --pour 10",                  // pour needs the canvas
        "teleport",                            // unknown subcommand
    });
}

TEST_CASE("simulate --help describes the options and succeeds") {
    const auto r = runSandglass("simulate --help");
    CHECK(r.exitCode == 0);
    CHECK(r.out.find("--until-settled") != std::string::npos);
    CHECK(r.out.find("--full-sweep") != std::string::npos);
}
