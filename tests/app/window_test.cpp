// SPDX-License-Identifier: MIT
// SPEC G1: the window opens, runs 200 frames with the simulation on and closes cleanly.
#include "support/display_guard.hpp"

#include <doctest/doctest.h>

#include "support/run_process.hpp"
#include "support/temporary_folder.hpp"

#include <cstdio>
#include <string>

namespace {

struct ProcessResult {
    int exitCode = -1;
    std::string output;
};

// The one CLI runner (support/run_process.hpp), with both streams together as a user sees them.
ProcessResult runSandglass(const std::vector<std::string>& arguments) {
    const cli::ProcessResult run = cli::runSandglassArgs(arguments);
    return {run.exitCode, run.out + run.err};
}

} // namespace

TEST_CASE("window: 200 frames with the simulation on, then a clean exit with every grain kept") {
    if (!sandglass::testing::requireDisplay("window")) return;
    const ProcessResult run = runSandglass({"gui", "--res", "24", "--run", "--frames", "200", "--size", "320x240"});
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    unsigned long long frames = 0, steps = 0;
    long long grains = -1, grainsAtStart = -2;
    const auto line = run.output.find("frames ");
    REQUIRE(line != std::string::npos);
    REQUIRE(std::sscanf(run.output.c_str() + line, "frames %llu, steps %llu, grains %lld (at start %lld)", &frames,
                        &steps, &grains, &grainsAtStart) == 4);
    CHECK(frames == 200);
    CHECK(steps > 0);
    CHECK(grains == grainsAtStart);
}

TEST_CASE("window: --screenshot writes the last frame") {
    if (!sandglass::testing::requireDisplay("window")) return;
    const sandglass::TemporaryFolder folder;
    const std::string file = (folder / "window-test-screenshot.png").string();
    const ProcessResult run = runSandglass({"gui", "--res", "16", "--frames", "3", "--size", "200x150", "--screenshot", file});
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    FILE* png = std::fopen(file.c_str(), "rb");
    REQUIRE(png != nullptr);
    unsigned char signature[8] = {};
    CHECK(std::fread(signature, 1, 8, png) == 8);
    std::fclose(png);
    CHECK(signature[1] == 'P');
    CHECK(signature[2] == 'N');
    CHECK(signature[3] == 'G');
}

TEST_CASE("window: a screenshot that cannot be written fails the run with one line, before the window opens") {
    const sandglass::TemporaryFolder folder;
    const std::string file = (folder / "missing-folder" / "shot.png").string();
    const cli::ProcessResult run = cli::runSandglassArgs({"gui", "--res", "16", "--frames", "2", "--screenshot", file});
    CHECK(run.exitCode == 1);
    CHECK(cli::lineCount(run.err) == 1);
    CHECK(run.err.find("missing-folder") != std::string::npos);
}
