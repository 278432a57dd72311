// SPDX-License-Identifier: MIT
// SPEC P2-P7 and R11 through the mouse path: cursor positions (projected column centres) go
// into Application::handleCanvasPointer, as the window's mouse handling sends them, and the
// grid shows exactly what the stroke should have done.
#include "support/app_test_support.hpp"
#include "support/released_columns.hpp"

#include "app/application.hpp"

#include "sandcore/cell_grid.hpp"

#include <GLFW/glfw3.h>
#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <vector>

using namespace sandglass;
using sandcore::GridLevel;

namespace {

std::optional<Application> openCanvas(int resolution = 48) {
    return testing::openApplication(testing::canvasOptions(640, 480, resolution, "sandglass painting test"), "painting");
}

// Mouse samples over column centres of the surface the settings pick: down, moves, up.
void stroke(Application& app, const std::vector<CanvasColumn>& columns, int stepsBetweenSamples = 0) {
    const PaintTarget target = app.state().painting.pickAtTarget ? PaintTarget::Bottom : PaintTarget::Top;
    const CanvasView view = app.canvasView();
    const CanvasSurface surface = canvasSurface(app.scene(), target, view.cellSize);
    glm::dvec2 last{};
    for (const CanvasColumn& column : columns) {
        const auto cursor = cursorOverColumn(view, surface, column);
        REQUIRE(cursor);
        last = *cursor;
        app.handleCanvasPointer({cursor->x, cursor->y, true, false, false});
        app.runSteps(stepsBetweenSamples);
    }
    app.handleCanvasPointer({last.x, last.y, false, false, false});
}

using support::releasedColumns;

std::set<std::pair<int, int>> joined(const std::vector<CanvasColumn>& samples) {
    std::set<std::pair<int, int>> columns{{samples.front().x, samples.front().z}};
    for (std::size_t i = 1; i < samples.size(); ++i)
        for (const CanvasColumn& c : columnsOnLine(samples[i - 1], samples[i])) columns.insert({c.x, c.z});
    return columns;
}

std::int64_t invalidCells(const sandcore::CellGrid& grid) {
    std::int64_t count = 0;
    for (sandcore::CellValue v : grid.cells()) count += v == sandcore::kInvalid ? 1 : 0;
    return count;
}

#define REQUIRE_DISPLAY()                                                         \
    if (!testing::requireDisplay("painting")) return

} // namespace

TEST_CASE("painting: a mouse stroke releases grains exactly over its joined columns, on either surface") {
    REQUIRE_DISPLAY();
    for (bool atTarget : {false, true}) {
        CAPTURE(atTarget);
        std::optional<Application> app = openCanvas();
        if (!app) return;
        app->state().painting.pickAtTarget = atTarget;
        const std::vector<CanvasColumn> samples{{4, 6}, {30, 17}, {22, 40}, {22, 40}, {9, 33}};
        const std::int64_t redraws = app->canvas().input().picker().redraws();
        stroke(*app, samples);
        const auto expected = joined(samples);
        CHECK(releasedColumns(app->scene()) == expected);
        CHECK(app->scene().grainCount() == std::int64_t(expected.size()));
        CHECK(app->canvas().input().picker().redraws() == redraws + 1); // drawn on button down only
        CHECK(app->state().painting.undoSteps == 1);
    }
}

TEST_CASE("painting: Alt or a panel under the mouse never starts a stroke") {
    REQUIRE_DISPLAY();
    std::optional<Application> app = openCanvas();
    if (!app) return;
    const CanvasView view = app->canvasView();
    const auto cursor = cursorOverColumn(view, canvasSurface(app->scene(), PaintTarget::Top, view.cellSize), {20, 20});
    REQUIRE(cursor);
    app->handleCanvasPointer({cursor->x, cursor->y, true, true, false});
    app->handleCanvasPointer({cursor->x, cursor->y, false, true, false});
    app->handleCanvasPointer({cursor->x, cursor->y, true, false, true});
    app->handleCanvasPointer({cursor->x, cursor->y, false, false, true});
    CHECK(app->scene().grainCount() == 0);
    app->handleCanvasPointer({cursor->x, cursor->y, true, false, false});
    CHECK(app->scene().grainCount() == 1);
}

TEST_CASE("painting: thin lines release one grain per distinct cell, thick lines one per sample") {
    REQUIRE_DISPLAY();
    // The mouse rests on each column for three samples; the sand falls out of the release cell
    // between samples (granular gravity 0.02 takes it a cell down in 10 steps), so the cell is
    // free again each time.
    const std::vector<CanvasColumn> samples{{10, 10}, {10, 10}, {10, 10}, {11, 10}, {11, 10}, {11, 10},
                                            {16, 12}, {16, 12}, {16, 12}};
    const std::size_t distinct = joined(samples).size();
    for (bool thin : {true, false}) {
        CAPTURE(thin);
        std::optional<Application> app = openCanvas();
        if (!app) return;
        app->state().painting.thinLines = thin;
        stroke(*app, samples, 10);
        if (thin)
            CHECK(app->scene().grainCount() == std::int64_t(distinct));
        else
            CHECK(app->scene().grainCount() == std::int64_t(distinct) + 6); // 2 more per resting column
    }
}

TEST_CASE("painting: the brush radius pours a disc of columns around each sample") {
    REQUIRE_DISPLAY();
    std::optional<Application> app = openCanvas();
    if (!app) return;
    app->state().painting.brushRadius = 2;
    stroke(*app, {{20, 20}});
    std::set<std::pair<int, int>> expected;
    for (const CanvasColumn& c : brushColumns({20, 20}, 2, 48, 48)) expected.insert({c.x, c.z});
    CHECK(releasedColumns(app->scene()) == expected);
    CHECK(expected.size() == 13);
}

TEST_CASE("painting: the eraser takes top grains and never an obstacle cell") {
    REQUIRE_DISPLAY();
    std::optional<Application> app = openCanvas();
    if (!app) return;
    PaintingSettings& painting = app->state().painting;
    painting.obstacleMin = {10, 0, 10};
    painting.obstacleMax = {20, 5, 20};
    app->state().commands.push(Command::AddObstacle);
    app->serveCommands();
    const std::int64_t obstacleCells = invalidCells(app->scene().grid(GridLevel::Lower));
    REQUIRE(obstacleCells == 10 * 5 * 10);

    // Sand on and beside the obstacle, three layers.
    painting.brushRadius = 3;
    std::vector<CanvasColumn> across;
    for (int x = 6; x <= 24; x += 3) across.push_back({x, 15});
    for (int layer = 0; layer < 3; ++layer) {
        stroke(*app, across);
        app->runSteps(120);
    }
    const std::int64_t poured = app->scene().grainCount();
    REQUIRE(poured > 0);

    // Erase over the same place many times: every grain goes, the obstacle stays whole.
    painting.erase = true;
    painting.pickAtTarget = true;
    for (int pass = 0; pass < 40; ++pass) stroke(*app, across);
    CHECK(app->scene().grainCount() < poured);
    CHECK(invalidCells(app->scene().grid(GridLevel::Lower)) == obstacleCells);
    for (int pass = 0; pass < 200 && app->scene().grainCount() > 0; ++pass)
        for (int z = 0; z < 48; z += 2) stroke(*app, {{0, z}, {47, z}});
    CHECK(app->scene().grainCount() == 0);
    CHECK(invalidCells(app->scene().grid(GridLevel::Lower)) == obstacleCells);

    app->state().commands.push(Command::ClearObstacles);
    app->serveCommands();
    CHECK(invalidCells(app->scene().grid(GridLevel::Lower)) == 0);
}

TEST_CASE("painting: undo restores the grid exactly (state hash), stroke by stroke") {
    REQUIRE_DISPLAY();
    std::optional<Application> app = openCanvas();
    if (!app) return;
    const std::uint64_t empty = app->scene().stateHash();
    stroke(*app, {{3, 3}, {40, 8}});
    app->runSteps(80);
    const std::uint64_t afterFirst = app->scene().stateHash();
    app->state().painting.erase = true;
    app->state().painting.pickAtTarget = true;
    stroke(*app, {{3, 3}, {40, 8}});
    CHECK(app->scene().stateHash() != afterFirst);
    CHECK(app->state().painting.undoSteps == 2);

    app->state().commands.push(Command::Undo);
    app->serveCommands();
    CHECK(app->scene().stateHash() == afterFirst);
    app->state().commands.push(Command::Undo);
    app->serveCommands();
    CHECK(app->scene().stateHash() == empty);
    CHECK(app->state().painting.undoSteps == 0);
    app->state().commands.push(Command::Undo);
    app->serveCommands();
    CHECK(app->state().statusLine == "nothing to undo");
    CHECK(keyCommand({}, GLFW_KEY_Z, GLFW_MOD_CONTROL) == KeyCommand::Undo);
    CHECK(keyCommand({}, GLFW_KEY_Z, 0) == KeyCommand::None);
}

TEST_CASE("painting: a bad draft image gives a one-line error and the canvas keeps painting") {
    REQUIRE_DISPLAY();
    std::optional<Application> app = openCanvas();
    if (!app) return;
    const sandglass::TemporaryFolder folder;
    const std::filesystem::path broken = folder / "broken-draft.png";
    std::ofstream(broken) << "this is not a PNG";
    CHECK_FALSE(app->loadDraft("no-such-draft.png"));
    CHECK(app->state().statusLine == "no-such-draft.png: no such file");
    CHECK_FALSE(app->loadDraft(broken.string()));
    CHECK(app->state().statusLine.find(broken.string() + ": not a readable PNG or JPEG image") == 0);
    CHECK(app->state().statusLine.find('\n') == std::string::npos);
    CHECK(app->canvas().input().draft() == nullptr);

    const std::string sun = std::string(SANDGLASS_SOURCE_DIR) + "/models/draft_sun.png";
    REQUIRE(app->loadDraft(sun));
    CHECK_FALSE(app->loadDraft(broken.string())); // the sun stays the draft
    REQUIRE(app->canvas().input().draft() != nullptr);
    CHECK(app->canvas().input().draft()->path() == sun);
    CHECK(app->state().painting.loadedDraft == sun);

    // Still paints, and with "colour from draft" each grain has the draft's colour at its column.
    app->state().painting.colorFromDraft = true;
    stroke(*app, {{5, 5}, {40, 44}});
    const auto& grains = app->scene().grains();
    REQUIRE(grains.size() > 0);
    const auto& upper = app->scene().grid(GridLevel::Upper);
    const sandcore::Int3 s = upper.size();
    int checked = 0;
    for (int z = 0; z < s.z; ++z)
        for (int x = 0; x < s.x; ++x) {
            const sandcore::CellValue id = upper.at(x, s.y - 1, z);
            if (id < 0) continue;
            CHECK(grains.color[std::size_t(id)] ==
                  app->canvas().input().draft()->colorAt((x + 0.5) / s.x, (z + 0.5) / s.z));
            ++checked;
        }
    CHECK(checked == std::int64_t(grains.size()));
}

TEST_CASE("painting: dropped .png and .jpg files are drafts, other files models") {
    CHECK(isDraftImageFile("a/b/sketch.PNG"));
    CHECK(isDraftImageFile("photo.jpeg"));
    CHECK(isDraftImageFile("photo.jpg"));
    CHECK_FALSE(isDraftImageFile("teapot.obj"));
    const auto drafts = listDraftFiles(std::filesystem::path(SANDGLASS_SOURCE_DIR) / "models");
    REQUIRE(drafts.size() >= 2);
    CHECK(std::filesystem::path(drafts[0]).filename() == "draft_rainbow.jpg");
    CHECK(std::filesystem::path(drafts[1]).filename() == "draft_sun.png");
}

TEST_CASE("painting: undo back to a different obstacle of the same count rebuilds the glass hull") {
    REQUIRE_DISPLAY();
    std::optional<Application> app = openCanvas();
    if (!app) return;
    PaintingSettings& painting = app->state().painting;
    painting.obstacleMin = {4, 0, 4};
    painting.obstacleMax = {10, 5, 10};
    app->state().commands.push(Command::AddObstacle);
    app->serveCommands();
    const std::vector<sandcore::CellBox> first = app->scene().obstacles(GridLevel::Lower);
    REQUIRE(first.size() == 1);
    stroke(*app, {{20, 20}, {30, 20}}); // its snapshot holds the first obstacle

    // Swap the obstacle for another one: the count stays 1.
    app->state().commands.push(Command::ClearObstacles);
    app->serveCommands();
    painting.obstacleMin = {30, 0, 30};
    painting.obstacleMax = {40, 8, 40};
    app->state().commands.push(Command::AddObstacle);
    app->serveCommands();
    REQUIRE(app->scene().obstacles(GridLevel::Lower).size() == 1);
    app->renderFrame(0.0); // the next frame draws the new layout
    CHECK(app->renderer().hullShowsObstaclesOf(app->scene()));

    app->state().commands.push(Command::Undo);
    app->serveCommands();
    REQUIRE(app->scene().obstacles(GridLevel::Lower).size() == 1);
    CHECK(app->scene().obstacles(GridLevel::Lower)[0].min == first[0].min);
    app->renderFrame(0.0);
    CHECK(app->renderer().hullShowsObstaclesOf(app->scene())); // the hull shows the first box again
}
