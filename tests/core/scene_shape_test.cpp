// SPDX-License-Identifier: MIT
// A Scene is built from plain facts (SceneShape), not from one of the app's scene kinds: each
// fact alone decides what it names, and the recipes' shapes are what sceneShapeOf gives.
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <stdexcept>

using namespace sandcore;

namespace {

// An open box under a release grid of the same footprint, with the shape given.
Scene boxScene(const SceneShape& shape) {
    StepSettings step;
    step.physics.level = PhysicsLevel::Granular;
    return Scene(shape, CellGrid({12, 4, 12}), CellGrid({12, 8, 12}), {}, step);
}

// The recipe's hourglass, built again from its layouts and fill with another shape.
Scene rebuilt(const Scene& scene, const SceneShape& shape) {
    return Scene(shape, scene.layout(GridLevel::Upper), scene.layout(GridLevel::Lower), scene.fillCells(),
                 scene.settings());
}

std::uint64_t hashAfter(Scene scene, int steps) {
    for (int i = 0; i < steps; ++i) scene.step();
    return scene.stateHash();
}

} // namespace

TEST_CASE("scene shape: the recipes give the shapes sceneShapeOf names") {
    StepSettings step;
    const Scene hourglass = makeHourglassScene(makeHourglassMask({24, 2.0f}), {}, step);
    CHECK(hourglass.shape() == sceneShapeOf(SceneKind::Hourglass));
    CHECK(hourglass.shape().hourglassNeck);
    CHECK(hourglass.shape().turnsOver);
    CHECK_FALSE(hourglass.shape().takesBodies);
    CHECK(makeSculptureScene(makeBoxShape({4, 4, 4}), step).shape() == sceneShapeOf(SceneKind::Sculpture));
    CHECK(makeCanvasScene({}, step).shape() == sceneShapeOf(SceneKind::Canvas));
    CHECK(sceneShapeOf(SceneKind::Canvas) == SceneShape{});
}

TEST_CASE("scene shape: turning over is allowed by the shape alone") {
    Scene still = boxScene({});
    CHECK_FALSE(still.flip());
    CHECK_FALSE(still.flipped());
    Scene turning = boxScene({.turnsOver = true});
    turning.addGrain(GridLevel::Lower, 0);
    CHECK(turning.flip());
    CHECK(turning.flipped());
    CHECK(turning.counters().grainsUpper == 1);
}

TEST_CASE("scene shape: moving bodies stand only where the shape takes them") {
    const MovingBody body{makeBoxShape({2, 2, 2}), {5, 0, 5}, 0};
    Scene open = boxScene({});
    CHECK(open.addBody(body) == 0);
    Scene closed = boxScene({.takesBodies = false});
    CHECK_THROWS_AS(closed.addBody(body), std::invalid_argument);
}

TEST_CASE("scene shape: the hourglass neck's flow follows the fact, and a scene built from facts steps as the recipe's") {
    StepSettings step;
    step.physics.level = PhysicsLevel::Granular;
    const Scene recipe = makeHourglassScene(makeHourglassMask({24, 2.0f}), {}, step);
    CHECK(recipe.neckFlowRate() > 0.0);
    const Scene sameFacts = rebuilt(recipe, sceneShapeOf(SceneKind::Hourglass));
    CHECK(sameFacts.neckFlowRate() == recipe.neckFlowRate());
    SceneShape noNeck = sceneShapeOf(SceneKind::Hourglass);
    noNeck.hourglassNeck = false;
    const Scene freeFall = rebuilt(recipe, noNeck);
    CHECK(freeFall.neckFlowRate() == 0.0);
    constexpr int kSteps = 120;
    const std::uint64_t expected = hashAfter(recipe.clone(), kSteps);
    CHECK(hashAfter(sameFacts.clone(), kSteps) == expected);
    // Without the neck's discharge the sand runs through the neck as it likes: another drain.
    CHECK(hashAfter(freeFall.clone(), kSteps) != expected);
    CHECK(boxScene({}).neckFlowRate() == 0.0);
    CHECK(boxScene({.hourglassNeck = true}).neckFlowRate() > 0.0);
}
