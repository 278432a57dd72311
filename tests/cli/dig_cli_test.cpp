// SPDX-License-Identifier: MIT
// `simulate --scene sandbox --dig`: a body driven through the bed from the command line.
#include "support/run_process.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

using cli::lineCount;
using cli::requireOneLineRefusals;
using cli::runSandglass;

TEST_CASE("simulate --dig drives a blade through the sandbox, keeps every grain and reports the trench") {
    // The sandbox at --res 40: a 40 x 26 x 40 box with a bed 8 deep; the blade's bottom 4 cells down.
    const std::string base = "simulate --scene sandbox --res 40 --dig '20,4,4 20,4,34' --steps 150 --json";
    const auto r = runSandglass(base);
    REQUIRE(r.exitCode == 0);
    const auto json = nlohmann::json::parse(r.out);
    CHECK(json["scene"] == "sandbox");
    CHECK(json["grains_initial"] == 40 * 40 * 8);
    CHECK(json["grains"] == json["grains_initial"]);
    CHECK(json["dig_body"] == "blade");
    CHECK(json["dig_done"] == true);
    CHECK(json["dig_cells_moved"] == 30);
    CHECK(json["dig_legs_stopped"] == 0);
    CHECK(json["grains_pushed"].get<long long>() >= 30 * 10 * 4); // a 10-wide blade 4 cells into the bed, each cell
    CHECK(json["trench_depth"].get<double>() > 0.5);
    CHECK(json["trench_depth"].get<double>() < 4.0); // the sides slid partly back in
    // Faster, on more threads and without sleeping: the same sand, cell for cell.
    const auto two = nlohmann::json::parse(runSandglass(base + " --threads 2 --full-sweep").out);
    CHECK(two["hash"] == json["hash"]);
    const auto fast = nlohmann::json::parse(runSandglass(base + " --dig-speed 6 --dig-body ball").out);
    CHECK(fast["dig_steps"] == 5);
    CHECK(fast["grains"] == json["grains_initial"]);
}

TEST_CASE("simulate --dig: bad paths, bodies and speeds give a one-line error") {
    requireOneLineRefusals({
        "simulate --scene sandbox --dig '1,2'",                     // not X,Y,Z
        "simulate --scene sandbox --dig 'a,b,c'",                   // not numbers
        "simulate --scene sandbox --dig ' '",                       // no point
        "simulate --scene sandbox --dig '30,8,6 300,8,6'",          // outside the box
        "simulate --scene sandbox --dig '1,0,1 1,0,20'",            // the blade does not fit there
        "simulate --scene hourglass --dig '1,2,3'",                 // not a canvas
        "simulate --scene sandbox --dig '30,8,6' --dig-speed 0",    // too slow
        "simulate --scene sandbox --dig '30,8,6' --dig-speed 65",   // too fast
        "simulate --scene sandbox --dig-speed 3",                   // no path
        "simulate --scene sandbox --dig-body box",                  // no path
        "simulate --scene sandbox --dig '30,8,6' --dig-body spoon", // no such body or file
    });
}
