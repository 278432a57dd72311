// SPDX-License-Identifier: MIT
// SPEC PH1 and PH7 through the real executable: --physics, --repose, --gravity, --trace.
#include "support/run_process.hpp"
#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>

using cli::runSandglass;

TEST_CASE("simulate --physics granular --trace writes one row per step and keeps every grain") {
    const sandglass::TemporaryFolder folder;
    const std::string trace = (folder.path() / "trace.csv").string();
    const auto r = runSandglass("simulate --scene canvas --res 24 --physics granular --repose 30 --gravity 0.5 "
                                "--pour 300 --until-settled --json --trace " + trace);
    REQUIRE(r.exitCode == 0);
    const auto json = nlohmann::json::parse(r.out);
    CHECK(json["physics"] == "granular");
    CHECK(json["grains"] == 300);
    CHECK(json["settled"] == true);
    std::ifstream file(trace);
    std::string line;
    REQUIRE(std::getline(file, line));
    CHECK(line == "step,grains_upper,grains_lower,moves");
    long long rows = 0, step = 0, upper = 0, lower = 0, moves = 0;
    while (std::getline(file, line)) {
        std::istringstream row(line);
        char comma;
        row >> step >> comma >> upper >> comma >> lower >> comma >> moves;
        ++rows;
        REQUIRE(step == rows);
    }
    CHECK(rows == json["steps"].get<long long>());
    CHECK(upper + lower == 300);
    CHECK(moves == 0); // the last step moved nothing: settled
}

TEST_CASE("granular and classic give different hashes, and granular repeats with 1 and 2 threads and a full sweep") {
    const std::string base = "simulate --scene sculpture --res 16 --steps 80 --seed 5 --json";
    const auto classic = nlohmann::json::parse(runSandglass(base + " --physics classic").out);
    const auto one = nlohmann::json::parse(runSandglass(base).out); // granular: the default
    const auto two = nlohmann::json::parse(runSandglass(base + " --physics granular --threads 2").out);
    const auto full = nlohmann::json::parse(runSandglass(base + " --physics granular --full-sweep").out);
    CHECK(classic["physics"] == "classic");
    CHECK(classic["hash"] != one["hash"]);
    CHECK(one["hash"] == two["hash"]);
    CHECK(one["hash"] == full["hash"]);
}

TEST_CASE("bad physics values are refused with one line naming the option") {
    const std::pair<const char*, const char*> bad[] = {
        {"simulate --physics sticky", "--physics"}, {"simulate --repose 19", "--repose"},
        {"simulate --repose 46", "--repose"},       {"simulate --gravity 0", "--gravity"},
        {"render --out x.png --physics x", "--physics"}, {"bench --gravity -1", "--gravity"},
    };
    for (const auto& [args, option] : bad) {
        CAPTURE(args);
        const auto r = runSandglass(args);
        CHECK(r.exitCode == 2);
        CHECK(cli::lineCount(r.err) == 1);
        CHECK(r.err.find(option) != std::string::npos);
    }
}
