// SPDX-License-Identifier: MIT
// SPEC I3: Application::openFile, the one path of `sandglass FILE`, drops and recent files.
#include "support/app_test_support.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <thread>

using namespace sandglass;

namespace {

void waitForBuild(Application& app) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    app.serveCommands();
    while (app.host().building() && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        app.serveCommands();
    }
}

} // namespace

TEST_CASE("open file: a draft image opened on the hourglass builds a canvas and shows the draft on it") {
    if (!testing::requireDisplay("opening a draft")) return;
    std::optional<Application> app;
    if (!testing::openApplicationInto(app, testing::proceduralHourglassOptions(320, 240, 24, "open draft"), "opening a draft"))
        return;
    const std::string sun = std::string(SANDGLASS_SOURCE_DIR) + "/models/draft_sun.png";
    CHECK(app->openFile(sun));
    waitForBuild(*app);
    REQUIRE_FALSE(app->host().building());
    CHECK(app->host().kind() == sandcore::SceneKind::Canvas);
    CHECK(app->state().painting.loadedDraft == sun);
    // A bundled draft is not one of the user's recent files; a .sand file that fails is not either.
    CHECK(app->state().files.recentFiles.empty());
    CHECK_FALSE(app->openFile("/no/such/state.sand"));
    CHECK(app->state().files.recentFiles.empty());
    CHECK(app->host().kind() == sandcore::SceneKind::Canvas); // the running scene stays
}
