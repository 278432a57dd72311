// SPDX-License-Identifier: MIT
// Obstacles placed with the mouse: armed from the panel, a left drag on the canvas floor
// outlines a box of columns and the release adds it (heights from the typed form), with no sand
// poured by that drag.
#include "support/app_test_support.hpp"

#include "app/application.hpp"

#include "scene/canvas_surface.hpp"

#include "sandcore/cell_grid.hpp"

#include <doctest/doctest.h>

#include <optional>

using namespace sandglass;

namespace {

std::int64_t invalidCellsIn(const sandcore::Scene& scene, int x0, int x1, int y0, int y1, int z0, int z1) {
    const sandcore::CellGrid& grid = scene.grid(sandcore::GridLevel::Lower);
    std::int64_t count = 0;
    for (int x = x0; x < x1; ++x)
        for (int y = y0; y < y1; ++y)
            for (int z = z0; z < z1; ++z) count += grid.at(x, y, z) == sandcore::kInvalid;
    return count;
}

} // namespace

TEST_CASE("obstacles: a drag on the canvas floor places the box under it, and pours no sand") {
    if (!testing::requireDisplay("obstacle placement")) return;
    std::optional<Application> app =
        testing::openApplication(testing::canvasOptions(640, 480, 40, "obstacle drag test"), "obstacle placement");
    if (!app) return;
    AppState& state = app->state();
    state.painting.obstacleMin = {0, 0, 0};
    state.painting.obstacleMax = {1, 4, 1}; // the typed form gives the height: 4 cells
    state.obstacleDrag.armed = true;
    const CanvasView view = app->canvasView();
    const CanvasSurface floor = canvasSurface(app->scene(), PaintTarget::Bottom, view.cellSize);
    const auto from = cursorOverColumn(view, floor, {8, 12});
    const auto across = cursorOverColumn(view, floor, {12, 14});
    const auto to = cursorOverColumn(view, floor, {15, 18});
    REQUIRE(from);
    REQUIRE(across);
    REQUIRE(to);
    const std::int64_t grainsBefore = app->scene().grainCount();
    app->handleObstacleDrag(from->x, from->y, true, {});
    app->handleObstacleDrag(across->x, across->y, true, {});
    CHECK(state.obstacleDrag.dragging);
    app->handleObstacleDrag(to->x, to->y, true, {});
    app->handleObstacleDrag(to->x, to->y, false, {});
    CHECK_FALSE(state.obstacleDrag.dragging);
    CHECK_FALSE(state.obstacleDrag.armed); // one box per "Place with the mouse"
    REQUIRE(state.commands.contains(Command::AddObstacle));
    app->serveCommands();
    CHECK(state.painting.obstacleMin == std::array<int, 3>{8, 0, 12});
    CHECK(state.painting.obstacleMax == std::array<int, 3>{16, 4, 19});
    CHECK(invalidCellsIn(app->scene(), 8, 16, 0, 4, 12, 19) == 8 * 4 * 7);
    CHECK(invalidCellsIn(app->scene(), 0, 40, 4, 5, 0, 40) == 0); // nothing above its height
    CHECK(app->scene().grainCount() == grainsBefore);
}

TEST_CASE("obstacles: a press over the panel does not start a box") {
    if (!testing::requireDisplay("obstacle placement")) return;
    std::optional<Application> app =
        testing::openApplication(testing::canvasOptions(640, 480, 40, "obstacle drag test"), "obstacle placement");
    if (!app) return;
    app->state().obstacleDrag.armed = true;
    const CanvasView view = app->canvasView();
    const auto over = cursorOverColumn(view, canvasSurface(app->scene(), PaintTarget::Bottom, view.cellSize), {10, 10});
    REQUIRE(over);
    app->handleObstacleDrag(over->x, over->y, true, {true, false}); // ImGui has the mouse
    CHECK_FALSE(app->state().obstacleDrag.dragging);
    CHECK(app->state().obstacleDrag.armed);
}
