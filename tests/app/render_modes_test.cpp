// SPDX-License-Identifier: MIT
// SPEC V1, V3, V5, C3: every render mode, with and without light, puts sand where the grains
// are and leaves the background elsewhere.
#include "support/app_test_support.hpp"

#include "app/application.hpp"

#include "sandcore/display_positions.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
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

// A sub-grain's quad is two triangles over 4 shared corners: whatever the draw path, every grain
// must come out as one full disc, also when several are drawn in one call (a corner taken from
// another grain shows as a crescent), and a sprite too.
namespace {

// Sand pixels of one half of the image (x below or above the middle) fill a disc around their centre.
void checkDisc(const RgbImage& image, bool rightHalf) {
    CAPTURE(rightHalf);
    auto inHalf = [&](int x) { return (x >= image.width / 2) == rightHalf; };
    double sumX = 0.0, sumY = 0.0;
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (inHalf(x) && looksLikeSand(at(image, x, y))) sumX += x, sumY += y, ++count;
    REQUIRE(count > 150);
    const double cx = sumX / count, cy = sumY / count;
    double farthest = 0.0;
    int left = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (inHalf(x) && looksLikeSand(at(image, x, y))) {
                farthest = std::max(farthest, std::hypot(x - cx, y - cy));
                left += x < cx ? 1 : 0;
            }
    // A disc fills the circle around its centre; a crescent or a lone triangle does not.
    CHECK(double(count) > 0.85 * 3.14159265 * farthest * farthest);
    CHECK(std::abs(2 * left - count) < count / 10);
}

} // namespace

TEST_CASE("render: grains are round discs as sprites, billboards and pseudo-billboards, drawn together") {
    if (!testing::requireDisplay("drawing")) return;
    for (RenderMode mode : {RenderMode::Sprites, RenderMode::Billboards, RenderMode::PseudoBillboards})
        for (GrainPath path : {GrainPath::GpuInterpolated, GrainPath::CpuFullUpload}) {
            CAPTURE(renderModeName(mode));
            CAPTURE(int(path));
            ApplicationOptions options = testing::canvasOptions(240, 120, 24, "sandglass round grains test");
            options.initial.render.mode = mode;
            options.initial.render.grainsPerCell = 1;
            options.initial.render.jitter = 0.0f;
            options.initial.render.pointSize = 30.0f;
            options.initial.render.grainPath = path;
            options.initial.simulationRunning = false;
            std::optional<Application> app = testing::openApplication(std::move(options), "round grains");
            if (!app) return;
            // Two grains side by side along x, two cells apart, seen from the front.
            const sandcore::CellGrid& lower = app->scene().grid(sandcore::GridLevel::Lower);
            const int x0 = lower.size().x / 2 - 2, z = lower.size().z / 2;
            for (int x : {x0, x0 + 4})
                REQUIRE(app->host().editScene().addGrain(sandcore::GridLevel::Lower, lower.index(x, 1, z)) >= 0);
            const sandcore::Int3 origin = app->scene().gridOrigin(sandcore::GridLevel::Lower);
            const float size = app->state().render.cellSize;
            auto corner = [&](float dx, float dy, float dz) {
                return sandcore::Vec3{(float(origin.x + x0) + dx) * size, (float(origin.y + 1) + dy) * size,
                                      (float(origin.z + z) + dz) * size};
            };
            app->camera().setView(CameraView::Front);
            app->camera().frame(corner(-0.5f, -0.5f, 0.0f), corner(5.5f, 1.5f, 1.0f));
            app->renderFrame(0.0);
            const RgbImage image = app->captureFrame();
            checkDisc(image, false);
            checkDisc(image, true);
        }
}
