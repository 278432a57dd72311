// SPDX-License-Identifier: MIT
// SPEC C3 and §6: bad input to render, gui and bench gives one line on stderr and a non-zero code.
#include "support/display_guard.hpp"
#include "support/run_process.hpp"
#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace {

struct Result {
    int exitCode = -1;
    std::string errors;
};

Result runWithStderr(const std::string& arguments) {
    const cli::ProcessResult r = cli::runSandglass(arguments);
    return {r.exitCode, r.err};
}

} // namespace

TEST_CASE("cli: bad render, gui and bench input gives one line and a non-zero exit") {
    // Output paths inside a folder of this test's own: should a check fail, nothing lands elsewhere.
    const sandglass::TemporaryFolder folder;
    // Built with append: GCC 12 warns falsely (-Wrestrict) on "'" + string + "'".
    std::string x = "'";
    x.append((folder / "x.png").string()).append("'");
    for (const std::string& arguments :
         {"render --out " + x + " --mode voxels", "render --out " + x + " --grains-per-cell 40",
          std::string("render --mode points"), "render --out " + x + " --size 12", "render --out " + x + " --scene teapot",
          "gui --screenshot " + x, std::string("gui --res 3 --frames 1"), std::string("bench --out"),
          std::string("bench --render --res 2"), "render --out " + x + " --zoom 0",
          "render --out " + x + " --grain-path both", "render --out " + x + " --frames -1",
          "render --out " + x + " --light --normals flat"}) {
        CAPTURE(arguments);
        const Result result = runWithStderr(arguments);
        CHECK(result.exitCode != 0);
        CHECK(cli::lineCount(result.errors) == 1);
        CHECK(result.errors.rfind("sandglass: ", 0) == 0);
    }
}

TEST_CASE("cli: render writes a PNG and reports fps and frame_ms as JSON") {
    if (!sandglass::testing::requireDisplay("sandglass render")) return;
    const sandglass::TemporaryFolder folder;
    const std::string file = (folder / "render-cli-test.png").string();
    const cli::ProcessResult run = cli::runSandglassArgs(
        {"render", "--res", "16", "--steps", "5", "--size", "64x64", "--timed-frames", "2", "--json", "--out", file});
    INFO(run.err);
    REQUIRE(run.exitCode == 0);
    CHECK(run.out.find("\"fps\":") != std::string::npos);
    CHECK(run.out.find("\"frame_ms\":") != std::string::npos);
    FILE* png = std::fopen(file.c_str(), "rb");
    REQUIRE(png != nullptr);
    std::fclose(png);
}

TEST_CASE("cli: render --normals picks how lit grains get their normals, and says which") {
    if (!sandglass::testing::requireDisplay("sandglass render --normals")) return;
    const sandglass::TemporaryFolder folder;
    std::string images[2];
    const char* methods[2] = {"gradient", "columns"};
    for (int i = 0; i < 2; ++i) {
        CAPTURE(methods[i]);
        const std::string file = (folder / (std::string("lit-") + methods[i] + ".png")).string();
        const cli::ProcessResult run =
            cli::runSandglassArgs({"render", "--res", "24", "--steps", "30", "--size", "96x96", "--timed-frames", "0",
                                   "--light", "--normals", methods[i], "--json", "--out", file});
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
        CHECK(run.out.find(std::string("\"normals\":\"") + methods[i] + "\"") != std::string::npos);
        std::ifstream png(file, std::ios::binary);
        images[i].assign(std::istreambuf_iterator<char>(png), std::istreambuf_iterator<char>());
        CHECK(!images[i].empty());
    }
    CHECK(images[0] != images[1]); // the two estimates light the same sand differently
}

TEST_CASE("cli: render --frames reports upload bytes, moves, CPU and upkeep time per frame, on both paths") {
    if (!sandglass::testing::requireDisplay("sandglass render --frames")) return;
    const sandglass::TemporaryFolder folder;
    const std::string file = (folder / "render-frames.png").string();
    for (const char* path : {"gpu", "cpu"}) {
        CAPTURE(path);
        const cli::ProcessResult run =
            cli::runSandglassArgs({"render", "--res", "24", "--steps", "40", "--frames", "4", "--size", "64x64",
                                   "--timed-frames", "1", "--grain-path", path, "--json", "--out", file});
        INFO(run.err);
        REQUIRE(run.exitCode == 0);
        for (const char* key : {"\"upload_bytes_per_frame\":", "\"moves_per_step\":", "\"cpu_ms_per_frame\":",
                                "\"app_cpu_ms_per_frame\":", "\"upkeep_ms_per_step\":", "\"gpu_ms_per_frame\":",
                                "\"gpu_frame_ms\":", "\"steps\":44"}) {
            CAPTURE(key);
            CHECK(run.out.find(key) != std::string::npos);
        }
        // The application's part is the frame's CPU time less the draw calls: never more than it.
        const nlohmann::json report = nlohmann::json::parse(run.out);
        CHECK(report["app_cpu_ms_per_frame"].get<double>() >= 0.0);
        CHECK(report["app_cpu_ms_per_frame"].get<double>() <= report["cpu_ms_per_frame"].get<double>());
        // The GPU's time of the drawing, from timer queries: some, for the still and the stepped frames.
        CHECK(report["gpu_ms_per_frame"].get<double>() > 0.0);
        CHECK(report["gpu_frame_ms"].get<double>() > 0.0);
        // Sand flows by step 40 (granular grains over the neck have left their cells): both paths
        // upload something, and moves are counted.
        CHECK(run.out.find("\"upload_bytes_per_frame\":0.0") == std::string::npos);
        CHECK(run.out.find("\"moves_per_step\":0.0") == std::string::npos);
    }
}

TEST_CASE("cli: render to a full device or a missing folder fails and keeps an existing PNG") {
    if (!sandglass::testing::requireDisplay("sandglass render")) return;
    const sandglass::TemporaryFolder folder;
    const std::string file = (folder / "kept.png").string();
    { std::ofstream(file, std::ios::binary) << "an older picture"; }
    const std::string missing = (folder / "missing-folder" / "x.png").string();
    for (const std::string& out : {std::string("/dev/full"), missing}) {
        CAPTURE(out);
        const cli::ProcessResult run =
            cli::runSandglassArgs({"render", "--res", "8", "--steps", "1", "--size", "32x32", "--out", out});
        CHECK(run.exitCode != 0);
        CHECK(cli::lineCount(run.err) == 1);
    }
    std::ifstream kept(file, std::ios::binary);
    CHECK(std::string(std::istreambuf_iterator<char>(kept), {}) == "an older picture");
}
