// SPDX-License-Identifier: MIT
#include "scene/scene_request.hpp"

#include "sandcore/scene.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace sandglass;

namespace {

std::string bundled(const std::string& name) { return std::string(SANDGLASS_SOURCE_DIR) + "/models/" + name; }

// Steps until nothing moves; returns the grains left in the upper grid.
std::int64_t grainsLeftAfterDrain(sandcore::Scene& scene) {
    for (int i = 0; i < 100000 && !scene.settled(); ++i) scene.step();
    REQUIRE(scene.settled());
    return scene.counters().grainsUpper;
}

} // namespace

TEST_CASE("every bundled hourglass drains completely") {
    for (const char* name : {"hourglass.obj", "slim_hourglass.obj", "shelf_hourglass.obj"})
        for (int resolution : {40, 64}) {
            SceneRequest request;
            request.modelPath = bundled(name);
            request.resolution = resolution;
            BuiltScene built = buildSceneWithReport({request, {}});
            INFO(name << " at " << resolution);
            REQUIRE(built.model.has_value());
            CHECK(built.model->voxels.closedness.closed);
            const std::int64_t grains = built.scene.grainCount();
            CHECK(grains > 0);
            CHECK(grainsLeftAfterDrain(built.scene) == 0);
            CHECK(built.scene.counters().grainsLower == grains);
        }
}

TEST_CASE("the shelf hourglass keeps sand on its shelf without noSharpEdges") {
    SceneRequest request;
    request.modelPath = bundled("shelf_hourglass.obj");
    request.resolution = 40;
    request.drainCompletely = false;
    sandcore::Scene scene = buildScene({request, {}});
    CHECK(grainsLeftAfterDrain(scene) > 0);
}

TEST_CASE("bundled sculptures fill their model and collapse onto the floor") {
    for (const char* name : {"ball.obj", "snowman.obj", "trefoil.obj"}) {
        SceneRequest request;
        request.kind = sandcore::SceneKind::Sculpture;
        request.modelPath = bundled(name);
        request.resolution = 24;
        BuiltScene built = buildSceneWithReport({request, {}});
        INFO(name);
        REQUIRE(built.model.has_value());
        CHECK(built.model->voxels.closedness.closed);
        CHECK(built.scene.grainCount() == built.model->voxels.cellsInside - built.noiseCellsRemoved);
        CHECK(std::abs(built.model->voxels.relativeError()) < 0.05);
        const std::int64_t grains = built.scene.grainCount();
        grainsLeftAfterDrain(built.scene);
        CHECK(built.scene.grainCount() == grains);
        CHECK(built.scene.counters().grainsLower == grains);
    }
}

TEST_CASE("procedural and canvas scenes too large for memory are refused before allocating") {
    sandglass::SceneRequest request;
    request.memoryLimit = 64ull << 20; // 64 MiB
    request.resolution = 256;
    for (sandcore::SceneKind kind : {sandcore::SceneKind::Hourglass, sandcore::SceneKind::Sculpture,
                                     sandcore::SceneKind::Canvas}) {
        request.kind = kind;
        try {
            sandglass::buildScene({request, {}});
            FAIL("a scene over the memory limit was built");
        } catch (const std::invalid_argument& e) {
            CHECK(std::string(e.what()).find("too large for memory at resolution 256") != std::string::npos);
        }
    }
    request.resolution = 0; // the scene's default fits easily
    request.kind = sandcore::SceneKind::Canvas;
    const sandcore::Scene canvas = sandglass::buildScene({request, {}});
    CHECK(canvas.grid(sandcore::GridLevel::Lower).size() == sandcore::Int3{60, 40, 60});
    CHECK(canvas.grid(sandcore::GridLevel::Upper).size() == sandcore::Int3{60, 10, 60});
}
