// SPDX-License-Identifier: MIT
// The digger's driver (scene/digger.hpp) and the host that runs it before each step.
#include "scene/compressed_snapshot.hpp"
#include "scene/digger.hpp"
#include "scene/scene_host.hpp"
#include "scene/state_file.hpp"
#include "support/temporary_folder.hpp"

#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

using namespace sandglass;
using sandcore::Int3;

TEST_CASE("digger: a path is points X,Y,Z between spaces or semicolons, and nothing else") {
    const std::vector<Int3> path = parseDigPath(" 1,2,3;4,5,6  -7,+8,9 ");
    REQUIRE(path.size() == 3);
    CHECK(path[1].x == 4);
    CHECK(path[2].x == -7);
    CHECK(path[2].y == 8);
    for (const char* bad : {"", " ; ", "1,2", "1,2,3,4", "1,2,x", "1.5,2,3", "1,,3"}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(parseDigPath(bad), std::invalid_argument);
    }
}

TEST_CASE("digger: the trench depth is the mean drop of the columns the path passes over") {
    const Int3 size{4, 5, 3};
    std::vector<int> before(12, 3), after(12, 3);
    after[0 + 4 * 1] = 1; // the column (0, 1) two lower
    after[3 + 4 * 1] = 4; // (3, 1) one higher
    // The path along z = 1 from x 0 to 3 passes over four columns: a drop of 2, two unchanged, a rise of 1.
    CHECK(trenchDepth(before, after, {{0, 0, 1}, {3, 0, 1}}, size) == doctest::Approx((2.0 - 1.0) / 4.0));
    CHECK(trenchDepth(before, after, {{0, 0, 1}}, size) == 0.0);
}

TEST_CASE("digger: the host moves the body before each step and lifts it out at the end, every grain kept") {
    SceneSettings settings;
    settings.request.kind = sandcore::SceneKind::Canvas;
    settings.request.sandbox = true;
    settings.request.resolution = 32;
    SceneHost host(settings);
    const std::int64_t grains = host.scene().grainCount();
    REQUIRE(grains == 32 * 32 * sandcore::defaultSandboxBedDepth(sandcore::canvasSettingsForWidth(32)));
    host.startDig(sandcore::makeBladeShape(8, 10, 2), {{16, 4, 4}, {16, 4, 20}}, 2);
    REQUIRE(host.dig() != nullptr);
    CHECK(host.scene().bodies().size() == 1);
    host.runSteps(4);
    CHECK(host.dig()->cellsMoved() == 8);
    CHECK(host.dig()->grainsPushed() > 0);
    host.runSteps(10);
    CHECK(host.dig()->done());
    CHECK(host.scene().bodies().empty());
    CHECK(host.scene().grainCount() == grains);
    CHECK_THROWS_AS(host.startDig(sandcore::makeBoxShape({2, 2, 2}), {{40, 0, 0}}, 1), std::invalid_argument);
}

TEST_CASE("digger: an undo snapshot keeps the body and its cells, a state file keeps the sand without it") {
    sandcore::Scene scene = sandcore::makeSandboxScene({{16, 2, 16}, {16, 12, 16}}, 4);
    REQUIRE(scene.addBody({sandcore::makeBladeShape(6, 6, 1), {8, 1, 3}, 0}) == 0);
    scene.moveBody(0, {8, 1, 9}, 100);
    const CompressedSnapshot undo(scene);
    const std::uint64_t hash = scene.stateHash();
    scene.moveBody(0, {8, 1, 13}, 100);
    scene.step();
    scene.restore(undo.expand(scene));
    CHECK(scene.stateHash() == hash);
    REQUIRE(scene.bodies().size() == 1);
    CHECK(scene.bodies()[0].position == Int3{8, 1, 9});
    for (std::uint32_t n : scene.bodyCells(0)) CHECK(scene.grid(sandcore::GridLevel::Lower)[n] == sandcore::kInvalid);
    CHECK(scene.sweepsMatchCells());

    TemporaryFolder folder;
    SceneRequest request;
    request.kind = sandcore::SceneKind::Canvas;
    request.resolution = 16;
    saveState(folder.path() / "dug.sand", scene, request);
    LoadedState loaded = loadState(folder.path() / "dug.sand");
    CHECK(loaded.scene.bodies().empty());
    CHECK(loaded.scene.grainCount() == scene.grainCount());
    CHECK(loaded.scene.grid(sandcore::GridLevel::Lower).at(8, 1, 9) == sandcore::kEmpty); // no wall left behind
}
