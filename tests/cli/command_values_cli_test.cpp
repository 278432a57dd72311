// SPDX-License-Identifier: MIT
// Every command-line value is checked where it enters: one line naming the option, exit code 2
// for a wrong command line, and the codes documented in every --help.
#include "support/run_process.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace cli;

TEST_CASE("bad values of every kind are refused with one line naming the option and exit code 2") {
    const std::pair<const char*, const char*> bad[] = {
        {"simulate --res 4", "--res"},                            // passed the parser before, failed deep inside
        {"simulate --res 9999999", "--res"},
        {"simulate --res ten", "--res"},
        {"simulate --seed -1", "--seed"},                         // wrapped to 2^64-1 before
        {"simulate --seed 18446744073709551616", "--seed"},       // 2^64: wrapped before
        {"simulate --steps 99999999999999999999", "--steps"},    // saturated before
        {"simulate --steps -1", "--steps"},
        {"simulate --steps 1e3", "--steps"},
        {"simulate --max-steps -1", "--max-steps"},
        {"simulate --neck nan", "--neck"},
        {"simulate --neck inf", "--neck"},
        {"simulate --fill 0", "--fill"},
        {"simulate --fill 1.5", "--fill"},
        {"simulate --threads 0", "--threads"},
        {"simulate --threads 100000", "--threads"},
        {"simulate --noise 9", "--noise"},
        {"gui --zoom nan", "--zoom"},
        {"gui --frames -1", "--frames"},
        {"gui --grains-per-cell 33", "--grains-per-cell"},
        {"gui --seed -1", "--seed"},
        {"gui --timer 0", "--timer"},
        {"simulate --flip-at -2", "--flip-at"},
        {"simulate --duration 0", "--duration"},
        {"render --out x.png --threads 0", "--threads"},
        {"render --out x.png --res 3", "--res"},
        {"bench --render --seconds nan", "--seconds"},
        {"bench --render --seconds -1", "--seconds"},
        {"bench --render --max-frames -1", "--max-frames"},
        {"bench --threads 0", "--threads"},
        {"voxelize models/ball.obj --res 0", "--res"},
    };
    for (const auto& [args, option] : bad) {
        CAPTURE(args);
        const ProcessResult r = runSandglass(args);
        CHECK(r.exitCode == 2);
        CHECK(lineCount(r.err) == 1);
        CHECK(r.err.find(option) != std::string::npos);
        CHECK(r.out.empty());
    }
}

TEST_CASE("seed and threads exist on every command that runs a scene, and --help documents the exit codes") {
    for (const char* command : {"simulate", "gui", "render", "bench"}) {
        CAPTURE(command);
        const ProcessResult r = runSandglass(std::string(command) + " --help");
        CHECK(r.exitCode == 0);
        CHECK(r.out.find("--seed") != std::string::npos);
        CHECK(r.out.find("--threads") != std::string::npos);
        CHECK(r.out.find("Exit codes: 0 success; 1 the work failed") != std::string::npos);
        CHECK(r.out.find("2 the command line is wrong") != std::string::npos);
    }
}

TEST_CASE("a failed job exits 1, a wrong command line 2") {
    CHECK(runSandglass("simulate --model no-such-model.obj --steps 1").exitCode == 1);
    CHECK(runSandglass("simulate --frobnicate").exitCode == 2);
}

TEST_CASE("--version names the commit and the libraries") {
    const ProcessResult r = runSandglass("--version");
    CHECK(r.exitCode == 0);
    CHECK(r.out.find("sandglass ") == 0);
    CHECK(r.out.find("(commit ") != std::string::npos);
    for (const char* library : {"Dear ImGui", "GLFW", "assimp", "CLI11"}) {
        CAPTURE(library);
        CHECK(r.out.find(library) != std::string::npos);
    }
}

TEST_CASE("--threads and --seed reach the step: the hash depends on the seed only") {
    const ProcessResult one = runSandglass("simulate --res 24 --steps 80 --threads 1 --seed 7 --json");
    const ProcessResult two = runSandglass("simulate --res 24 --steps 80 --threads 2 --seed 7 --json");
    const ProcessResult other = runSandglass("simulate --res 24 --steps 80 --threads 1 --seed 8 --json");
    REQUIRE(one.exitCode == 0);
    auto hashOf = [](const std::string& json) { return json.substr(json.find("\"hash\":\""), 27); };
    CHECK(two.out.find("\"threads\":2") != std::string::npos);
    CHECK(hashOf(one.out) == hashOf(two.out));
    CHECK(hashOf(one.out) != hashOf(other.out));
}
