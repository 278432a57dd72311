// SPDX-License-Identifier: MIT
// SPEC I3: `sandglass FILE` (and `sandglass gui FILE`) opens a .sand state, a model as an
// hourglass, or a draft image on the canvas.
#include "support/run_process.hpp"
#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>

using namespace cli;

namespace {

const std::string kModels = std::string(SANDGLASS_SOURCE_DIR) + "/models/";

long long grainsAtStart(const ProcessResult& r) {
    const auto at = r.out.find("(at start ");
    return at == std::string::npos ? -1 : std::atoll(r.out.c_str() + at + 10);
}

bool noDisplay(const ProcessResult& r) {
    if (r.exitCode == 0 || r.err.find("OpenGL") == std::string::npos) return false;
    MESSAGE("no display: " << r.err);
    return true;
}

} // namespace

TEST_CASE("open file: a model opens as an hourglass, the same one --model builds") {
    const ProcessResult byFile = runSandglassArgs({"gui", kModels + "framed_hourglass.obj", "--frames", "2", "--res", "32"});
    if (noDisplay(byFile)) return;
    REQUIRE(byFile.exitCode == 0);
    const ProcessResult byOption =
        runSandglassArgs({"gui", "--model", kModels + "framed_hourglass.obj", "--frames", "2", "--res", "32", "--no-settings"});
    REQUIRE(byOption.exitCode == 0);
    CHECK(grainsAtStart(byFile) > 0);
    CHECK(grainsAtStart(byFile) == grainsAtStart(byOption));
    // Not the default model at that resolution.
    const ProcessResult byDefault = runSandglassArgs({"gui", "--shape", "hourglass", "--frames", "2", "--res", "32", "--no-settings"});
    CHECK(grainsAtStart(byDefault) != grainsAtStart(byFile));
}

TEST_CASE("open file: a .sand file opens the saved state") {
    sandglass::TemporaryFolder folder;
    const auto state = folder / "state.sand";
    REQUIRE(runSandglassArgs({"simulate", "--shape", "hourglass", "--res", "24", "--steps", "5", "--save", state.string()}).exitCode == 0);
    const ProcessResult r = runSandglassArgs({"gui", state.string(), "--frames", "2"});
    if (noDisplay(r)) return;
    REQUIRE(r.exitCode == 0);
    const ProcessResult loaded = runSandglassArgs({"gui", "--load", state.string(), "--frames", "2"});
    CHECK(grainsAtStart(r) == grainsAtStart(loaded));
    CHECK(grainsAtStart(r) > 0);
}

TEST_CASE("open file: a draft image opens on the canvas") {
    const ProcessResult r = runSandglassArgs({"gui", kModels + "draft_sun.png", "--frames", "2", "--res", "32"});
    if (noDisplay(r)) return;
    CAPTURE(r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(grainsAtStart(r) == 0); // an empty canvas, with the draft shown to paint over
    // The draft really is the canvas's: pouring over it needs one.
    const ProcessResult demo = runSandglassArgs({"gui", kModels + "draft_sun.png", "--frames", "2", "--res", "32", "--paint-demo", "1"});
    CHECK(demo.exitCode == 0);
    CHECK(demo.out.find("paint demo: ") != std::string::npos);
}

TEST_CASE("open file: without a subcommand, a file that is not there gets one line and exit code 1") {
    const ProcessResult r = runSandglassArgs({"/no/such/place/model.obj"});
    CHECK(r.exitCode == 1);
    CHECK(r.err.find("/no/such/place/model.obj") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    const ProcessResult state = runSandglassArgs({"/no/such/place/state.sand"});
    CHECK(state.exitCode == 1);
    CHECK(state.err.find("/no/such/place/state.sand") != std::string::npos);
}
