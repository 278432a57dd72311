// SPDX-License-Identifier: MIT
// P2-P7 through the painter: the same path the mouse takes after picking.
#include "scene/sand_painter.hpp"

#include "sandcore/scenes.hpp"

#include "support/released_columns.hpp"

#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <set>

using namespace sandglass;
using sandcore::GridLevel;

namespace {
sandcore::Scene smallCanvas() { return sandcore::makeCanvasScene({{16, 3, 16}, {16, 10, 16}}); }

using support::releasedColumns;
} // namespace

TEST_CASE("a stroke releases grains exactly over the columns of its joined line") {
    sandcore::Scene scene = smallCanvas();
    SandPainter painter;
    PaintSettings settings;
    painter.beginStroke(scene, {2, 3}, settings);
    painter.continueStroke(scene, {9, 6}, settings); // a fast mouse: 7 columns apart
    painter.endStroke();
    std::set<std::pair<int, int>> expected;
    for (const CanvasColumn& c : columnsOnLine({2, 3}, {9, 6})) expected.insert({c.x, c.z});
    CHECK(expected.size() == 8);
    CHECK(releasedColumns(scene) == expected);
    CHECK(scene.grainCount() == 8);
    CHECK(painter.grainsReleased() == 8);
}

TEST_CASE("joined lines have no gaps: each column touches the previous one") {
    const auto line = columnsOnLine({0, 0}, {13, -5});
    CHECK(line.front() == CanvasColumn{0, 0});
    CHECK(line.back() == CanvasColumn{13, -5});
    for (std::size_t i = 1; i < line.size(); ++i) {
        CHECK(std::abs(line[i].x - line[i - 1].x) <= 1);
        CHECK(std::abs(line[i].z - line[i - 1].z) <= 1);
    }
    CHECK(line.size() == 14);
}

TEST_CASE("thin lines release one grain per distinct column, thick lines one per sample") {
    for (bool thin : {true, false}) {
        CAPTURE(thin);
        sandcore::Scene scene = smallCanvas();
        SandPainter painter;
        PaintSettings settings;
        settings.thinLines = thin;
        painter.beginStroke(scene, {5, 5}, settings);
        // A released grain leaves its cell within 10 steps (granular gravity 0.02: g n^2 / 2 >= 1),
        // so the release cell is free again at the next sample.
        constexpr int kStepsBetweenSamples = 10;
        const auto fallAway = [&] {
            for (int i = 0; i < kStepsBetweenSamples; ++i) scene.step();
        };
        for (int sample = 0; sample < 6; ++sample) {
            fallAway();
            painter.continueStroke(scene, {5, 5}, settings);
        }
        fallAway();
        painter.continueStroke(scene, {6, 5}, settings);
        painter.endStroke();
        CHECK(painter.grainsReleased() == (thin ? 2 : 8));
        CHECK(scene.grainCount() == (thin ? 2 : 8));
    }
}

TEST_CASE("a brush radius releases a disc of columns, clipped to the canvas") {
    const auto disc = brushColumns({5, 5}, 2, 16, 16);
    CHECK(disc.size() == 13); // radius 2: 1 + 4 + 4 + 4
    CHECK(brushColumns({0, 0}, 2, 16, 16).size() == 6);
    sandcore::Scene scene = smallCanvas();
    SandPainter painter;
    PaintSettings settings;
    settings.brushRadius = 2;
    painter.beginStroke(scene, {5, 5}, settings);
    CHECK(scene.grainCount() == 13);
}

TEST_CASE("the eraser takes the top grain of a column and never an obstacle cell") {
    sandcore::Scene scene = smallCanvas();
    scene.addObstacle(GridLevel::Lower, {{4, 0, 4}, {7, 3, 7}});
    const auto& lower = scene.grid(GridLevel::Lower);
    // Sand on the obstacle at (5, 3, 5) and (5, 4, 5), and on the floor beside it.
    REQUIRE(scene.addGrain(GridLevel::Lower, lower.index(5, 3, 5)) >= 0);
    REQUIRE(scene.addGrain(GridLevel::Lower, lower.index(5, 4, 5)) >= 0);
    REQUIRE(scene.addGrain(GridLevel::Lower, lower.index(9, 0, 9)) >= 0);
    SandPainter painter;
    PaintSettings erase;
    erase.action = PaintAction::Erase;
    painter.beginStroke(scene, {5, 5}, erase);
    CHECK(lower.at(5, 4, 5) == sandcore::kEmpty); // the top grain went first
    CHECK(lower.at(5, 3, 5) >= 0);
    painter.continueStroke(scene, {5, 5}, erase);
    CHECK(lower.at(5, 3, 5) == sandcore::kEmpty);
    for (int i = 0; i < 5; ++i) painter.continueStroke(scene, {5, 5}, erase); // nothing left but the obstacle
    painter.endStroke();
    for (int y = 0; y < 3; ++y) CHECK(lower.at(5, y, 5) == sandcore::kInvalid);
    CHECK(scene.grainCount() == 1);
    CHECK(painter.grainsErased() == 2);
}

TEST_CASE("undo restores the scene exactly as it was before the last stroke") {
    sandcore::Scene scene = smallCanvas();
    SandPainter painter;
    PaintSettings settings;
    painter.beginStroke(scene, {3, 3}, settings);
    painter.continueStroke(scene, {8, 3}, settings);
    painter.endStroke();
    for (int i = 0; i < 20; ++i) scene.step();
    const std::uint64_t before = scene.stateHash();
    const auto stepsBefore = scene.counters().stepsDone;

    painter.beginStroke(scene, {10, 10}, settings);
    for (int i = 0; i < 5; ++i) {
        scene.step();
        painter.continueStroke(scene, {10, 12 - i}, settings);
    }
    painter.endStroke();
    REQUIRE(scene.stateHash() != before);
    CHECK(painter.undo(scene));
    CHECK(scene.stateHash() == before);
    CHECK(scene.counters().stepsDone == stepsBefore);
    // The future after an undo is the same as if the stroke had never happened.
    sandcore::Scene reference = smallCanvas();
    SandPainter again;
    again.beginStroke(reference, {3, 3}, settings);
    again.continueStroke(reference, {8, 3}, settings);
    again.endStroke();
    for (int i = 0; i < 20; ++i) reference.step();
    for (int i = 0; i < 50; ++i) {
        scene.step();
        reference.step();
    }
    CHECK(scene.stateHash() == reference.stateHash());
    CHECK(painter.undo(scene));   // the first stroke
    CHECK(scene.grainCount() == 0);
    CHECK(!painter.undo(scene));  // nothing left
}

TEST_CASE("undo history is capped by memory as well as by count, and always keeps the last stroke") {
    sandcore::Scene scene = smallCanvas();
    PaintSettings settings;
    const std::size_t oneSnapshot = snapshotBytes(scene.snapshot());
    REQUIRE(oneSnapshot > 0);
    // An empty 16-wide canvas: 16*3*16 + 16*10*16 cells of 4 bytes, no grains, no obstacles.
    CHECK(oneSnapshot == (16 * 3 * 16 + 16 * 10 * 16) * sizeof(sandcore::CellValue));

    // The history keeps compressed snapshots (E3): far below the raw size, and limits apply to
    // the compressed bytes. A dry run measures what each of six strokes keeps.
    std::vector<std::size_t> kept;
    {
        sandcore::Scene dry = smallCanvas();
        for (int stroke = 0; stroke < 6; ++stroke) {
            kept.push_back(CompressedSnapshot(dry).bytes());
            releaseGrain(dry, {stroke, 2}, 0);
        }
    }
    CHECK(kept.front() * 10 < oneSnapshot);
    // Room for the newest three and half of another.
    SandPainter painter(UndoLimits{32, kept[3] + kept[4] + kept[5] + kept[2] / 2});
    std::vector<std::uint64_t> hashes;
    for (int stroke = 0; stroke < 6; ++stroke) {
        hashes.push_back(scene.stateHash());
        painter.beginStroke(scene, {stroke, 2}, settings);
        painter.endStroke();
        CHECK(painter.undoBytes() <= painter.undoLimits().maxBytes);
    }
    CHECK(painter.undoDepth() == 3);
    CHECK(painter.undoBytes() == kept[3] + kept[4] + kept[5]);
    // The newest three strokes come back, newest first; the older ones were dropped.
    for (int stroke = 5; stroke >= 3; --stroke) {
        REQUIRE(painter.undo(scene));
        CHECK(scene.stateHash() == hashes[std::size_t(stroke)]);
    }
    CHECK_FALSE(painter.undo(scene));
    CHECK(painter.undoBytes() == 0);

    // A limit smaller than one snapshot still keeps the last stroke.
    SandPainter tight(UndoLimits{32, 1});
    tight.beginStroke(scene, {1, 1}, settings);
    tight.beginStroke(scene, {2, 2}, settings);
    CHECK(tight.undoDepth() == 1);

    // The count cap still holds when memory would allow more.
    SandPainter counted(UndoLimits{2, std::size_t(1) << 30});
    for (int stroke = 0; stroke < 5; ++stroke) counted.beginStroke(scene, {stroke, 4}, settings);
    CHECK(counted.undoDepth() == 2);
    CHECK(UndoLimits{}.maxStrokes == 32);
    CHECK(UndoLimits{}.maxBytes == std::size_t(256) << 20);
}

TEST_CASE("colour from draft gives each released grain the draft's colour at its column") {
    // A 2x2 draft: red, green / blue, white (rows from the top = from z = 0).
    const DraftImage draft(2, 2, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255});
    sandcore::Scene scene = smallCanvas();
    SandPainter painter;
    PaintSettings settings;
    settings.colorFromDraft = true;
    painter.beginStroke(scene, {1, 1}, settings, &draft);   // left, top half -> red
    painter.continueStroke(scene, {14, 14}, settings, &draft); // ends right, bottom half -> white
    painter.endStroke();
    const auto& grains = scene.grains();
    CHECK(grains.color[0] == 0xff0000ffu);
    CHECK(grains.color[grains.size() - 1] == 0xffffffffu);
    settings.colorFromDraft = false;
    settings.color = 0xff3366ccu;
    painter.beginStroke(scene, {1, 14}, settings, &draft);
    CHECK(grains.color[grains.size() - 1] == 0xff3366ccu);
}

TEST_CASE("a bad draft image gives a one-line error naming the file") {
    const TemporaryFolder folder;
    const std::filesystem::path& dir = folder.path();
    const auto garbage = dir / "garbage.png";
    std::ofstream(garbage) << "this is not a PNG";
    REQUIRE(::mkfifo((dir / "pipe.png").c_str(), 0600) == 0); // would block a reader forever
    for (const auto& [path, cause] : {std::pair<std::string, std::string>{(dir / "missing.png").string(), "no such file"},
                                      {garbage.string(), "not a readable PNG or JPEG image"},
                                      {dir.string(), "is a folder"},
                                      {(dir / "pipe.png").string(), "is a FIFO (named pipe), not a regular file"}}) {
        CAPTURE(path);
        try {
            DraftImage::load(path);
            FAIL("a bad image was accepted");
        } catch (const std::runtime_error& e) {
            const std::string message = e.what();
            CHECK(message.rfind(path + ": ", 0) == 0);
            CHECK(message.find(cause) != std::string::npos);
            CHECK(message.find('\n') == std::string::npos);
        }
    }
}

TEST_CASE("redo takes back an undo exactly, and a new stroke forgets what could be redone") {
    sandcore::Scene scene = smallCanvas();
    SandPainter painter;
    PaintSettings settings;
    std::vector<std::uint64_t> hashes{scene.stateHash()};
    for (int stroke = 0; stroke < 3; ++stroke) {
        painter.beginStroke(scene, {2 + 3 * stroke, 4}, settings);
        painter.continueStroke(scene, {2 + 3 * stroke, 9}, settings);
        painter.endStroke();
        for (int i = 0; i < 5; ++i) scene.step();
        hashes.push_back(scene.stateHash());
    }
    CHECK_FALSE(painter.redo(scene));
    REQUIRE(painter.undo(scene));
    REQUIRE(painter.undo(scene));
    CHECK(painter.redoDepth() == 2);
    CHECK(painter.redoBytes() > 0);
    CHECK(painter.redo(scene));
    CHECK(scene.stateHash() == hashes[2]);
    CHECK(painter.redo(scene));
    CHECK(scene.stateHash() == hashes[3]);
    CHECK_FALSE(painter.redo(scene));
    CHECK(painter.undoDepth() == 3);
    // Undo, then a new stroke: the undone future is gone.
    REQUIRE(painter.undo(scene));
    CHECK(scene.stateHash() != hashes[3]);
    painter.beginStroke(scene, {1, 1}, settings);
    painter.endStroke();
    CHECK(painter.redoDepth() == 0);
    CHECK_FALSE(painter.redo(scene));
    // The whole state comes back through compression: the future after redo is the same.
    sandcore::Scene again = smallCanvas();
    SandPainter other;
    other.beginStroke(again, {5, 5}, settings);
    other.endStroke();
    for (int i = 0; i < 7; ++i) again.step();
    const std::uint64_t before = again.stateHash();
    REQUIRE(other.undo(again));
    REQUIRE(other.redo(again));
    CHECK(again.stateHash() == before);
}

TEST_CASE("compressed history: a 256-wide canvas keeps a stroke in far less than its raw size") {
    sandcore::Scene scene = sandcore::makeCanvasScene({{256, 42, 256}, {256, 170, 256}});
    SandPainter painter;
    PaintSettings settings;
    settings.brushRadius = 6;
    for (int stroke = 0; stroke < 4; ++stroke) {
        painter.beginStroke(scene, {40 + 40 * stroke, 40}, settings);
        for (int i = 0; i < 30; ++i) {
            scene.step();
            painter.continueStroke(scene, {40 + 40 * stroke + i, 40 + 4 * i}, settings);
        }
        painter.endStroke();
    }
    const std::size_t raw = snapshotBytes(scene.snapshot());
    const std::size_t perStroke = painter.undoBytes() / painter.undoDepth();
    MESSAGE("256-wide canvas, " << scene.grainCount() << " grains: raw snapshot " << raw << " bytes, compressed "
                                << perStroke << " bytes per stroke");
    CHECK(painter.undoDepth() == 4);
    CHECK(perStroke * 50 < raw);
}

TEST_CASE("compressed snapshot: expands to exactly the scene's snapshot, obstacles and all") {
    sandcore::Scene scene = smallCanvas();
    scene.addObstacle(GridLevel::Lower, {{2, 0, 2}, {6, 4, 7}});
    scene.addObstacle(GridLevel::Lower, {{-3, 5, 10}, {30, 6, 12}}); // clipped to the grid
    scene.addObstacle(GridLevel::Upper, {{8, 0, 8}, {9, 3, 9}});
    SandPainter painter;
    PaintSettings settings;
    settings.brushRadius = 3;
    settings.color = 0xff00ff00u;
    painter.beginStroke(scene, {4, 4}, settings);
    for (int i = 0; i < 12; ++i) {
        scene.step();
        painter.continueStroke(scene, {4 + i, 4 + i / 2}, settings);
    }
    painter.endStroke();
    scene.clearObstacles(GridLevel::Upper);
    const sandcore::SceneSnapshot expected = scene.snapshot();
    const sandcore::SceneSnapshot got = CompressedSnapshot(scene).expand(scene);
    CHECK(std::ranges::equal(got.upper.cells(), expected.upper.cells()));
    CHECK(std::ranges::equal(got.lower.cells(), expected.lower.cells()));
    CHECK(got.grains.place == expected.grains.place);
    CHECK(got.grains.color == expected.grains.color);
    CHECK(got.nextIdentity == expected.nextIdentity);
    CHECK(got.counters.stepsDone == expected.counters.stepsDone);
    CHECK(got.lowerObstacles.size() == 2);
    CHECK(got.upperObstacles.empty());
}
