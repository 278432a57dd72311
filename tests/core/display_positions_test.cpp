// SPDX-License-Identifier: MIT
// R8: smooth display positions without drift, and jitter.
#include "support/scene_fixtures.hpp"

#include "sandcore/display_positions.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sandcore;

namespace {
// The display point of a resting grain, computed here independently of the library's code path.
Vec3 expectedRestingPoint(const Scene& scene, std::uint32_t id, const DisplaySettings& display) {
    const GrainStore& g = scene.grains();
    const Int3 c = scene.grid(g.level[id]).coordinate(g.place[id].cell);
    const Int3 o = scene.gridOrigin(g.level[id]);
    const Vec3 j = jitterOffset(g.identity[id], display.jitter);
    return {(float(c.x + o.x) + 0.5f + j.x) * display.cellSize, (float(c.y + o.y) + 0.5f + j.y) * display.cellSize,
            (float(c.z + o.z) + 0.5f + j.z) * display.cellSize};
}
} // namespace

TEST_CASE("after 10^6 steps every resting grain sits exactly on its cell's display point") {
    StepSettings classic; // a grain poured every step, each moving one cell a step (R2)
    classic.physics.level = PhysicsLevel::Classic;
    Scene scene = makeCanvasScene({{12, 3, 12}, {12, 8, 12}}, classic);
    const DisplaySettings display{0.37f, 0.8f};
    std::int64_t glidesChecked = 0;
    for (int i = 0; i < 1'000'000; ++i) {
        if (i < 400) scene.addGrain(GridLevel::Upper, pourCell(scene));
        scene.step();
        if (i > 2000) continue;
        // While sand moves, a gliding grain is on the straight line from its old cell's display
        // point to its new one: at fraction f, (1 - f) of the move is still ahead.
        for (std::uint32_t id = 0; id < scene.grains().size(); ++id) {
            if (scene.grains().place[id].movedAtStep != scene.counters().stepsDone) continue;
            const MoveCode from = scene.grains().place[id].cameFrom;
            const Vec3 end = expectedRestingPoint(scene, id, display);
            const Vec3 middle = grainDisplayPosition(scene, id, 0.25f, display);
            REQUIRE(middle.x == doctest::Approx(end.x + 0.75f * float(moveDx(from)) * display.cellSize));
            REQUIRE(middle.y == doctest::Approx(end.y + 0.75f * float(moveDy(from)) * display.cellSize));
            REQUIRE(middle.z == doctest::Approx(end.z + 0.75f * float(moveDz(from)) * display.cellSize));
            ++glidesChecked;
        }
    }
    CHECK(glidesChecked > 1000);
    REQUIRE(scene.settled());
    REQUIRE(scene.grainCount() == 400);
    for (std::uint32_t id = 0; id < scene.grains().size(); ++id)
        for (float fraction : {0.0f, 0.25f, 0.5f, 0.999f}) {
            const Vec3 p = grainDisplayPosition(scene, id, fraction, display);
            REQUIRE(p == expectedRestingPoint(scene, id, display));
        }
}

TEST_CASE("a grain that moved in the last step glides from its old cell to its new one") {
    Scene scene = fixtures::boxScene({3, 5, 3});
    const auto id = std::uint32_t(fixtures::putLower(scene, 1, 4, 1));
    const DisplaySettings display{2.0f, 0.0f};
    scene.step(); // (1,4,1) -> (1,3,1)
    const Vec3 start = grainDisplayPosition(scene, id, 0.0f, display);
    const Vec3 middle = grainDisplayPosition(scene, id, 0.5f, display);
    const Vec3 end = grainDisplayPosition(scene, id, 1.0f, display);
    CHECK(start.y == doctest::Approx((4 + 0.5) * 2.0));
    CHECK(middle.y == doctest::Approx((3.5 + 0.5) * 2.0));
    CHECK(end.y == doctest::Approx((3 + 0.5) * 2.0));
    CHECK(start.x == end.x);
    // Once a later step leaves it at rest, it is drawn at rest whatever the fraction.
    scene.step();
    scene.step();
    scene.step();
    scene.step();
    CHECK(grainDisplayPosition(scene, id, 0.0f, display) == expectedRestingPoint(scene, id, display));
}

TEST_CASE("jitter stays within +-jitter/2 per axis, is fixed per grain, and 0 means the cell centre") {
    for (std::uint32_t identity = 0; identity < 5000; ++identity) {
        const Vec3 j = jitterOffset(identity, 0.5f);
        CHECK(std::abs(j.x) <= 0.25f);
        CHECK(std::abs(j.y) <= 0.25f);
        CHECK(std::abs(j.z) <= 0.25f);
        CHECK(j == jitterOffset(identity, 0.5f));
        CHECK(jitterOffset(identity, 0.0f) == Vec3{0.0f, 0.0f, 0.0f});
    }
    CHECK(!(jitterOffset(1, 1.0f) == jitterOffset(2, 1.0f)));
}

TEST_CASE("writeDisplayPositions matches grainDisplayPosition for every grain") {
    Scene scene = makeCanvasScene({{10, 3, 10}, {10, 6, 10}});
    for (int i = 0; i < 30; ++i) {
        scene.addGrain(GridLevel::Upper, pourCell(scene));
        scene.step();
    }
    std::vector<Vec3> positions(std::size_t(scene.grainCount()));
    writeDisplayPositions(scene, 0.3f, {}, positions);
    for (std::uint32_t id = 0; id < positions.size(); ++id)
        CHECK(positions[id] == grainDisplayPosition(scene, id, 0.3f, {}));
}
