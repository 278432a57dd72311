// SPDX-License-Identifier: MIT
#include "support/run_process.hpp"
#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

namespace {

using Run = cli::ProcessResult;
using cli::runSandglass;

std::string model(const std::string& name) { return std::string("'") + SANDGLASS_SOURCE_DIR + "/models/" + name + "'"; }

} // namespace

TEST_CASE("voxelize --json prints the C2 keys for a closed model") {
    const Run run = runSandglass("voxelize " + model("ball.obj") + " --res 32 --json");
    REQUIRE(run.exitCode == 0);
    const auto json = nlohmann::json::parse(run.out);
    CHECK(json["grid"] == nlohmann::json::array({32, 32, 32}));
    for (const char* key : {"cells_inside", "mesh_volume", "voxel_volume", "relative_error", "closed",
                            "boundary_edges", "milliseconds"})
        CHECK_MESSAGE(json.contains(key), key);
    CHECK(json["closed"] == true);
    CHECK(json["boundary_edges"] == 0);
    CHECK(json["voxel_volume"].get<double>() == json["cells_inside"].get<double>());
    const double mesh = json["mesh_volume"], voxels = json["voxel_volume"];
    CHECK(json["relative_error"].get<double>() == doctest::Approx((voxels - mesh) / mesh));
    CHECK(std::abs(json["relative_error"].get<double>()) < 0.03);
}

TEST_CASE("voxelize reports an open mesh with a null mesh volume") {
    const sandglass::TemporaryFolder folder;
    const std::filesystem::path& dir = folder.path();
    // A cube without its top face.
    std::ofstream(dir / "open.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                       "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 1 5 8 4\nf 2 3 7 6\n";
    const Run run = runSandglass("voxelize '" + (dir / "open.obj").string() + "' --res 8 --robust --json");
    REQUIRE(run.exitCode == 0);
    const auto json = nlohmann::json::parse(run.out);
    CHECK(json["closed"] == false);
    CHECK(json["boundary_edges"] == 4);
    CHECK(json["mesh_volume"].is_null());
    CHECK(json["cells_inside"] == 8 * 8 * 8);
}

TEST_CASE("each bad input gives one line on stderr naming the file, and a non-zero exit") {
    const sandglass::TemporaryFolder folder;
    const std::filesystem::path& dir = folder.path();
    std::ofstream(dir / "points.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\n";
    std::ofstream(dir / "nan.obj") << "v 0 0 0\nv nan 0 0\nv 0 1 1\nf 1 2 3\n";
    std::ofstream(dir / "flat.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n";
    std::ofstream(dir / "garbage.obj") << "\x01\x02 not a model \xff";
    const struct {
        std::string file, cause;
    } cases[] = {{"missing.obj", "no such file"},
                 {"points.obj", "contains no triangles"},
                 {"nan.obj", "NaN or infinite coordinate"},
                 {"flat.obj", "zero extent along z"},
                 {"garbage.obj", ""}};
    for (const auto& c : cases) {
        const std::string path = (dir / c.file).string();
        const Run run = runSandglass("voxelize '" + path + "' --res 16 --json");
        INFO(c.file << ": " << run.err);
        CHECK(run.exitCode != 0);
        CHECK(run.out.empty());
        CHECK(run.err.find(path + ": ") != std::string::npos);
        CHECK(run.err.find(c.cause) != std::string::npos);
        CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
    }
    const Run huge = runSandglass("voxelize " + model("ball.obj") + " --res 2000");
    CHECK(huge.exitCode != 0);
    CHECK(huge.err.find("exceeds the limit of 2^31 cells") != std::string::npos);
}

TEST_CASE("simulate --model drains the default hourglass") {
    const Run run = runSandglass("simulate --scene hourglass --model " + model("hourglass.obj") +
                                 " --res 32 --until-settled --json");
    REQUIRE(run.exitCode == 0);
    const auto json = nlohmann::json::parse(run.out);
    CHECK(json["settled"] == true);
    CHECK(json["grains_upper"] == 0);
    CHECK(json["grains"] == json["grains_initial"]);
    const Run bad = runSandglass("simulate --scene sculpture --model /nonexistent/model.obj --res 32");
    CHECK(bad.exitCode != 0);
    CHECK(bad.err == "sandglass: /nonexistent/model.obj: no such file\n");
}
