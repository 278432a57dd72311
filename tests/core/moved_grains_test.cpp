// SPDX-License-Identifier: MIT
// Scene::movedGrains: the grains the last step moved, each once, equal to those whose cell changed.
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"
#include "support/scene_fixtures.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

using namespace sandcore;

namespace {

struct Place {
    GridLevel level;
    std::uint32_t cell;
    bool operator==(const Place&) const = default;
};

std::vector<Place> placesOf(const Scene& scene) {
    std::vector<Place> places;
    const GrainStore& grains = scene.grains();
    for (std::uint32_t id = 0; id < grains.size(); ++id) places.push_back({grains.level[id], grains.place[id].cell});
    return places;
}

// Each listed move says where its grain is now: the record's cell, grid and last move.
void checkMovesMatchRecords(const Scene& scene) {
    const GrainStore& grains = scene.grains();
    for (const GrainMove& move : scene.movedGrains()) {
        REQUIRE(move.grain < grains.size());
        REQUIRE_MESSAGE(move.cell == grains.place[move.grain].cell, "grain " << move.grain << " is listed in another cell");
        REQUIRE_MESSAGE(move.level == grains.level[move.grain], "grain " << move.grain << " is listed in another grid");
        REQUIRE(move.cameFrom == grains.place[move.grain].cameFrom);
    }
}

// Steps the scene and checks after every step that movedGrains lists exactly the grains whose
// place changed, without repeats. Returns how many moves were checked.
std::int64_t checkEveryStep(Scene& scene, int steps) {
    std::int64_t checked = 0;
    for (int i = 0; i < steps; ++i) {
        const std::vector<Place> before = placesOf(scene);
        scene.step();
        const std::vector<Place> after = placesOf(scene);
        std::vector<std::uint32_t> changed;
        for (std::uint32_t id = 0; id < after.size(); ++id)
            if (!(before[id] == after[id])) changed.push_back(id);
        std::vector<std::uint32_t> listed = fixtures::movedIds(scene);
        std::sort(listed.begin(), listed.end());
        REQUIRE_MESSAGE(std::adjacent_find(listed.begin(), listed.end()) == listed.end(), "a grain is listed twice");
        REQUIRE_MESSAGE(listed == changed, "step " << i + 1 << ": listed " << listed.size() << ", changed " << changed.size());
        // movesLastStep counts a grain that falls into the neck row and passes it in one step twice.
        CHECK(std::int64_t(listed.size()) <= scene.counters().movesLastStep);
        for (std::uint32_t id : listed) CHECK(scene.grains().place[id].movedAtStep == scene.counters().stepsDone);
        checkMovesMatchRecords(scene);
        checked += std::int64_t(listed.size());
    }
    return checked;
}

} // namespace

TEST_CASE("movedGrains lists exactly the grains whose cell changed, transitions included") {
    // Both rule sets: a grain that falls into the neck row and passes it in the same step is
    // listed by its sweep first, then in the lower grid.
    for (PhysicsLevel physics : {PhysicsLevel::Classic, PhysicsLevel::Granular})
        for (int threads : {1, 2}) {
            CAPTURE(threads);
            CAPTURE(int(physics));
            StepSettings settings;
            settings.seed = 7;
            settings.threads = threads;
            settings.physics.level = physics;
            Scene scene = makeHourglassScene(makeHourglassMask({40, 2.5f, 0.0f}), {}, settings);
            CHECK(checkEveryStep(scene, physics == PhysicsLevel::Classic ? 120 : 200) > 1000);
            CHECK(scene.counters().grainsLower > 0); // grains went through the neck: transitions were checked
        }
}

TEST_CASE("movedGrains after restoring a snapshot: the grains of its last step, where they are") {
    Scene scene = makeHourglassScene(makeHourglassMask({32, 2.0f, 0.0f}), {}, {});
    for (int i = 0; i < 60; ++i) scene.step();
    const SceneSnapshot saved = scene.snapshot();
    const std::vector<std::uint32_t> listed = fixtures::movedIds(scene);
    scene.step();
    scene.restore(saved);
    std::vector<std::uint32_t> restored = fixtures::movedIds(scene);
    std::vector<std::uint32_t> expected = listed;
    std::ranges::sort(restored);
    std::ranges::sort(expected);
    CHECK(restored == expected);
    CHECK(!restored.empty());
    checkMovesMatchRecords(scene);
}

TEST_CASE("movedGrains under the granular rules and after edits that renumber grains") {
    StepSettings settings;
    settings.seed = 3;
    settings.physics.level = PhysicsLevel::Granular;
    Scene scene = makeSculptureScene(makeSphereMask(16), settings);
    CHECK(checkEveryStep(scene, 30) > 100);
    // Fast falls of several cells, and busy layers split into strips over two threads: still
    // each grain once (a move goes down at least a layer, and each layer is visited once).
    settings.physics.gravity = 2.0f;
    settings.threads = 2;
    Scene fast = makeSculptureScene(makeSphereMask(24), settings);
    CHECK(checkEveryStep(fast, 40) > 1000);

    // Removing a grain gives the last grain its id: the list follows.
    Scene classic = makeSculptureScene(makeSphereMask(16), {});
    classic.step();
    const std::uint32_t last = classic.grains().size() - 1;
    const bool lastMoved = std::ranges::count(fixtures::movedIds(classic), last) == 1;
    const GrainStore& grains = classic.grains();
    const std::vector<std::uint32_t> listed = fixtures::movedIds(classic);
    const auto other = std::ranges::find_if(listed, [&](std::uint32_t id) { return id != last; });
    REQUIRE(other != listed.end());
    const std::uint32_t victim = *other;
    REQUIRE(classic.removeGrain(grains.level[victim], grains.place[victim].cell));
    for (std::uint32_t id : fixtures::movedIds(classic)) CHECK(id < classic.grains().size());
    CHECK(std::ranges::count(fixtures::movedIds(classic), victim) == (lastMoved ? 1 : 0));
    checkMovesMatchRecords(classic);

    // A flip moves every grain.
    Scene hourglass = makeHourglassScene(makeHourglassMask({24, 1.5f, 0.0f}), {}, {});
    hourglass.step();
    REQUIRE(hourglass.flip());
    CHECK(std::int64_t(hourglass.movedGrains().size()) == hourglass.grainCount());
    checkMovesMatchRecords(hourglass);
}
