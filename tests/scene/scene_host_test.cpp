// SPDX-License-Identifier: MIT
#include "scene/scene_host.hpp"
#include "scene/statistics.hpp"

#include "support/phase_gate.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <thread>

using namespace sandglass;

namespace {
SceneSettings procedural(const char* shape, int resolution) {
    SceneSettings settings;
    settings.request.shape = shape;
    settings.request.resolution = resolution;
    return settings;
}
} // namespace

TEST_CASE("scene settings: defaults are applied once and every value is checked against its one range") {
    SceneSettings settings;
    applySceneDefaults(settings);
    CHECK(settings.request.resolution == 64);
    settings.request.kind = sandcore::SceneKind::Canvas;
    settings.request.resolution = 0;
    applySceneDefaults(settings);
    CHECK(settings.request.resolution == 60);

    auto refused = [](auto change) {
        SceneSettings bad;
        change(bad);
        try {
            applySceneDefaults(bad);
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    CHECK(refused([](SceneSettings& s) { s.request.resolution = kResolutionRange.min - 1; }).find("--res must lie in 8..4096") == 0);
    CHECK(refused([](SceneSettings& s) { s.step.threads = 0; }).find("--threads") == 0);
    CHECK(refused([](SceneSettings& s) { s.request.neckRadius = std::nanf(""); }).find("--neck") == 0);
    CHECK(refused([](SceneSettings& s) { s.request.fillFraction = 0.0f; }).find("--fill") == 0);
    CHECK(refused([](SceneSettings& s) { s.request.noiseThreshold = 6; }).find("--noise") == 0);
    CHECK(refused([](SceneSettings& s) { s.request.shape = "pyramid"; }).find("unknown shape") == 0);
    CHECK(refused([](SceneSettings& s) {
              s.request.kind = sandcore::SceneKind::Canvas;
              s.request.shape = "cube";
          }).find("the canvas takes no model or shape") == 0);
    CHECK(refused([](SceneSettings&) {}).empty());
}

TEST_CASE("scene host: the clock's steps, single steps while paused, and revisions that say what changed") {
    SceneHost host(procedural("hourglass", 24));
    const std::uint64_t content = host.contentRevision(), layout = host.layoutRevision();
    CHECK(host.advance(1.0) == 0); // paused
    host.requestSingleStep();
    CHECK(host.advance(0.0) == 1);
    CHECK(host.scene().counters().stepsDone == 1);
    CHECK(host.displayStepFraction() == 1.0f); // a paused step is shown done, not undone
    CHECK(host.contentRevision() != content);
    CHECK(host.layoutRevision() == layout);
    host.setRunning(true);
    host.setStepsPerSecond(30.0);
    int steps = 0;
    for (int frame = 0; frame < 60; ++frame) steps += host.advance(1.0 / 60.0);
    CHECK(steps == 30);
    CHECK(host.stepsPerSecond() == doctest::Approx(30.0).epsilon(0.05));
    host.editLayout();
    CHECK(host.layoutRevision() != layout);
}

TEST_CASE("scene host: seed and threads change without a rebuild, and threads never change the result") {
    SceneHost one(procedural("hourglass", 32)), two(procedural("hourglass", 32));
    sandcore::StepSettings step = two.loaded().step;
    step.threads = 2;
    two.applyStepSettings(step);
    CHECK(two.scene().settings().threads == 2);
    CHECK(two.loaded().step.threads == 2);
    one.runSteps(50);
    two.runSteps(50);
    CHECK(one.scene().stateHash() == two.scene().stateHash());
    step.seed = 99;
    two.applyStepSettings(step);
    one.runSteps(50);
    two.runSteps(50);
    CHECK(one.scene().stateHash() != two.scene().stateHash()); // the new seed steered the slips
}

TEST_CASE("scene host: a failed build keeps the running scene, and the last of several requests wins") {
    SceneHost host(procedural("hourglass", 24));
    const std::uint64_t hash = host.scene().stateHash();
    SceneSettings broken = procedural("hourglass", 24);
    broken.request.shape.clear();
    broken.request.modelPath = "no-such-model.obj";
    host.requestBuild(broken);
    const std::optional<BuildOutcome> failed = host.finishBuilds();
    REQUIRE(failed);
    CHECK_FALSE(failed->adopted);
    CHECK(failed->message.find("no-such-model.obj") != std::string::npos);
    CHECK(host.scene().stateHash() == hash);
    CHECK(host.loaded().request.shape == "hourglass");

    host.requestBuild(procedural("sphere", 40));
    host.requestBuild(procedural("cube", 20)); // waits for the sphere, which is then dropped
    host.requestBuild(procedural("cube", 16));
    const std::optional<BuildOutcome> built = host.finishBuilds();
    REQUIRE(built);
    CHECK(built->adopted);
    CHECK(host.loaded().request.shape == "cube");
    CHECK(host.loaded().request.resolution == 16);
    CHECK(host.kind() == sandcore::SceneKind::Hourglass);
    CHECK(host.scene().shape() == sandcore::sceneShapeOf(sandcore::SceneKind::Hourglass));
}

TEST_CASE("scene host: a cancelled build keeps the running scene unchanged and says so") {
    SceneHost host(procedural("hourglass", 24));
    host.runSteps(20);
    const std::uint64_t hash = host.scene().stateHash();
    // The build is held at voxelizing, so the cancel surely meets it running.
    testing::PhaseGate gate(BuildPhase::Voxelizing);
    host.setBuildPhaseListener(gate.listener());
    SceneSettings model = procedural("hourglass", 32);
    model.request.shape.clear();
    model.request.modelPath = defaultModelFor(sandcore::SceneKind::Hourglass);
    host.requestBuild(model);
    REQUIRE(gate.waitUntilReached());
    const BuildProgress* progress = host.buildProgress();
    REQUIRE(progress != nullptr);
    CHECK(progress->phase() == BuildPhase::Voxelizing);
    CHECK(progress->shareDone() > 0.0f);
    CHECK(progress->shareDone() < 1.0f);
    host.requestBuild(procedural("cube", 16)); // waits for the model; the cancel drops it too
    CHECK(host.buildWaiting());

    host.cancelBuild();
    CHECK(progress->cancelRequested());
    CHECK_FALSE(host.buildWaiting());
    gate.open();
    const std::optional<BuildOutcome> outcome = host.finishBuilds();
    REQUIRE(outcome);
    CHECK(outcome->cancelled);
    CHECK_FALSE(outcome->adopted);
    CHECK(outcome->message == "build cancelled; the running scene is kept");
    CHECK_FALSE(host.building());
    CHECK(host.buildProgress() == nullptr);
    CHECK(host.scene().stateHash() == hash);
    CHECK(host.scene().counters().stepsDone == 20);
    CHECK(host.loaded().request.shape == "hourglass");
    CHECK(host.loaded().request.resolution == 24);

    // The next request builds as ever.
    host.setBuildPhaseListener({});
    host.requestBuild(procedural("cube", 16));
    const std::optional<BuildOutcome> built = host.finishBuilds();
    REQUIRE(built);
    CHECK(built->adopted);
    CHECK_FALSE(built->cancelled);
    CHECK(host.loaded().request.shape == "cube");
}

TEST_CASE("step rate: frames without steps count, so the readout is the true rate") {
    StepRateMeter meter;
    for (int frame = 0; frame < 120; ++frame) meter.addFrame(1.0 / 120.0, frame % 4 == 0 ? 1 : 0); // 30 steps/s
    CHECK(meter.stepsPerSecond() == doctest::Approx(30.0).epsilon(0.02));
    for (int frame = 0; frame < 3; ++frame) meter.addFrame(1.0 / 3.0, 10); // slow frames, several steps each
    CHECK(meter.stepsPerSecond() == doctest::Approx(30.0).epsilon(0.02));
}

TEST_CASE("streaming median: exact for short series, within half a percent in bounded memory for long ones") {
    StreamingMedian shortSeries;
    for (double v : {5.0, 1.0, 3.0}) shortSeries.add(v);
    CHECK(shortSeries.median() == 3.0);
    StreamingMedian longSeries;
    const std::size_t count = StreamingMedian::kExactSamples * 3;
    for (std::size_t i = 0; i < count; ++i) longSeries.add(0.1 + double(i % 1000) * 0.001); // median 0.6
    CHECK(longSeries.count() == count);
    CHECK(longSeries.median() == doctest::Approx(0.6).epsilon(0.005));
}
