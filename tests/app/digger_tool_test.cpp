// SPDX-License-Identifier: MIT
// The digger tool in the window: a left drag on the sandbox's floor places a blade and drags it
// through the sand, the arrow keys move it a cell, and Undo takes the whole drag back; a model
// file chosen in the panel becomes the body.
#include "support/app_test_support.hpp"

#include "app/application.hpp"

#include "scene/canvas_surface.hpp"
#include "scene/data_paths.hpp"
#include "scene/digger.hpp"
#include "support/temporary_folder.hpp"

#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

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

TEST_CASE("digger tool: a model file becomes the body at the next drag, a bad file leaves everything as it was") {
    if (!testing::requireDisplay("digger tool")) return;
    ApplicationOptions options = testing::canvasOptions(640, 480, 48, "digger model body test");
    options.initial.scene.request.sandbox = true;
    std::optional<Application> app = testing::openApplication(std::move(options), "digger tool");
    if (!app) return;
    AppState& state = app->state();
    state.digger.active = true;
    const CanvasView view = app->canvasView();
    const CanvasSurface floor = canvasSurface(app->scene(), PaintTarget::Bottom, view.cellSize);
    const auto at = cursorOverColumn(view, floor, {24, 24});
    REQUIRE(at);

    // A file that is no model: the one-line reason, the blade still the body, the scene untouched.
    TemporaryFolder folder;
    const std::filesystem::path bad = folder / "not_a_model.obj";
    std::ofstream(bad) << "this is not a mesh\n";
    const std::uint64_t before = app->scene().stateHash();
    state.digger.modelPath = bad.string();
    state.commands.push(Command::LoadDiggerBody);
    app->serveCommands();
    CHECK(state.statusLine.rfind("digger body: ", 0) == 0);
    CHECK(state.statusLine.find('\n') == std::string::npos);
    CHECK(state.digger.body == 0);
    CHECK(state.digger.loadedModel.empty());
    CHECK(app->scene().stateHash() == before);
    app->handleDiggerDrag(at->x, at->y, true, {});
    app->handleDiggerDrag(at->x, at->y, false, {});
    REQUIRE(app->scene().bodies().size() == 1);
    const int width = app->scene().grid(sandcore::GridLevel::Lower).size().x;
    const sandcore::InsideMask blade = makeDigBodyShape("blade", width, sandcore::defaultSandboxBedDepth(sandcore::canvasSettingsForWidth(width)));
    CHECK(app->scene().bodies()[0].shape.inside == blade.inside);

    // A good one: voxelized as --dig-body voxelizes it, and the next drag swaps the blade for it.
    const std::string ball = (modelsFolder() / "ball.obj").string();
    state.digger.modelPath = ball;
    state.commands.push(Command::LoadDiggerBody);
    app->serveCommands();
    CHECK(state.digger.body == 3);
    CHECK(state.digger.loadedModel == ball);
    CHECK(state.statusLine.find("ball.obj") != std::string::npos);
    const std::int64_t grains = app->scene().grainCount();
    app->handleDiggerDrag(at->x, at->y, true, {});
    app->handleDiggerDrag(at->x, at->y, false, {});
    REQUIRE(app->scene().bodies().size() == 1);
    const sandcore::InsideMask expected = makeDigBodyShape(ball, width, 0);
    CHECK(app->scene().bodies()[0].shape.size == expected.size);
    CHECK(app->scene().bodies()[0].shape.inside == expected.inside);
    CHECK(app->scene().grainCount() == grains);

    // A bad file now keeps the ball.
    state.digger.modelPath = bad.string();
    state.commands.push(Command::LoadDiggerBody);
    app->serveCommands();
    CHECK(state.digger.body == 3);
    CHECK(state.digger.loadedModel == ball);
    CHECK(app->scene().bodies()[0].shape.inside == expected.inside);
}
