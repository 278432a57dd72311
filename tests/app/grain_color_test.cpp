// SPDX-License-Identifier: MIT
// SPEC P6 / V1: a grain's own colour shows in every render mode, lit or not; grains without
// one keep the pale sand colours.
#include "support/app_test_support.hpp"

#include "app/application.hpp"

#include <doctest/doctest.h>

#include <optional>
#include <string>

using namespace sandglass;

namespace {

using testing::Pixel;

Pixel at(const RgbImage& image, int x, int y) { return testing::pixelAt(image, x, y); }

// Opens a small canvas, pours a disc of red sand at the left and default sand at the right, and
// lets it settle; the camera looks straight down.
bool paintCanvas(std::optional<Application>& app) {
    ApplicationOptions options = testing::canvasOptions(200, 200, 24, "sandglass colour test");
    options.initial.render.hull = false;
    if (!testing::openApplicationInto(app, std::move(options), "colours")) return false;
    app->camera().setView(CameraView::Top);
    PaintingSettings& painting = app->state().painting;
    painting.brushRadius = 4;
    const CanvasView view = app->canvasView();
    const CanvasSurface surface = canvasSurface(app->scene(), PaintTarget::Top, view.cellSize);
    for (int layer = 0; layer < 4; ++layer)
        for (bool red : {true, false}) {
            painting.defaultSandColor = !red;
            painting.sandColor = {0.9f, 0.1f, 0.1f};
            const auto cursor = cursorOverColumn(view, surface, {red ? 6 : 17, 12});
            REQUIRE(cursor);
            app->handleCanvasPointer({cursor->x, cursor->y, true, false, false});
            app->handleCanvasPointer({cursor->x, cursor->y, false, false, false});
            app->runSteps(60);
        }
    return true;
}

} // namespace

TEST_CASE("render: painted colours show in every mode, with and without light") {
    if (!testing::requireDisplay("colours")) return;
    std::optional<Application> app;
    if (!paintCanvas(app)) return;
    const CanvasView view = app->canvasView();
    const CanvasSurface floor = canvasSurface(app->scene(), PaintTarget::Bottom, view.cellSize);
    const auto redSpot = cursorOverColumn(view, floor, {6, 12});
    const auto sandSpot = cursorOverColumn(view, floor, {17, 12});
    REQUIRE(redSpot);
    REQUIRE(sandSpot);
    for (RenderMode mode : kRenderModes)
        for (bool light : {false, true}) {
            CAPTURE(renderModeName(mode));
            CAPTURE(light);
            app->state().render.mode = mode;
            app->state().render.lighting = light;
            app->renderFrame(0.0);
            const RgbImage image = app->captureFrame();
            // Count over a small square, since sub-grains leave gaps.
            int red = 0, sand = 0;
            for (int dy = -3; dy <= 3; ++dy)
                for (int dx = -3; dx <= 3; ++dx) {
                    const Pixel r = at(image, int(redSpot->x) + dx, int(redSpot->y) + dy);
                    red += r.r > r.g + 60 && r.r > r.b + 60 ? 1 : 0;
                    const Pixel s = at(image, int(sandSpot->x) + dx, int(sandSpot->y) + dy);
                    sand += s.r > s.b + 12 && s.g > s.b + 12 && std::abs(s.r - s.g) < 40 ? 1 : 0;
                }
            CHECK(red > 20);
            CHECK(sand > 20);
        }
}
