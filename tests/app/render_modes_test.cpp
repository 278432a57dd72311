// SPEC V1, V3, V5, C3: every render mode, with and without light, puts sand where the grains
// are and leaves the background elsewhere.
#include "support/app_test_support.hpp"

#include "app/application.hpp"

#include "sandcore/display_positions.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <optional>
#include <vector>

using namespace sandglass;

namespace {

using testing::Pixel;

Pixel at(const RgbImage& image, int x, int y) { return testing::pixelAt(image, x, y); }

// Sand is yellow: red and green clearly above blue, lit or not; the glass is bluish, the
// backgrounds grey.
bool looksLikeSand(Pixel p) { return p.r > p.b + 12 && p.g > p.b + 12; }

ApplicationOptions smallHourglass(RenderMode mode, bool light, bool black) {
    ApplicationOptions options;
    options.window = {160, 160, false, false, "sandglass test"};
    options.offscreen = true;
    options.initial.showGui = false;
    options.initial.scene.request.resolution = 24;
    options.initial.render.mode = mode;
    options.initial.render.lighting = light;
    options.initial.render.blackBackground = black;
    options.stepsBeforeStart = 40; // sand in both bulbs
    return options;
}

struct ScreenBox {
    int minX = 1 << 30, minY = 1 << 30, maxX = -1, maxY = -1;
};

// Where the grains land on screen, from the same camera the renderer used.
ScreenBox grainsOnScreen(Application& app, int width, int height, std::vector<std::pair<int, int>>& points) {
    const sandcore::Scene& scene = app.scene();
    const RenderSettings& render = app.state().render;
    std::vector<sandcore::Vec3> positions(scene.grains().size());
    sandcore::writeDisplayPositions(scene, app.displayStepFraction(), {render.cellSize, render.jitter}, positions);
    const glm::mat4 viewProjection = app.camera().projection(float(width) / float(height)) * app.camera().view();
    ScreenBox box;
    for (const sandcore::Vec3& p : positions) {
        const glm::vec4 clip = viewProjection * glm::vec4(p.x, p.y, p.z, 1.0f);
        const int x = int((clip.x / clip.w * 0.5f + 0.5f) * float(width));
        const int y = int((0.5f - clip.y / clip.w * 0.5f) * float(height)); // image rows run downwards
        points.emplace_back(x, y);
        box.minX = std::min(box.minX, x), box.maxX = std::max(box.maxX, x);
        box.minY = std::min(box.minY, y), box.maxY = std::max(box.maxY, y);
    }
    return box;
}

void checkMode(RenderMode mode, bool light, bool black) {
    CAPTURE(renderModeName(mode));
    CAPTURE(light);
    CAPTURE(black);
    std::optional<Application> app = testing::openApplication(smallHourglass(mode, light, black), "drawing");
    if (!app) return;
    app->renderFrame(0.0);
    const RgbImage image = app->captureFrame();
    REQUIRE(image.width == 160);
    REQUIRE(image.height == 160);

    std::vector<std::pair<int, int>> points;
    const ScreenBox box = grainsOnScreen(*app, image.width, image.height, points);
    REQUIRE(box.maxX > box.minX);

    // Most grains' own pixels show sand (the rest are hidden in gaps between sub-grains).
    int sandAtGrains = 0;
    for (auto [x, y] : points)
        if (x >= 0 && y >= 0 && x < image.width && y < image.height && looksLikeSand(at(image, x, y))) ++sandAtGrains;
    CHECK(sandAtGrains > int(points.size()) * 6 / 10);

    // Outside the grains' screen box (plus a sub-grain's reach) there is no sand at all, and
    // the corners are the chosen background.
    const int margin = 6;
    int sandOutside = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const bool inside = x >= box.minX - margin && x <= box.maxX + margin && y >= box.minY - margin &&
                                y <= box.maxY + margin;
            if (!inside && looksLikeSand(at(image, x, y))) ++sandOutside;
        }
    CHECK(sandOutside == 0);
    const int background = black ? 0 : 255;
    for (auto [x, y] : {std::pair{0, 0}, std::pair{159, 0}, std::pair{0, 159}, std::pair{159, 159}}) {
        const Pixel p = at(image, x, y);
        CHECK(p.r == background);
        CHECK(p.g == background);
        CHECK(p.b == background);
    }
}

} // namespace

TEST_CASE("render: every mode with and without light draws sand where the grains are") {
    if (!testing::requireDisplay("drawing")) return;
    for (RenderMode mode : kRenderModes)
        for (bool light : {false, true}) checkMode(mode, light, false);
}

TEST_CASE("render: black background keeps the sand and turns the rest black") {
    if (!testing::requireDisplay("drawing")) return;
    checkMode(RenderMode::PseudoBillboards, true, true);
    checkMode(RenderMode::Points, false, true);
}
