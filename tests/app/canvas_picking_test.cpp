// SPDX-License-Identifier: MIT
// SPEC P1: the integer id picker finds exactly the column under the cursor, for a canvas past
// the thesis's 65k-cell limit, in several views and on both surfaces, through the same lookup
// the mouse uses; the id image is drawn once per view and reused while the view stays.
#include "support/app_test_support.hpp"

#include "app/application.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

using namespace sandglass;

namespace {

constexpr int kWidth = 1280, kHeight = 800;

std::optional<Application> openCanvas(int resolution) {
    return testing::openApplication(testing::canvasOptions(kWidth, kHeight, resolution, "sandglass picking test"), "picking");
}

glm::dvec2 toPixels(const CanvasView& view, const CanvasSurface& surface, double x, double z) {
    const glm::vec4 clip = view.projection * view.view *
                           glm::vec4(surface.originX + float(x) * surface.cellSize, surface.y,
                                     surface.originZ + float(z) * surface.cellSize, 1.0f);
    return {(double(clip.x / clip.w) * 0.5 + 0.5) * view.framebufferWidth,
            (0.5 - double(clip.y / clip.w) * 0.5) * view.framebufferHeight};
}

// True when the pixel that holds p lies wholly inside the projected (convex) cell: then that
// pixel's centre is in the cell whatever p's offset, and the rasterised id must be exact.
// Cells less than a pixel deep on screen cannot be told apart by any picker and are skipped.
bool pixelInside(const std::array<glm::dvec2, 4>& quad, glm::dvec2 p) {
    const glm::dvec2 pixel(std::floor(p.x), std::floor(p.y));
    int sign = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec2 a = quad[i], edge = quad[(i + 1) % 4] - a;
        for (const glm::dvec2 corner : {pixel, pixel + glm::dvec2(1, 0), pixel + glm::dvec2(0, 1), pixel + glm::dvec2(1, 1)}) {
            const double cross = edge.x * (corner.y - a.y) - edge.y * (corner.x - a.x);
            const int s = cross > 0.0 ? 1 : -1;
            if (sign == 0) sign = s;
            if (s != sign || cross == 0.0) return false;
        }
    }
    return true;
}

struct PickCounts {
    int onScreen = 0, resolvable = 0, wrong = 0;
    int resolvableAbove65535 = 0; ///< ids the thesis's RGB code could not hold
};

PickCounts checkView(Application& app, PaintTarget target) {
    app.state().painting.pickAtTarget = target == PaintTarget::Bottom;
    const CanvasView view = app.canvasView();
    const CanvasSurface surface = canvasSurface(app.scene(), target, view.cellSize);
    PickCounts counts;
    for (int z = 0; z < surface.columnsZ; ++z)
        for (int x = 0; x < surface.columnsX; ++x) {
            const std::optional<glm::dvec2> cursor = cursorOverColumn(view, surface, {x, z});
            REQUIRE(cursor);
            const glm::dvec2 centre = toPixels(view, surface, x + 0.5, z + 0.5);
            if (centre.x < 0 || centre.y < 0 || centre.x >= view.framebufferWidth || centre.y >= view.framebufferHeight)
                continue;
            ++counts.onScreen;
            const std::optional<CanvasColumn> picked = app.columnUnderCursor(cursor->x, cursor->y);
            const std::array<glm::dvec2, 4> quad{toPixels(view, surface, x, z), toPixels(view, surface, x + 1, z),
                                                 toPixels(view, surface, x + 1, z + 1),
                                                 toPixels(view, surface, x, z + 1)};
            if (pixelInside(quad, centre)) {
                ++counts.resolvable;
                if (z * surface.columnsX + x + 1 > 65535) ++counts.resolvableAbove65535;
                if (!picked || !(*picked == CanvasColumn{x, z})) ++counts.wrong;
            }
        }
    return counts;
}

} // namespace

TEST_CASE("picking: the id at each column's projected centre is that column (256 x 256 canvas)") {
    if (!testing::requireDisplay("picking")) return;
    std::optional<Application> app = openCanvas(256);
    if (!app) return;
    REQUIRE(app->scene().grid(sandcore::GridLevel::Upper).size().x == 256);
    REQUIRE(app->scene().grid(sandcore::GridLevel::Upper).size().z == 256);
    struct ViewCase {
        std::string name;
        CameraView view;
        float yaw, pitch, zoom;
    };
    // At the framing distance a 256-column canvas seen at 20 degrees has cells under a pixel
    // deep, which no picker can tell apart, so the slanted views are zoomed in; the front view
    // looks edge-on at the canvas and is raised by 30 degrees.
    const ViewCase views[] = {{"perspective", CameraView::Perspective, 0.0f, 0.2f, 0.5f},
                              {"front", CameraView::Front, 0.0f, 0.52f, 0.5f},
                              {"top", CameraView::Top, 0.0f, 0.0f, 1.0f},
                              {"rotated", CameraView::Perspective, 2.3f, 0.45f, 0.8f}};
    for (const ViewCase& v : views)
        for (PaintTarget target : {PaintTarget::Top, PaintTarget::Bottom}) {
            CAPTURE(v.name);
            CAPTURE(int(target));
            app->camera().setView(v.view);
            app->camera().rotate(v.yaw, v.pitch);
            app->camera().zoom(v.zoom);
            const std::int64_t redrawsBefore = app->canvas().input().picker().redraws();
            const PickCounts counts = checkView(*app, target);
            MESSAGE(v.name << " target " << int(target) << ": " << counts.onScreen << " on screen, "
                           << counts.resolvable << " resolvable");
            CHECK(counts.wrong == 0);
            // Exactness is checked on many cells, not a few: most on-screen cells are resolvable.
            CHECK(counts.resolvable > 5000);
            // Thousands of lookups, one drawing and read-back of the id image.
            CHECK(app->canvas().input().picker().redraws() == redrawsBefore + 1);
        }
}

TEST_CASE("picking: no cell limit, ids above 65535 come back exactly (320 x 320 canvas)") {
    if (!testing::requireDisplay("picking")) return;
    std::optional<Application> app = openCanvas(320);
    if (!app) return;
    REQUIRE(app->scene().grid(sandcore::GridLevel::Upper).size().x == 320);
    app->camera().setView(CameraView::Top);
    app->camera().zoom(0.9f); // closer, so most of the 320 x 320 columns cover a pixel centre
    const PickCounts counts = checkView(*app, PaintTarget::Top);
    CHECK(counts.wrong == 0);
    CHECK(counts.resolvableAbove65535 > 20000);
}

TEST_CASE("picking: a new view or window draws the id image again, the same view does not") {
    if (!testing::requireDisplay("picking")) return;
    std::optional<Application> app = openCanvas(32);
    if (!app) return;
    const std::int64_t start = app->canvas().input().picker().redraws();
    app->columnUnderCursor(kWidth / 2.0, kHeight / 2.0);
    app->columnUnderCursor(kWidth / 2.0 + 5.0, kHeight / 2.0);
    CHECK(app->canvas().input().picker().redraws() == start + 1);
    app->camera().rotate(0.1f, 0.0f);
    app->columnUnderCursor(kWidth / 2.0, kHeight / 2.0);
    CHECK(app->canvas().input().picker().redraws() == start + 2);
    app->state().painting.pickAtTarget = true; // the other surface is another image
    app->columnUnderCursor(kWidth / 2.0, kHeight / 2.0);
    CHECK(app->canvas().input().picker().redraws() == start + 3);
}

TEST_CASE("picking: cursor coordinates scale to framebuffer pixels on HiDPI screens") {
    int x = 0, y = 0;
    cursorToFramebuffer(100.5, 40.25, 800, 600, 1600, 1200, x, y);
    CHECK(x == 201);
    CHECK(y == 80);
    cursorToFramebuffer(799.9, 599.9, 800, 600, 800, 600, x, y);
    CHECK(x == 799);
    CHECK(y == 599);
}

TEST_CASE("picking: stays exact when the image is shifted beside the panel (lens shift)") {
    if (!testing::requireDisplay("picking")) return;
    std::optional<Application> app = openCanvas(64);
    if (!app) return;
    app->camera().setView(CameraView::Top);
    const CanvasView plain = app->canvasView();
    const CanvasSurface surface = canvasSurface(app->scene(), PaintTarget::Top, plain.cellSize);
    const glm::dvec2 before = toPixels(plain, surface, 32.0, 32.0);
    app->camera().setLensShift(0.3f);
    const CanvasView shifted = app->canvasView();
    const glm::dvec2 after = toPixels(shifted, surface, 32.0, 32.0);
    // The canvas centre moves right by 0.3 of half the width, and not up or down.
    CHECK(after.x - before.x == doctest::Approx(0.15 * plain.framebufferWidth).epsilon(0.01));
    CHECK(after.y == doctest::Approx(before.y).epsilon(0.001));
    const PickCounts counts = checkView(*app, PaintTarget::Top);
    CHECK(counts.wrong == 0);
    CHECK(counts.resolvable > 1000);
}
