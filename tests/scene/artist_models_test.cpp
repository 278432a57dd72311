// SPDX-License-Identifier: MIT
// SPEC S7-S9 with the bundled models made as artists make them: a framed hourglass whose glass
// has thickness (OBJ with parts, Y up; and one binary STL, Z up) and a capped glass with a closed
// inner cavity. Each fills its upper cavity, drains completely and stands up by itself.
#include "scene/model_parts.hpp"
#include "scene/sand_space.hpp"
#include "scene/scene_request.hpp"
#include "support/temporary_folder.hpp"

#include "sandcore/cell_grid.hpp"
#include "sandcore/mesh_shapes.hpp"
#include "sandcore/scene.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <string>

using namespace sandglass;

namespace {

std::string bundled(const std::string& name) { return std::string(SANDGLASS_SOURCE_DIR) + "/models/" + name; }

std::int64_t fillableCells(const sandcore::CellGrid& grid) {
    return std::count_if(grid.cells().begin(), grid.cells().end(), [](sandcore::CellValue c) { return c != sandcore::kInvalid; });
}

struct ArtistModel {
    const char* file;
    const char* upFound;
    VesselKind vessel;
};

} // namespace

TEST_CASE("artist-made hourglasses fill their upper cavity, drain completely and are stood up") {
    // The capped glass's inner surface is closed: its inside is the sand space (solid); the
    // framed glass is open at its ends and its space is what it encloses with the plates.
    const ArtistModel models[] = {{"framed_hourglass.obj", "+y", VesselKind::Cavity},
                                  {"framed_hourglass_z.stl", "+z", VesselKind::Cavity},
                                  {"capped_glass.obj", "+y", VesselKind::Solid}};
    for (const ArtistModel& model : models) {
        SceneRequest request;
        request.modelPath = bundled(model.file);
        request.resolution = 48;
        BuiltScene built = buildSceneWithReport({request, {}});
        INFO(model.file);
        CHECK(built.vessel == model.vessel);
        REQUIRE(built.upAxis.has_value());
        CHECK(built.upAxisFound);
        CHECK(std::string(sandcore::upAxisName(*built.upAxis)) == model.upFound);
        const std::int64_t grains = built.scene.grainCount();
        const double fill = double(grains) / double(fillableCells(built.scene.grid(sandcore::GridLevel::Upper)));
        CHECK(fill >= 0.6);
        CHECK(fill <= 1.0);
        // Upright: the upper bulb sits over the lower one, about as large.
        const std::int64_t lower = fillableCells(built.scene.grid(sandcore::GridLevel::Lower));
        CHECK(lower > grains);
        for (int i = 0; i < 100000 && !built.scene.settled(); ++i) built.scene.step();
        REQUIRE(built.scene.settled());
        CHECK(built.scene.counters().grainsUpper == 0);
        CHECK(built.scene.grainCount() == grains);
        CHECK(built.scene.counters().grainsLower == grains);
    }
}

TEST_CASE("the framed hourglass lists its parts with roles chosen by name") {
    const std::vector<ModelPart> loaded = loadModelParts(bundled("framed_hourglass.obj"));
    std::vector<ModelPart> parts = loaded;
    chooseRoles(parts, sandcore::SceneKind::Hourglass, {});
    REQUIRE(parts.size() == 6);
    CHECK(parts[0].name == "glass");
    CHECK(parts[0].role == PartRole::Vessel);
    CHECK(parts[0].closed);
    for (std::size_t i = 1; i < parts.size(); ++i) {
        INFO(parts[i].name);
        CHECK(parts[i].role == PartRole::Frame);
        CHECK(parts[i].hasColour);
        CHECK(parts[i].colour[0] > parts[i].colour[2]); // wood: warm
    }
    CHECK(parts[0].colour[2] > parts[0].colour[0]); // glass: cool
    chooseRoles(parts, sandcore::SceneKind::Hourglass, {{"pillar_2", PartRole::Vessel}});
    CHECK(parts[4].name == "pillar_2");
    CHECK(parts[4].role == PartRole::Vessel);
    CHECK_THROWS_WITH_AS(chooseRoles(parts, sandcore::SceneKind::Hourglass, {{"lid", PartRole::Frame}}),
                         doctest::Contains("no part 'lid'"), std::invalid_argument);
    CHECK(parsePartRoleChoice("top_plate=frame") == PartRoleChoice{"top_plate", PartRole::Frame});
    CHECK_THROWS_AS(parsePartRoleChoice("top_plate"), std::invalid_argument);
    CHECK_THROWS_AS(parsePartRoleChoice("top_plate=wood"), std::invalid_argument);
    // A binary STL is one object, named after the file; its shells are its parts (W1).
    const std::vector<ModelPart> stl = loadModelParts(bundled("framed_hourglass_z.stl"));
    REQUIRE(stl.size() == loaded.size());
    CHECK(stl[0].name == "framed_hourglass_z #1");
    CHECK(stl[0].object == "framed_hourglass_z");
    CHECK(mergedMesh(stl).triangles.size() == mergedMesh(loaded).triangles.size());
}

TEST_CASE("a one-surface hourglass keeps its inside as the sand space") {
    SceneRequest request;
    request.modelPath = bundled("hourglass.obj");
    request.resolution = 40;
    const BuiltScene built = buildSceneWithReport({request, {}});
    CHECK(built.vessel == VesselKind::Solid);
    CHECK(built.upAxis == sandcore::UpAxis::PlusY);
    REQUIRE(built.parts.size() == 1);
    CHECK(built.parts[0].role == PartRole::Vessel);
}

TEST_CASE("--up turns a model, and an hourglass laid on its side is stood up without it") {
    SceneRequest request;
    request.modelPath = bundled("framed_hourglass_z.stl");
    request.resolution = 40;
    request.upAxis = "+y"; // wrong on purpose: the model lies on its side
    const BuiltScene sideways = buildSceneWithReport({request, {}});
    CHECK(!sideways.upAxisFound);
    CHECK(sideways.upAxis == sandcore::UpAxis::PlusY);
    request.upAxis = "+z";
    const BuiltScene upright = buildSceneWithReport({request, {}});
    request.upAxis.clear();
    const BuiltScene found = buildSceneWithReport({request, {}});
    CHECK(found.scene.stateHash() == upright.scene.stateHash());
    // Laid on its side the glass has no neck across y: one vessel over an open box, not two bulbs.
    const auto lowerOf = [](const BuiltScene& b) { return b.scene.grid(sandcore::GridLevel::Lower).size().y; };
    CHECK(lowerOf(sideways) != lowerOf(upright));
    request.upAxis = "up";
    SceneSettings bad{request, {}};
    CHECK_THROWS_WITH_AS(applySceneDefaults(bad), doctest::Contains("--up"), std::invalid_argument);
}

TEST_CASE("a glass whose ends are open and no frame encloses nothing: it stays a solid") {
    TemporaryFolder folder;
    // Only the glass object of the framed hourglass, written as its own file: the tube is open
    // at both ends, so no cavity; its own inside is the glass wall.
    const std::vector<ModelPart> parts = loadModelParts(bundled("framed_hourglass.obj"));
    std::ofstream obj(folder / "tube.obj");
    for (const auto& v : parts[0].mesh.vertices) obj << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
    for (const auto& t : parts[0].mesh.triangles) obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    obj.close();
    sandcore::VoxelizeSettings settings;
    settings.resolution = 40;
    const SandSpace space = loadSandSpace((folder / "tube.obj").string(), settings, ModelUse::MaskOnly, {});
    CHECK(space.vessel == VesselKind::Solid);
    CHECK(space.cavities == 0);
}

TEST_CASE("a sculpture on a pedestal: the pedestal stays as an obstacle and sand rests on it (S11)") {
    TemporaryFolder folder;
    std::ofstream obj(folder / "statue.obj");
    auto write = [&](const char* name, const sandcore::TriangleMesh& mesh, std::size_t base) {
        obj << "o " << name << '\n';
        for (const auto& v : mesh.vertices) obj << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
        for (const auto& t : mesh.triangles) obj << "f " << t[0] + base << ' ' << t[1] + base << ' ' << t[2] + base << '\n';
    };
    const sandcore::TriangleMesh pedestal = sandcore::makeBoxMesh({-1.0f, 0.0f, -1.0f}, {1.0f, 0.5f, 1.0f});
    sandcore::TriangleMesh statue = sandcore::makeIcosphereMesh(2, 0.6f);
    for (auto& v : statue.vertices) v.y += 1.1f;
    write("pedestal", pedestal, 1);
    write("statue", statue, 1 + pedestal.vertices.size());
    obj.close();
    SceneRequest request;
    request.kind = sandcore::SceneKind::Sculpture;
    request.modelPath = (folder / "statue.obj").string();
    request.resolution = 24;
    BuiltScene built = buildSceneWithReport({request, {}});
    REQUIRE(built.parts.size() == 2);
    CHECK(built.parts[0].role == PartRole::Static);
    CHECK(built.parts[1].role == PartRole::Sand);
    const sandcore::CellGrid& upper = built.scene.grid(sandcore::GridLevel::Upper);
    const auto invalid = std::count(upper.cells().begin(), upper.cells().end(), sandcore::kInvalid);
    CHECK(invalid > 24 * 5 * 24 / 2); // the pedestal's cells
    const std::int64_t grains = built.scene.grainCount();
    for (int i = 0; i < 100000 && !built.scene.settled(); ++i) built.scene.step();
    REQUIRE(built.scene.settled());
    CHECK(built.scene.grainCount() == grains);
    CHECK(built.scene.counters().grainsUpper > 0); // a heap on top of the pedestal
    // Made sand by the user, the pedestal collapses with the rest.
    request.partRoles = {{"pedestal", PartRole::Sand}};
    BuiltScene allSand = buildSceneWithReport({request, {}});
    const sandcore::CellGrid& open = allSand.scene.grid(sandcore::GridLevel::Upper);
    CHECK(std::count(open.cells().begin(), open.cells().end(), sandcore::kInvalid) == 0);
    CHECK(allSand.scene.grainCount() > grains);
}
