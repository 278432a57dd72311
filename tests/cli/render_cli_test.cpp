// SPEC C3 and §6: bad input to render, gui and bench gives one line on stderr and a non-zero code.
#include "support/display_guard.hpp"
#include "support/run_process.hpp"

#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
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
    for (const char* arguments :
         {"render --out x.png --mode voxels", "render --out x.png --grains-per-cell 40", "render --mode points",
          "render --out x.png --size 12", "render --out x.png --scene teapot", "gui --screenshot x.png",
          "gui --res 3 --frames 1", "bench --out", "bench --render --res 2", "render --out x.png --zoom 0"}) {
        CAPTURE(arguments);
        const Result result = runWithStderr(arguments);
        CHECK(result.exitCode != 0);
        CHECK(cli::lineCount(result.errors) == 1);
        CHECK(result.errors.rfind("sandglass: ", 0) == 0);
    }
}

TEST_CASE("cli: render writes a PNG and reports fps and frame_ms as JSON") {
    if (!sandglass::testing::requireDisplay("sandglass render")) return;
    const std::string file = "build/render-cli-test.png";
    std::remove(file.c_str());
    const std::string command = std::string(SANDGLASS_EXECUTABLE) +
                                " render --res 16 --steps 5 --size 64x64 --timed-frames 2 --json --out " + file;
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::array<char, 2048> buffer{};
    std::string output;
    while (fgets(buffer.data(), int(buffer.size()), pipe) != nullptr) output += buffer.data();
    REQUIRE(pclose(pipe) == 0);
    CHECK(output.find("\"fps\":") != std::string::npos);
    CHECK(output.find("\"frame_ms\":") != std::string::npos);
    FILE* png = std::fopen(file.c_str(), "rb");
    REQUIRE(png != nullptr);
    std::fclose(png);
}
