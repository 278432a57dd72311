// SPDX-License-Identifier: MIT
// SPEC S7-S9 through the real executable: parts, roles, the up axis and the sand space in the JSON.
#include "support/run_process.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <string>

using cli::runSandglass;

namespace {
std::string model(const std::string& name) {
    std::string quoted(1, '\'');
    quoted.append(SANDGLASS_SOURCE_DIR).append("/models/").append(name).push_back('\'');
    return quoted;
}
} // namespace

TEST_CASE("simulate --json reports the framed hourglass's parts, its cavity and the up axis found") {
    const auto r = runSandglass("simulate --model " + model("framed_hourglass.obj") + " --res 40 --steps 0 --json");
    REQUIRE(r.exitCode == 0);
    const auto json = nlohmann::json::parse(r.out);
    REQUIRE(json["parts"].size() == 6);
    CHECK(json["parts"][0] == nlohmann::json{{"name", "glass"}, {"triangles", 16640}, {"closed", true}, {"role", "vessel"}});
    CHECK(json["parts"][1]["role"] == "frame");
    CHECK(json["vessel"] == "cavity");
    CHECK(json["up_axis"] == "+y");
    CHECK(json["up_axis_found"] == true);
    const double fill = json["grains_initial"].get<double>() / json["upper_cells"].get<double>();
    CHECK(fill >= 0.6);
    CHECK(fill <= 1.0);
}

TEST_CASE("voxelize --json finds the Z-up STL's axis, and --part and --up are checked where they enter") {
    const auto r = runSandglass("voxelize " + model("framed_hourglass_z.stl") + " --res 40 --json");
    REQUIRE(r.exitCode == 0);
    const auto json = nlohmann::json::parse(r.out);
    CHECK(json["up_axis"] == "+z");
    CHECK(json["vessel"] == "cavity");
    CHECK(json["cavities"] == 1);
    // One object of six shells: the glass and the frame's parts, told apart by where the sand space lies.
    REQUIRE(json["parts"].size() == 6);
    CHECK(json["parts"][0]["name"] == "framed_hourglass_z #1");
    CHECK(json["parts"][0]["role"] == "vessel");
    for (std::size_t i = 1; i < 6; ++i) CHECK(json["parts"][i]["role"] == "frame");
    const auto given = runSandglass("voxelize " + model("framed_hourglass_z.stl") + " --res 40 --up -z --json");
    REQUIRE(given.exitCode == 0);
    CHECK(nlohmann::json::parse(given.out)["up_axis"] == "-z");
    const auto role = runSandglass("simulate --model " + model("framed_hourglass.obj") +
                                   " --res 24 --steps 0 --part top_plate=vessel --json");
    REQUIRE(role.exitCode == 0);
    CHECK(nlohmann::json::parse(role.out)["parts"][2]["role"] == "vessel");
    const auto unknown = runSandglass("simulate --model " + model("framed_hourglass.obj") + " --res 24 --part lid=frame");
    CHECK(unknown.exitCode != 0);
    CHECK(unknown.err.find("no part 'lid'") != std::string::npos);
    const auto badUp = runSandglass("simulate --model " + model("framed_hourglass.obj") + " --res 24 --up sideways");
    CHECK(badUp.exitCode != 0);
    CHECK(badUp.err.find("--up") != std::string::npos);
}
