// SPDX-License-Identifier: MIT
// SPEC S10: a model is drawn where its cells are. The drawing's transform (scale, padding, the
// quarter turns to the up axis, the shift into the scene's grids) is checked against the
// voxelizer's cells: point by point for the turns, and for the bundled hourglasses by the
// sand space (the cavity the scene holds) lying centred inside the drawn glass.
#include "support/temporary_folder.hpp"

#include "scene/model_drawing.hpp"
#include "scene/scene_host.hpp"
#include "scene/scene_request.hpp"

#include "sandcore/mesh_shapes.hpp"
#include "sandcore/scene.hpp"
#include "sandcore/scenes.hpp"
#include "sandcore/up_axis.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <string>

using namespace sandglass;

namespace {

std::string bundled(const std::string& name) { return std::string(SANDGLASS_SOURCE_DIR) + "/models/" + name; }

struct Box {
    std::array<float, 3> low{1e30f, 1e30f, 1e30f}, high{-1e30f, -1e30f, -1e30f};
    void add(float x, float y, float z) {
        const float p[3] = {x, y, z};
        for (std::size_t a = 0; a < 3; ++a) low[a] = std::min(low[a], p[a]), high[a] = std::max(high[a], p[a]);
    }
    float centre(std::size_t a) const { return 0.5f * (low[a] + high[a]); }
};

// Every cell sand may take, in world cells (both grids, the upper one at its origin).
Box sandSpaceOf(const sandcore::Scene& scene) {
    Box box;
    for (sandcore::GridLevel level : {sandcore::GridLevel::Lower, sandcore::GridLevel::Upper}) {
        const sandcore::CellGrid& grid = scene.grid(level);
        const sandcore::Int3 o = scene.gridOrigin(level), s = grid.size();
        for (int y = 0; y < s.y; ++y)
            for (int z = 0; z < s.z; ++z)
                for (int x = 0; x < s.x; ++x)
                    if (grid.at(x, y, z) != sandcore::kInvalid) {
                        box.add(float(x + o.x), float(y + o.y), float(z + o.z));
                        box.add(float(x + o.x + 1), float(y + o.y + 1), float(z + o.z + 1));
                    }
    }
    return box;
}

Box drawnBox(const ModelDrawing& drawing, PartLook look) {
    Box box;
    for (const DrawnPart& part : drawing.parts)
        if (part.look == look)
            for (const ModelVertex& v : part.vertices) box.add(v.x, v.y, v.z);
    return box;
}

} // namespace

TEST_CASE("model drawing: a point goes where sandcore's quarter turns move its cell, for all six up axes") {
    ModelToWorld toWorld;
    toWorld.placement.size = {4, 5, 6};
    toWorld.placement.scale = {2.0, 2.0, 2.0}; // two cells per model unit
    toWorld.placement.modelMin = {-1.0, -1.0, -1.0};
    toWorld.placement.padding = {0.5, 0.5, 0.5};
    toWorld.maskOrigin = {3, -2, 7};
    const sandcore::Int3 cell{1, 3, 4};
    for (sandcore::UpAxis up : {sandcore::UpAxis::PlusX, sandcore::UpAxis::MinusX, sandcore::UpAxis::PlusY,
                                sandcore::UpAxis::MinusY, sandcore::UpAxis::PlusZ, sandcore::UpAxis::MinusZ}) {
        CAPTURE(sandcore::upAxisName(up));
        sandcore::InsideMask mask = sandcore::InsideMask::empty(toWorld.placement.size);
        mask.set(cell.x, cell.y, cell.z, true);
        const sandcore::InsideMask turned = sandcore::turnToUp(mask, up);
        sandcore::Int3 moved{-1, -1, -1};
        for (int y = 0; y < turned.size.y; ++y)
            for (int z = 0; z < turned.size.z; ++z)
                for (int x = 0; x < turned.size.x; ++x)
                    if (turned.at(x, y, z)) moved = {x, y, z};
        REQUIRE(moved.x >= 0);
        // The model point at the centre of the cell: grid = (model - min) * scale + padding.
        const sandcore::Vec3 model{float((cell.x + 0.5 - 0.5) / 2.0 - 1.0), float((cell.y + 0.5 - 0.5) / 2.0 - 1.0),
                                   float((cell.z + 0.5 - 0.5) / 2.0 - 1.0)};
        toWorld.up = up;
        const sandcore::Vec3 world = toWorld.apply(model);
        CHECK(world.x == doctest::Approx(moved.x + 0.5 + 3));
        CHECK(world.y == doctest::Approx(moved.y + 0.5 - 2));
        CHECK(world.z == doctest::Approx(moved.z + 0.5 + 7));
    }
}

TEST_CASE("model drawing: the bundled hourglasses' sand space lies centred inside their drawn glass, upright") {
    for (const std::string file : {"framed_hourglass.obj", "framed_hourglass_z.stl", "capped_glass.obj"}) {
        CAPTURE(file);
        SceneRequest request;
        request.modelPath = bundled(file);
        request.resolution = 48;
        const BuiltScene built = buildSceneWithReport({request, {}});
        REQUIRE(built.drawing != nullptr);
        const Box space = sandSpaceOf(built.scene);
        // The STL is one part, drawn as glass; the OBJ files have a glass part and a wooden frame.
        const Box glass = drawnBox(*built.drawing, PartLook::Glass);
        Box all = glass;
        const Box frame = drawnBox(*built.drawing, PartLook::Opaque);
        for (std::size_t a = 0; a < 3; ++a) all.low[a] = std::min(all.low[a], frame.low[a]), all.high[a] = std::max(all.high[a], frame.high[a]);
        for (std::size_t a = 0; a < 3; ++a) {
            CAPTURE(a);
            // Within a cell of where the voxelizer put the cells: centred on the model (the
            // models are symmetric), and inside the glass across, inside the whole model along y.
            CHECK(std::abs(space.centre(a) - all.centre(a)) <= 1.0f);
            const Box& around = a == 1 ? all : glass;
            CHECK(space.low[a] >= around.low[a] - 0.5f);
            CHECK(space.high[a] <= around.high[a] + 0.5f);
        }
        // Upright: the hourglass is taller than wide in the drawing too (the STL lies along z in its file).
        CHECK(all.high[1] - all.low[1] > all.high[0] - all.low[0]);
        // The sand space fills most of the inside height: the drawing is not shifted or scaled off it.
        CHECK(space.high[1] - space.low[1] > 0.6f * (all.high[1] - all.low[1]));
        CHECK(built.drawing->heightCells == doctest::Approx(float(built.scene.gridOrigin(sandcore::GridLevel::Upper).y +
                                                                   built.scene.grid(sandcore::GridLevel::Upper).size().y)));
    }
}

TEST_CASE("model drawing: glass and frame keep their roles and colours, smooth normals are unit") {
    SceneRequest request;
    request.modelPath = bundled("framed_hourglass.obj");
    request.resolution = 32;
    const BuiltScene built = buildSceneWithReport({request, {}});
    REQUIRE(built.drawing != nullptr);
    const ModelDrawing& drawing = *built.drawing;
    REQUIRE(drawing.parts.size() == 6);
    CHECK(drawing.parts[0].name == "glass");
    CHECK(drawing.parts[0].look == PartLook::Glass);
    for (std::size_t i = 1; i < drawing.parts.size(); ++i) {
        CAPTURE(drawing.parts[i].name);
        CHECK(drawing.parts[i].look == PartLook::Opaque);
        CHECK(drawing.parts[i].colour[0] == doctest::Approx(0.45f)); // the MTL's wood
    }
    for (const DrawnPart& part : drawing.parts) {
        REQUIRE(part.vertices.size() % 3 == 0);
        for (const ModelVertex& v : part.vertices)
            CHECK(v.nx * v.nx + v.ny * v.ny + v.nz * v.nz == doctest::Approx(1.0f).epsilon(1e-3));
    }
    // A procedural scene has no drawing: it keeps the voxel hull.
    SceneRequest procedural;
    procedural.shape = "hourglass";
    procedural.resolution = 24;
    CHECK(buildSceneWithReport({procedural, {}}).drawing == nullptr);
}

TEST_CASE("model drawing: a loaded scene is drawn as modelled when its model file still gives its grids") {
    SceneSettings settings;
    settings.request.modelPath = bundled("framed_hourglass.obj");
    settings.request.resolution = 24;
    SceneHost host(settings);
    REQUIRE(host.modelDrawing() != nullptr);
    sandcore::Scene turned = host.scene().clone();
    REQUIRE(turned.flip());
    const std::int64_t grains = turned.grainCount();
    host.adoptLoaded(std::move(turned), settings);
    CHECK(host.modelDrawing() != nullptr);
    CHECK(host.scene().flipped());
    // Another resolution gives other grids: the drawing would not fit, the voxel hull is drawn.
    SceneSettings other = settings;
    other.request.resolution = 20;
    host.adoptLoaded(host.scene().clone(), other);
    CHECK(host.modelDrawing() == nullptr);
    // The model file is gone: the scene still runs, without a drawing.
    SceneSettings gone = settings;
    gone.request.modelPath = bundled("no_such_model.obj");
    host.adoptLoaded(host.scene().clone(), gone);
    CHECK(host.modelDrawing() == nullptr);
    CHECK(host.scene().grainCount() == grains);
}

TEST_CASE("model drawing: a face modelled twice, with either winding, is drawn once") {
    TemporaryFolder folder;
    std::ofstream obj(folder / "doubled.obj");
    const sandcore::TriangleMesh box = sandcore::makeBoxMesh({0, 0, 0}, {1, 2, 1});
    obj << "o glass\n";
    for (const auto& v : box.vertices) obj << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
    for (const auto& t : box.triangles) {
        obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
        obj << "f " << t[0] + 1 << ' ' << t[2] + 1 << ' ' << t[1] + 1 << '\n'; // the other side
    }
    obj.close();
    const std::vector<ModelPart> parts = loadModelParts((folder / "doubled.obj").string());
    REQUIRE(parts.size() == 1);
    CHECK(parts[0].mesh.triangles.size() == 24);
    sandcore::VoxelizeSettings settings;
    settings.resolution = 16;
    const ModelToWorld toWorld{sandcore::placeInGrid(parts[0].mesh, settings), sandcore::UpAxis::PlusY, {0, 0, 0}, {}};
    const ModelDrawing drawing = makeModelDrawing(parts, toWorld, 16.0f);
    REQUIRE(drawing.parts.size() == 1);
    CHECK(drawing.parts[0].vertices.size() == 12 * 3);
}
