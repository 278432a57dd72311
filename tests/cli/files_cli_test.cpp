// SPDX-License-Identifier: MIT
// SPEC E1, E2 through the real executable: simulate --save / --load / --export, voxelize --out.
#include "support/display_guard.hpp"
#include "support/run_process.hpp"
#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <fstream>

using cli::lineCount;
using cli::runSandglass;
using sandglass::TemporaryFolder;

namespace {
std::string quoted(const std::filesystem::path& file) {
    std::string text(1, '\'');
    text.append(file.string()).push_back('\'');
    return text;
}
const std::string kVessel = std::string("'") + SANDGLASS_SOURCE_DIR + "/models/hourglass.obj'";
} // namespace

TEST_CASE("simulate --save then --load --steps N gives the hash of running on without saving") {
    TemporaryFolder folder;
    const auto state = folder / "run.sand";
    const std::string scene = "simulate --scene hourglass --shape hourglass --res 24 --seed 9 --json";
    const auto straight = nlohmann::json::parse(runSandglass(scene + " --steps 200").out);
    const auto first = runSandglass(scene + " --steps 100 --save " + quoted(state));
    REQUIRE(first.exitCode == 0);
    CHECK(nlohmann::json::parse(first.out)["saved"] == state.string());
    const auto second = runSandglass("simulate --json --steps 100 --load " + quoted(state));
    REQUIRE(second.exitCode == 0);
    const auto json = nlohmann::json::parse(second.out);
    CHECK(json["hash"] == straight["hash"]);
    CHECK(json["scene"] == "hourglass");
    CHECK(json["grains"] == straight["grains"]);
}

TEST_CASE("simulate --load of a damaged, empty or foreign file: one line naming it, exit 1") {
    TemporaryFolder folder;
    const auto state = folder / "good.sand";
    REQUIRE(runSandglass("simulate --scene canvas --res 16 --pour 50 --steps 60 --save " + quoted(state)).exitCode == 0);
    std::ifstream in(state, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto write = [&](const std::string& name, const std::string& content) {
        std::ofstream(folder / name, std::ios::binary) << content;
        return folder / name;
    };
    std::string flipped = bytes;
    flipped[flipped.size() / 2] ^= 4;
    for (const auto& file : {write("truncated.sand", bytes.substr(0, bytes.size() / 2)), write("flipped.sand", flipped),
                             write("empty.sand", ""), write("model.sand", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")}) {
        CAPTURE(file);
        const auto r = runSandglass("simulate --steps 5 --load " + quoted(file));
        CHECK(r.exitCode == 1);
        CHECK(lineCount(r.err) == 1);
        CHECK(r.err.find(file.string() + ": ") != std::string::npos);
    }
    CHECK(runSandglass("simulate --load " + quoted(state) + " --scene canvas").exitCode == 2);
}

TEST_CASE("simulate --export writes the sand, and an unknown format or missing folder fails before the run") {
    TemporaryFolder folder;
    for (const char* name : {"sand.ply", "sand.vox", "sand.stl"}) {
        const auto r = runSandglass("simulate --scene sculpture --shape sphere --res 12 --steps 30 --export " + quoted(folder / name));
        CHECK(r.exitCode == 0);
        CHECK(std::filesystem::file_size(folder / name) > 100);
    }
    const auto unknown = runSandglass("simulate --res 12 --steps 100000000 --export " + quoted(folder / "sand.xyz"));
    CHECK(unknown.exitCode == 1);
    CHECK(lineCount(unknown.err) == 1);
    CHECK(unknown.err.find("unknown export format") != std::string::npos);
    const auto missing = runSandglass("simulate --res 12 --steps 100000000 --save " + quoted(folder / "no" / "x.sand"));
    CHECK(missing.exitCode == 1);
    CHECK(lineCount(missing.err) == 1);
}

TEST_CASE("voxelize --out writes the inside cells as .binvox or .vox") {
    TemporaryFolder folder;
    const auto r = runSandglass("voxelize " + kVessel + " --res 24 --json --out " + quoted(folder / "glass.binvox"));
    REQUIRE(r.exitCode == 0);
    const auto json = nlohmann::json::parse(r.out);
    std::ifstream in(folder / "glass.binvox", std::ios::binary);
    std::string header;
    std::getline(in, header);
    CHECK(header == "#binvox 1");
    CHECK(runSandglass("voxelize " + kVessel + " --res 24 --out " + quoted(folder / "glass.vox")).exitCode == 0);
    CHECK(std::filesystem::file_size(folder / "glass.vox") > 100);
    const auto bad = runSandglass("voxelize " + kVessel + " --res 24 --out " + quoted(folder / "glass.png"));
    CHECK(bad.exitCode == 2);
    CHECK(lineCount(bad.err) == 1);
}

TEST_CASE("gui --load opens the saved state in the window, and a damaged file is one line and exit 1") {
    if (!sandglass::testing::requireDisplay("gui --load")) return;
    TemporaryFolder folder;
    const auto state = folder / "glass.sand";
    REQUIRE(runSandglass("simulate --scene hourglass --shape hourglass --res 20 --steps 30 --save " + quoted(state)).exitCode == 0);
    const auto opened = runSandglass("gui --frames 1 --size 160x120 --load " + quoted(state));
    INFO(opened.out, opened.err);
    REQUIRE(opened.exitCode == 0);
    CHECK(opened.out.find("frames 1, steps 30,") != std::string::npos);
    std::ofstream(folder / "broken.sand") << "SANDGLASS but not really";
    const auto broken = runSandglass("gui --frames 1 --size 160x120 --load " + quoted(folder / "broken.sand"));
    CHECK(broken.exitCode == 1);
    CHECK(lineCount(broken.err) == 1);
    CHECK(broken.err.find((folder / "broken.sand").string()) != std::string::npos);
    // The state says what the scene is: scene options beside --load are a usage error.
    CHECK(runSandglass("gui --frames 1 --res 30 --load " + quoted(state)).exitCode == 2);
}
