// SPDX-License-Identifier: MIT
// A moving body in pixels: drawn by the renderer as an opaque solid with depth test, on both
// grain paths. A blade standing out of the sandbox's bed hides the sand behind it (the same
// pixel is sand once it is lifted out), and a ball buried in the bed is hidden by the sand over it.
#include "support/app_test_support.hpp"

#include "app/application.hpp"
#include "scene/digger.hpp"

#include "sandcore/moving_body.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <optional>

using namespace sandglass;

namespace {

constexpr int kSize = 320;
constexpr int kResolution = 40; // the sandbox's bed is 8 deep

using testing::ScreenPoint;

// Where a point inside a cell of the lower grid lands on the frame.
ScreenPoint project(Application& app, glm::vec3 cell) {
    return testing::projectToFrame(app, cell * app.state().render.cellSize, kSize);
}

// The body's painted steel against the warm sand and the white background.
bool steel(testing::Pixel p) { return p.b > p.r + 12; }
bool sand(testing::Pixel p) { return p.r > p.b + 20; }

testing::Pixel drawnAt(Application& app, ScreenPoint at) {
    app.renderFrame(0.0);
    const RgbImage frame = app.captureFrame();
    REQUIRE(frame.width == kSize);
    const testing::Pixel p = testing::pixelAt(frame, at.x, at.y);
    MESSAGE("pixel " << at.x << "," << at.y << ": " << p.r << " " << p.g << " " << p.b); // with -s
    return p;
}

void checkBodyDrawnWithDepth(GrainPath path) {
    ApplicationOptions options = testing::canvasOptions(kSize, kSize, kResolution, "body drawing test");
    options.initial.scene.request.sandbox = true;
    options.initial.render.grainPath = path;
    std::optional<Application> app = testing::openApplication(std::move(options), "body drawing");
    if (!app) return;
    const int width = app->scene().grid(sandcore::GridLevel::Lower).size().x;

    // A blade across the middle, from the floor to well above the bed.
    const sandcore::InsideMask blade = sandcore::makeBladeShape(width / 4, 16, 2);
    const sandcore::Int3 middle{width / 2, 0, width / 2};
    REQUIRE(app->host().editLayout().addBody({blade, middle, 0}) == 0);
    const ScreenPoint bladeTop = project(*app, {float(middle.x) + 0.5f, 14.5f, float(middle.z)});
    CHECK(steel(drawnAt(*app, bladeTop)));
    app->host().editLayout().removeBody(0);
    CHECK(sand(drawnAt(*app, bladeTop))); // what the blade hid

    // A ball on the floor under the bed: the sand above it is what shows.
    const sandcore::InsideMask ball = sandcore::makeBallShape(5);
    const sandcore::Int3 buried{width / 2, 0, width / 4};
    REQUIRE(app->host().editLayout().addBody({ball, buried, 0}) == 0);
    CHECK(app->renderer().bodyTriangles() == 0); // not drawn yet
    const ScreenPoint ballCentre = project(*app, {float(buried.x) + 0.5f, 2.5f, float(buried.z) + 0.5f});
    CHECK(sand(drawnAt(*app, ballCentre)));
    CHECK(app->renderer().bodyTriangles() > 0); // drawn, and hidden by the sand in front
}

} // namespace

TEST_CASE("render: a moving body is an opaque solid, depth-tested against the sand, on the GPU grain path") {
    if (!testing::requireDisplay("body drawing")) return;
    checkBodyDrawnWithDepth(GrainPath::GpuInterpolated);
}

TEST_CASE("render: a moving body is an opaque solid, depth-tested against the sand, on the CPU grain path") {
    if (!testing::requireDisplay("body drawing")) return;
    checkBodyDrawnWithDepth(GrainPath::CpuFullUpload);
}
