// SPDX-License-Identifier: MIT
// SPEC E4: the P key's screenshots show the sand without the panels (unless asked), go to the
// chosen folder as the first free sandglass-N.png, never replace a file, and say where they went.
#include "support/app_test_support.hpp"
#include "support/temporary_folder.hpp"

#include "app/application.hpp"

#include <doctest/doctest.h>
#include <stb_image.h>

#include <fstream>
#include <optional>

using namespace sandglass;

namespace {

ApplicationOptions hourglassWithPanels(const std::filesystem::path& screenshotFolder) {
    ApplicationOptions options = testing::proceduralHourglassOptions(480, 320, 20, "sandglass screenshot test");
    options.initial.showGui = true;
    options.screenshotFolder = screenshotFolder;
    options.frameLimit = 1; // each run() draws one more frame
    return options;
}

// The PNG's pixels, or an empty image when it cannot be read.
RgbImage readPng(const std::filesystem::path& file) {
    int width = 0, height = 0, channels = 0;
    unsigned char* data = stbi_load(file.c_str(), &width, &height, &channels, 3);
    if (!data) return {};
    RgbImage image{width, height, std::vector<std::uint8_t>(data, data + std::size_t(width) * std::size_t(height) * 3)};
    stbi_image_free(data);
    return image;
}

} // namespace

TEST_CASE("screenshot: without the panels by default, numbered in the chosen folder, never over a file") {
    TemporaryFolder folder;
    std::optional<Application> app = testing::openApplication(hourglassWithPanels(folder.path()), "screenshots");
    if (!app) return;
    // A frame as the window shows it, panels included, to compare with (ImGui sizes a new
    // window in its first frame and shows it from the second).
    for (int frame = 0; frame < 3; ++frame) app->renderFrame(0.0);
    const RgbImage shown = app->captureFrame();
    app->state().commands.push(Command::Screenshot);
    CHECK(app->run() == 0);
    const RgbImage sandOnly = readPng(folder / "sandglass-1.png");
    REQUIRE(sandOnly.width == shown.width);
    REQUIRE(sandOnly.height == shown.height);
    CHECK(app->state().files.lastScreenshot == (folder / "sandglass-1.png").string());
    CHECK(app->state().statusLine == "screenshot saved to " + (folder / "sandglass-1.png").string());
    // The panel's title bar sits at the top left; without it, that corner is the background the sand is drawn on.
    const testing::Pixel corner = testing::pixelAt(sandOnly, 100, 20), farCorner = testing::pixelAt(sandOnly, 470, 310);
    const testing::Pixel panelCorner = testing::pixelAt(shown, 100, 20);
    CHECK(corner.r == farCorner.r);
    CHECK(corner.g == farCorner.g);
    CHECK(corner.b == farCorner.b);
    INFO(panelCorner.r, " ", panelCorner.g, " ", panelCorner.b, " vs ", corner.r, " ", corner.g, " ", corner.b);
    CHECK((panelCorner.r != corner.r || panelCorner.g != corner.g || panelCorner.b != corner.b));

    // Asked to show the panels; a file of someone else's at number 2 stays as it was.
    std::ofstream(folder / "sandglass-2.png") << "not ours";
    app->state().files.screenshotWithPanel = true;
    app->state().commands.push(Command::Screenshot);
    CHECK(app->run() == 0);
    CHECK(app->state().files.lastScreenshot == (folder / "sandglass-3.png").string());
    const RgbImage withPanels = readPng(folder / "sandglass-3.png");
    REQUIRE(withPanels.width == shown.width);
    const testing::Pixel panelAgain = testing::pixelAt(withPanels, 100, 20);
    CHECK(panelAgain.r == panelCorner.r);
    CHECK(panelAgain.g == panelCorner.g);
    CHECK(panelAgain.b == panelCorner.b);
    std::ifstream kept(folder / "sandglass-2.png");
    std::string content;
    std::getline(kept, content);
    CHECK(content == "not ours");
}

TEST_CASE("screenshot: a folder that cannot be written is one line in the status line, and the app runs on") {
    TemporaryFolder folder;
    std::optional<Application> app = testing::openApplication(hourglassWithPanels(folder / "missing"), "screenshot errors");
    if (!app) return;
    app->state().commands.push(Command::Screenshot);
    CHECK(app->run() == 0);
    CHECK(app->state().statusLine.find((folder / "missing").string()) != std::string::npos);
    CHECK(app->state().statusLine.find('\n') == std::string::npos);
    CHECK(app->state().files.lastScreenshot.empty());
    CHECK(app->framesDrawn() == 1);
}
