// SPDX-License-Identifier: MIT
// SPEC I4: a second start of the window restores what the first one left; --no-settings and a
// damaged file start from the defaults. Each test keeps its settings in its own folder.
#include "support/run_process.hpp"
#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

using namespace cli;

namespace {

nlohmann::json readJson(const std::filesystem::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in);
}

// "frames 2, steps 0, grains 12186 (at start 12186)": the grains the window's scene started with.
long long grainsAtStart(const ProcessResult& r) {
    const auto at = r.out.find("(at start ");
    return at == std::string::npos ? -1 : std::atoll(r.out.c_str() + at + 10);
}

// The settings of this test only: XDG_CONFIG_HOME for the processes it starts.
struct ConfigFolder {
    sandglass::TemporaryFolder folder;
    ConfigFolder() { ::setenv("XDG_CONFIG_HOME", folder.path().c_str(), 1); }
    std::filesystem::path settings() const { return folder.path() / "sandglass/settings.json"; }
};

} // namespace

TEST_CASE("settings: a second start of the window restores what the first one changed") {
    ConfigFolder config;
    const auto shots = config.folder / "shots";
    std::filesystem::create_directory(shots);
    const ProcessResult first = runSandglassArgs({"gui", "--frames", "3", "--scene", "sculpture", "--res", "32", "--mode",
                                                  "billboards", "--palette", "beach", "--light", "--size", "700x500",
                                                  "--screenshot-dir", shots.string()});
    if (first.err.find("no OpenGL") != std::string::npos || first.err.find("display") != std::string::npos) {
        MESSAGE("no display: the remembered window is not checked (" << first.err << ")");
        return;
    }
    REQUIRE(first.exitCode == 0);
    REQUIRE(std::filesystem::exists(config.settings()));
    CHECK(std::filesystem::exists(config.folder / "sandglass/imgui.ini")); // ImGui's panel layout beside it
    const nlohmann::json saved = readJson(config.settings());
    CHECK(saved["render_mode"] == "billboards");
    CHECK(saved["palette"] == "beach");
    CHECK(saved["lighting"] == true);
    CHECK(saved["scene"] == "sculpture");
    CHECK(saved["window_width"] == 700);
    CHECK(saved["window_height"] == 500);
    CHECK(saved["screenshot_folder"] == shots.string());

    // The second start names nothing: the sculpture comes back (its grains, not the hourglass's),
    // and what it writes at its end is what it ran with.
    const ProcessResult second = runSandglassArgs({"gui", "--frames", "3", "--res", "32"});
    REQUIRE(second.exitCode == 0);
    CHECK(grainsAtStart(second) == grainsAtStart(first));
    const nlohmann::json again = readJson(config.settings());
    for (const char* key : {"render_mode", "palette", "lighting", "scene", "model", "window_width", "window_height",
                            "screenshot_folder"}) {
        CAPTURE(key);
        CHECK(again[key] == saved[key]);
    }

    // The command line still wins over what is remembered.
    const ProcessResult third = runSandglassArgs({"gui", "--frames", "2", "--mode", "sprites", "--scene", "hourglass", "--res", "32"});
    REQUIRE(third.exitCode == 0);
    CHECK(grainsAtStart(third) != grainsAtStart(first));
    CHECK(readJson(config.settings())["render_mode"] == "sprites");
    CHECK(readJson(config.settings())["palette"] == "beach");
}

TEST_CASE("settings: --no-settings starts from the defaults and leaves the file alone") {
    ConfigFolder config;
    std::filesystem::create_directories(config.settings().parent_path());
    const std::string remembered = R"({"scene": "canvas", "render_mode": "sprites"})";
    std::ofstream(config.settings()) << remembered;
    const ProcessResult r = runSandglassArgs({"gui", "--frames", "2", "--no-settings", "--res", "32"});
    if (r.exitCode != 0 && r.err.find("OpenGL") != std::string::npos) return;
    REQUIRE(r.exitCode == 0);
    CHECK(grainsAtStart(r) > 0); // the default hourglass, not the remembered empty canvas
    std::ifstream in(config.settings());
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str() == remembered);
}

TEST_CASE("settings: a garbage settings file gives one line and the defaults") {
    ConfigFolder config;
    std::filesystem::create_directories(config.settings().parent_path());
    std::ofstream(config.settings()) << "{\"scene\": \"canvas\", garbage";
    const ProcessResult r = runSandglassArgs({"gui", "--frames", "2", "--res", "32"});
    if (r.exitCode != 0 && r.err.find("OpenGL") != std::string::npos) return;
    REQUIRE(r.exitCode == 0);
    CAPTURE(r.err);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find(config.settings().string() + ": ") != std::string::npos);
    CHECK(grainsAtStart(r) > 0); // the default hourglass
    CHECK(readJson(config.settings())["scene"] == "hourglass"); // the end of the run wrote a good file
}
