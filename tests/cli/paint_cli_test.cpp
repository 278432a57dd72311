// SPDX-License-Identifier: MIT
// SPEC P5 at the command line: --draft loads a draft (a bad one is one line on stderr and a
// failed run, as a bad --load), --paint-demo pours a drawing over it through the mouse path.
#include "support/display_guard.hpp"
#include "support/run_process.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

TEST_CASE("cli: --paint-demo pours sand over the draft, a bad --draft is one line and a failed run") {
    if (!sandglass::testing::requireDisplay("the painting demo")) return;
    const std::string sun = std::string(SANDGLASS_SOURCE_DIR) + "/models/draft_sun.png";
    const cli::ProcessResult demo =
        cli::runSandglass("gui --scene canvas --res 32 --size 320x240 --frames 1 --draft " + sun + " --paint-demo 1");
    CHECK(demo.exitCode == 0);
    CHECK(demo.out.find("paint demo: ") != std::string::npos);
    CHECK(demo.out.find("paint demo: 0 grains") == std::string::npos);

    const cli::ProcessResult bad =
        cli::runSandglass("gui --scene canvas --res 32 --size 320x240 --frames 1 --draft no-such-draft.png");
    CHECK(bad.exitCode == 1);
    CHECK(bad.err == "sandglass: no-such-draft.png: no such file\n");
    CHECK(bad.out.find("frames 1") == std::string::npos);

    const cli::ProcessResult misuse = cli::runSandglass("gui --paint-demo 2 --frames 1");
    CHECK(misuse.exitCode != 0);
    CHECK(cli::lineCount(misuse.err) == 1);
}
