// SPDX-License-Identifier: MIT
// SPEC U4: long command-line work draws a progress line on an interactive terminal only.
#include "app/cli/terminal_progress.hpp"

#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

using namespace sandglass;

namespace {

std::string readAll(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

TEST_CASE("terminal progress: a bar with the rate and the time left when the end is known") {
    CHECK(progressLine("simulate", 250.0, 1000.0, "steps", 5.0) ==
          "simulate [#####...............]  25%  50 steps/s  0:15 left");
    CHECK(progressLine("simulate", 1000.0, 1000.0, "steps", 10.0) ==
          "simulate [####################] 100%  100 steps/s  0:00 left");
}

TEST_CASE("terminal progress: the count, the rate and the time so far when the end is not known") {
    CHECK(progressLine("simulate", 4200.0, 0.0, "steps", 70.0) == "simulate  4200 steps  60 steps/s  1:10");
    CHECK(progressLine("simulate", 0.0, 0.0, "steps", 0.0) == "simulate  0 steps  0 steps/s  0:00");
}

TEST_CASE("terminal progress: drawn in place and cleared at the end, nothing when not a terminal") {
    const TemporaryFolder folder;
    const std::filesystem::path shown = folder / "terminal.txt", quiet = folder / "pipe.txt";
    {
        std::FILE* out = std::fopen(shown.string().c_str(), "wb");
        REQUIRE(out != nullptr);
        TerminalProgress progress("simulate", "steps", true, out, std::chrono::milliseconds(0));
        progress.update(10.0, 100.0);
        progress.update(20.0, 100.0); // within half a second of the last: not drawn again
        progress.finish();
        std::fclose(out);
    }
    const std::string text = readAll(shown);
    CHECK(text.rfind("\r\033[Ksimulate [##", 0) == 0);
    CHECK(text.find(" 10%") != std::string::npos);
    CHECK(text.find(" 20%") == std::string::npos);
    CHECK(text.size() > 4);
    CHECK(text.substr(text.size() - 4) == "\r\033[K");
    {
        std::FILE* out = std::fopen(quiet.string().c_str(), "wb");
        REQUIRE(out != nullptr);
        TerminalProgress progress("simulate", "steps", false, out, std::chrono::milliseconds(0));
        progress.update(10.0, 100.0);
        progress.finish();
        std::fclose(out);
    }
    CHECK(readAll(quiet).empty());
}

TEST_CASE("terminal progress: a log written through the ticker keeps every line, and no terminal gets no ticker") {
    std::ostringstream log;
    {
        ElapsedTicker ticker("bench", log, false);
        ticker.stream() << "stage one\n" << "stage " << 2 << "\n";
    }
    CHECK(log.str() == "stage one\nstage 2\n");
}
