// SPDX-License-Identifier: MIT
// SPEC C4: `sandglass bench --quick` produces the report (its content, not its speed).
#include "support/run_process.hpp"
#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

TEST_CASE("bench --quick writes the Markdown report, CSV tables and PNG plots, and its checks pass") {
    // A folder name a shell would run or choke on: the report must not pass it to one.
    const sandglass::TemporaryFolder folder;
    const fs::path out = folder / "it's a \"report\" $(touch pwned) `touch pwned`";
    const auto r = cli::runSandglassArgs({"bench", "--quick", "--out", out.string()});
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    for (const char* file : {"README.md", "voxelization.csv", "voxelization_dense.csv", "voxelization_binning.csv",
                             "simulation.csv", "plausibility.csv", "discharge.csv", "voxelization.png",
                             "simulation.png", "discharge.png"}) {
        CAPTURE(file);
        REQUIRE(fs::exists(out / file));
        CHECK(fs::file_size(out / file) > 50);
    }
    std::ifstream readme(out / "README.md");
    std::stringstream text;
    text << readme.rdbuf();
    CHECK(text.str().find("Checks: all passed.") != std::string::npos);
    CHECK(text.str().find("| discharge rate") != std::string::npos);
    CHECK(text.str().find("| sphere | 20480 | 64 |") != std::string::npos);
    CHECK(text.str().find("repose angle") != std::string::npos);
    // The PNGs are real images.
    std::ifstream png(out / "simulation.png", std::ios::binary);
    char magic[4] = {};
    png.read(magic, 4);
    CHECK(std::string(magic + 1, 3) == "PNG");
    CHECK_FALSE(fs::exists("pwned"));
    CHECK_FALSE(fs::exists(folder / "pwned"));
}

TEST_CASE("bench refuses an output folder it cannot create, with one line") {
    const auto r = cli::runSandglass("bench --quick --out /proc/no-such-place/report");
    CHECK(r.exitCode != 0);
    CHECK(cli::lineCount(r.err) >= 1);
    CHECK(r.err.find("sandglass: ") != std::string::npos);
}
