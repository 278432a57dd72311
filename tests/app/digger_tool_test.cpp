// SPDX-License-Identifier: MIT
// The digger tool in the window: a left drag on the sandbox's floor places a blade and drags it
// through the sand, the arrow keys move it a cell, and Undo takes the whole drag back.
#include "support/app_test_support.hpp"

#include "app/application.hpp"

#include "scene/canvas_surface.hpp"

#include <doctest/doctest.h>

#include <optional>

using namespace sandglass;

TEST_CASE("digger tool: a drag pushes the sand aside, keeps every grain, and undoes as one step") {
    if (!testing::requireDisplay("digger tool")) return;
    ApplicationOptions options = testing::canvasOptions(640, 480, 40, "digger tool test");
    options.initial.scene.request.sandbox = true; // a bed 8 deep
    std::optional<Application> app = testing::openApplication(std::move(options), "digger tool");
    if (!app) return;
    AppState& state = app->state();
    state.digger.active = true;
    state.digger.depth = 4;
    const CanvasView view = app->canvasView();
    const CanvasSurface floor = canvasSurface(app->scene(), PaintTarget::Bottom, view.cellSize);
    const auto from = cursorOverColumn(view, floor, {20, 8});
    const auto to = cursorOverColumn(view, floor, {20, 30});
    REQUIRE(from);
    REQUIRE(to);
    const std::int64_t grains = app->scene().grainCount();
    const std::uint64_t before = app->scene().stateHash();
    app->handleDiggerDrag(from->x, from->y, true, {});
    REQUIRE(app->scene().bodies().size() == 1);
    CHECK(app->scene().bodies()[0].position == sandcore::Int3{20, 4, 8});
    for (int frame = 0; frame < 10; ++frame) app->handleDiggerDrag(to->x, to->y, true, {}); // 4 cells a frame
    app->handleDiggerDrag(to->x, to->y, false, {});
    CHECK_FALSE(state.digger.dragging);
    CHECK(app->scene().bodies()[0].position == sandcore::Int3{20, 4, 30});
    CHECK(app->scene().grainsPushedTotal() > 22 * 4);
    CHECK(app->scene().grainCount() == grains);
    CHECK(app->driveDiggerByKey(KeyCommand::RotateRight));
    CHECK(app->scene().bodies()[0].position == sandcore::Int3{21, 4, 30});
    CHECK(state.painting.undoSteps == 1);
    state.commands.push(Command::Undo);
    app->serveCommands();
    CHECK(app->scene().bodies().empty()); // placed by that drag, so gone with it
    CHECK(app->scene().stateHash() == before);
}
