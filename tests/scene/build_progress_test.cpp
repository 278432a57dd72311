// SPDX-License-Identifier: MIT
// SPEC I5: a build passes its phases in order and ends in Done; a cancel stops it at the next
// phase with BuildCancelled.
#include "scene/build_progress.hpp"
#include "scene/scene_request.hpp"

#include <doctest/doctest.h>

#include <vector>

using namespace sandglass;

namespace {

SceneSettings modelScene(sandcore::SceneKind kind, int resolution) {
    SceneSettings settings;
    settings.request.kind = kind;
    settings.request.modelPath = defaultModelFor(kind);
    settings.request.resolution = resolution;
    return settings;
}

// The phases one build of `settings` reports, in order.
std::vector<BuildPhase> phasesOf(const SceneSettings& settings) {
    std::vector<BuildPhase> phases;
    BuildProgress progress([&](BuildPhase phase) { phases.push_back(phase); });
    buildSceneWithReport(settings, &progress);
    CHECK(progress.phase() == BuildPhase::Done);
    CHECK(progress.shareDone() == 1.0f);
    return phases;
}

} // namespace

TEST_CASE("build progress: a model build reports loading, voxelizing, the sand space and filling in order, then done") {
    const std::vector<BuildPhase> modelPhases{BuildPhase::Loading, BuildPhase::Voxelizing, BuildPhase::FindingSandSpace,
                                              BuildPhase::Filling, BuildPhase::Done};
    CHECK(phasesOf(modelScene(sandcore::SceneKind::Hourglass, 24)) == modelPhases);
    CHECK(phasesOf(modelScene(sandcore::SceneKind::Sculpture, 20)) == modelPhases);

    // Nothing to load: a procedural shape and the canvas go straight to filling.
    SceneSettings sphere;
    sphere.request.kind = sandcore::SceneKind::Sculpture;
    sphere.request.shape = "sphere";
    sphere.request.resolution = 16;
    CHECK(phasesOf(sphere) == std::vector<BuildPhase>{BuildPhase::Filling, BuildPhase::Done});
    SceneSettings canvas;
    canvas.request.kind = sandcore::SceneKind::Canvas;
    canvas.request.resolution = 16;
    CHECK(phasesOf(canvas) == std::vector<BuildPhase>{BuildPhase::Filling, BuildPhase::Done});

    // The bar only grows, and each phase has a name to show.
    for (std::size_t i = 1; i < modelPhases.size(); ++i)
        CHECK(buildShareAtStart(modelPhases[i - 1]) < buildShareAtStart(modelPhases[i]));
    CHECK(buildShareAtStart(BuildPhase::Loading) == 0.0f);
    CHECK(std::string(buildPhaseName(BuildPhase::Voxelizing)) == "voxelizing");
    CHECK(std::string(buildPhaseName(BuildPhase::FindingSandSpace)) == "finding the sand space");
}

TEST_CASE("build progress: a cancel stops the build at its next phase") {
    std::vector<BuildPhase> phases;
    BuildProgress progress([&](BuildPhase phase) {
        phases.push_back(phase);
        if (phase == BuildPhase::Voxelizing) progress.cancel(); // as if the user pressed Cancel now
    });
    try {
        buildSceneWithReport(modelScene(sandcore::SceneKind::Hourglass, 24), &progress);
        FAIL("the cancelled build finished");
    } catch (const BuildCancelled& cancelled) {
        CHECK(std::string(cancelled.what()) == "cancelled");
    }
    // Voxelizing is reached and refused; no later phase starts.
    CHECK(phases == std::vector<BuildPhase>{BuildPhase::Loading, BuildPhase::Voxelizing});
    CHECK(progress.cancelRequested());

    BuildProgress cancelledFirst;
    cancelledFirst.cancel();
    CHECK_THROWS_AS(buildSceneWithReport(modelScene(sandcore::SceneKind::Sculpture, 20), &cancelledFirst), BuildCancelled);
    CHECK(cancelledFirst.phase() == BuildPhase::Loading);
}
