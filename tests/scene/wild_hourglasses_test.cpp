// SPDX-License-Identifier: MIT
// W1-W5 property tests: generated models of every kind users download, loaded with no options,
// checked against the generator's ground truth (tools/wild_models). The corpus report
// (wild_report) runs the same checks over many more seeds.
#include "support/temporary_folder.hpp"
#include "wild_models/wild_checks.hpp"

#include "scene/mesh_loader.hpp"
#include "scene/scene_request.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace sandglass;
using namespace sandglass::wild;

namespace {

// Checks `count` models of a class from `firstSeed` on, alternating OBJ and STL files. No grain
// may ever lie outside the glass (W3 holds by construction) and every model must build; of the
// other properties (the up axis, 40% of the upper bulb as sand, every grain through the neck)
// all must hold in at least `share` of the models. docs/shapes.md lists what still fails.
void requireClassPasses(ModelClass modelClass, std::uint64_t firstSeed, int count, const CheckSettings& settings,
                        double share = 0.9) {
    TemporaryFolder folder;
    int passed = 0;
    for (int i = 0; i < count; ++i) {
        const std::uint64_t seed = firstSeed + std::uint64_t(i);
        const std::string file = std::string(className(modelClass)) + "-" + std::to_string(seed) + (i % 2 ? ".stl" : ".obj");
        CAPTURE(file);
        const ModelCheck check = checkModel(generate(modelClass, seed), folder / file, settings);
        CHECK_MESSAGE(check.loaded, check.failure);
        CHECK_MESSAGE(!check.grainOutside, check.failure);
        if (check.passed()) ++passed;
        else MESSAGE(file << ": " << check.failure);
    }
    CHECK(double(passed) >= share * double(count));
}

CheckSettings withoutDrain() {
    CheckSettings settings;
    settings.drain = false;
    return settings;
}

} // namespace

TEST_CASE("W2, W3: hourglasses with thick glass in a frame find their sand space, up axis and fill without options") {
    requireClassPasses(ModelClass::ThickFramed, 1000, 30, withoutDrain());
}

TEST_CASE("W2, W3: single-wall glasses, closed or open and closed by plates with gaps, find their sand space") {
    requireClassPasses(ModelClass::SingleWall, 2000, 30, withoutDrain());
}

TEST_CASE("W2, W3: two open bulbs closed by stacked plates are one hourglass") {
    requireClassPasses(ModelClass::OpenBulbsPlates, 3000, 30, withoutDrain());
}

TEST_CASE("W1, W3: a one-object game asset: its modelled sand starts in the upper bulb, its frame holds none") {
    requireClassPasses(ModelClass::OneObjectAsset, 4000, 30, withoutDrain());
}

TEST_CASE("W2, W3: glass cones with a neck under a cell beside a post: the neck opens, the post holds no sand") {
    requireClassPasses(ModelClass::ConesRingsPost, 5000, 30, withoutDrain());
}

TEST_CASE("W5: an open funnel says it is no hourglass and fills inside its cone") {
    requireClassPasses(ModelClass::Funnel, 6000, 12, withoutDrain());
}

TEST_CASE("W4: open characters modelled Z-up or Y-up stand as solid statues inside their body") {
    requireClassPasses(ModelClass::Character, 7000, 20, withoutDrain());
}

TEST_CASE("W4: parts thinner than a cell get a refusal that names the resolution that holds them") {
    requireClassPasses(ModelClass::Keyboard, 8000, 4, withoutDrain());
}

TEST_CASE("W4: keys under a cell thin that still hold sand come with a note naming the resolution that holds them") {
    TemporaryFolder folder;
    CheckSettings settings = withoutDrain();
    settings.resolution = 128; // keys about 0.6 cells thin: some hold cell centres, some do not
    int noted = 0;
    for (std::uint64_t seed = 8100; seed < 8104; ++seed) {
        const WildModel model = generate(ModelClass::Keyboard, seed);
        CAPTURE(seed);
        REQUIRE(model.smallestPartExtent() < model.largestExtent() / settings.resolution);
        const ModelCheck check = checkModel(model, folder / ("keyboard-" + std::to_string(seed) + ".obj"), settings);
        CHECK_MESSAGE(check.passed(), check.failure);
        if (check.note.find("--res ") != std::string::npos) ++noted;
    }
    CHECK(noted > 0);
}

TEST_CASE("W3: every kind of hourglass drains with no grain ever outside the glass, and all of it ends below the neck") {
    CheckSettings settings;
    settings.resolution = 40;
    for (ModelClass modelClass : {ModelClass::ThickFramed, ModelClass::SingleWall, ModelClass::OpenBulbsPlates,
                                  ModelClass::OneObjectAsset, ModelClass::ConesRingsPost}) {
        CAPTURE(className(modelClass));
        requireClassPasses(modelClass, 9000, 2, settings);
    }
}

namespace {

struct Drained {
    std::int64_t grains = 0;    ///< at the start
    std::int64_t leftAbove = 0; ///< above the neck once it settled
};

// Drains 30 generated hourglasses (seeds 9100-9105 of each kind) under `rules`, for the models
// that got as far as the drain.
std::vector<Drained> grainsLeftAboveNeck(sandcore::PhysicsLevel rules) {
    CheckSettings settings;
    settings.resolution = 40;
    settings.physics = rules;
    TemporaryFolder folder;
    std::vector<Drained> drained;
    for (ModelClass modelClass : {ModelClass::ThickFramed, ModelClass::SingleWall, ModelClass::OpenBulbsPlates,
                                  ModelClass::OneObjectAsset, ModelClass::ConesRingsPost})
        for (std::uint64_t seed = 9100; seed < 9106; ++seed) {
            const std::string file = std::string(className(modelClass)) + "-" + std::to_string(seed) + ".obj";
            const ModelCheck check = checkModel(generate(modelClass, seed), folder / file, settings);
            if (check.grainsLeftAbove < 0) continue;
            if (check.grainsLeftAbove > 0) MESSAGE(file << ": " << check.grainsLeftAbove << " of " << check.grains << " grains left above the neck");
            drained.push_back({check.grains, check.grainsLeftAbove});
        }
    return drained;
}

} // namespace

// The sand is capped at what the lower bulb surely takes under the scene's rules (heapCapacity in
// scenes.cpp): every model that gets as far as the drain runs out completely.
TEST_CASE("S3, W3: the lower bulb takes all the sand a model's hourglass starts with: none stays above the neck") {
    for (sandcore::PhysicsLevel rules : {sandcore::PhysicsLevel::Classic, sandcore::PhysicsLevel::Granular}) {
        CAPTURE(int(rules));
        const std::vector<Drained> drained = grainsLeftAboveNeck(rules);
        CHECK(drained.size() >= 27); // of 30: the rest failed an earlier check, which the tests above count
        for (const Drained& d : drained) CHECK(d.leftAbove == 0);
    }
}

TEST_CASE("W4: an open character fills with at least as many cells as the majority vote asked for by --robust") {
    TemporaryFolder folder;
    for (std::uint64_t seed = 7100; seed < 7104; ++seed) {
        const WildModel model = generate(ModelClass::Character, seed);
        const std::filesystem::path file = folder / ("character-" + std::to_string(seed) + ".obj");
        writeObj(model, file);
        SceneSettings settings;
        settings.request.kind = sandcore::SceneKind::Sculpture;
        settings.request.modelPath = file.string();
        const BuiltScene automatic = buildSceneWithReport(settings);
        settings.request.robust = true;
        const BuiltScene vote = buildSceneWithReport(settings);
        CHECK(automatic.sandSpaceCells > 0);
        CHECK(automatic.sandSpaceCells >= vote.sandSpaceCells);
    }
}
