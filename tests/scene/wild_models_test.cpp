// SPDX-License-Identifier: MIT
// The generator of models from the wild (tools/wild_models): its files are valid and the same
// for the same seed, and its ground truth agrees with the meshes it writes, so the tests that
// load these models can trust it.
#include "support/temporary_folder.hpp"
#include "wild_models/wild_models.hpp"

#include "sandcore/triangle_mesh.hpp"
#include "sandcore/up_axis.hpp"
#include "sandcore/voxelizer.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>

using namespace sandglass;
using wild::ModelClass;

namespace {

std::string contents(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

sandcore::TriangleMesh mergedMesh(const wild::WildModel& model) {
    sandcore::TriangleMesh all;
    for (const wild::Object& object : model.objects) all.append(object.mesh);
    return all;
}

sandcore::Vec3 toVec3(wild::Point p) { return {float(p[0]), float(p[1]), float(p[2])}; }

// The model point at the centre of grid cell (x, y, z) of a voxelization.
wild::Point cellCentre(const sandcore::VoxelPlacement& placement, int x, int y, int z) {
    const int cell[3] = {x, y, z};
    wild::Point p{};
    for (std::size_t a = 0; a < 3; ++a) p[a] = (cell[a] + 0.5 - placement.padding[a]) / placement.scale[a] + placement.modelMin[a];
    return p;
}

bool hasNeck(ModelClass modelClass) {
    return modelClass != ModelClass::Funnel && modelClass != ModelClass::Character && modelClass != ModelClass::Keyboard;
}

} // namespace

TEST_CASE("wild models: every class gives indexed objects turned by a proper rotation onto its up axis") {
    for (ModelClass modelClass : wild::kAllClasses)
        for (std::uint64_t seed = 1; seed <= 6; ++seed) {
            const wild::WildModel model = wild::generate(modelClass, seed);
            CAPTURE(wild::className(modelClass));
            CAPTURE(seed);
            REQUIRE_FALSE(model.objects.empty());
            for (const wild::Object& object : model.objects) {
                CHECK_FALSE(object.name.empty());
                REQUIRE_FALSE(object.mesh.triangles.empty());
                for (const auto& t : object.mesh.triangles)
                    for (std::uint32_t index : t) REQUIRE(index < object.mesh.vertices.size());
            }
            const auto& r = model.rotation;
            const int determinant = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                                    r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
            CHECK(determinant == 1);
            // sandcore's turn for the model's up axis takes the true up back to +y.
            const sandcore::AxisTurn turn = sandcore::axisTurnFor(sandcore::UpAxis(model.upAxis));
            const wild::Point up = model.upDirection();
            for (int a = 0; a < 3; ++a) CHECK(turn.sign[a] * up[std::size_t(turn.source[a])] == (a == 1 ? 1.0 : 0.0));
            CHECK(model.unitScale >= 1e-3);
            CHECK(model.unitScale <= 1e3);
            CHECK(model.hasModelledSand() == (modelClass == ModelClass::OneObjectAsset));
        }
}

TEST_CASE("wild models: the same seed writes byte-identical OBJ and STL files, another seed other ones") {
    TemporaryFolder folder;
    for (ModelClass modelClass : wild::kAllClasses) {
        CAPTURE(wild::className(modelClass));
        wild::writeObj(wild::generate(modelClass, 7), folder / "a.obj");
        wild::writeObj(wild::generate(modelClass, 7), folder / "b.obj");
        wild::writeObj(wild::generate(modelClass, 8), folder / "c.obj");
        wild::writeStl(wild::generate(modelClass, 7), folder / "a.stl");
        wild::writeStl(wild::generate(modelClass, 7), folder / "b.stl");
        CHECK(contents(folder / "a.obj") == contents(folder / "b.obj"));
        CHECK(contents(folder / "a.obj") != contents(folder / "c.obj"));
        CHECK(contents(folder / "a.stl") == contents(folder / "b.stl"));
        // Binary STL: 80 header bytes, a count, 50 bytes a triangle.
        const std::string stl = contents(folder / "a.stl");
        const std::size_t triangles = wild::generate(modelClass, 7).triangleCount();
        REQUIRE(stl.size() == 84 + 50 * triangles);
        const auto byte = [&](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(stl[i])); };
        CHECK((byte(80) | byte(81) << 8 | byte(82) << 16 | byte(83) << 24) == triangles);
        CHECK(stl.rfind("solid", 0) == std::string::npos);
    }
}

TEST_CASE("wild models: a point on the axis is in its bulb, a point far away or beside the wall is not") {
    for (ModelClass modelClass : {ModelClass::ThickFramed, ModelClass::SingleWall, ModelClass::OpenBulbsPlates,
                                  ModelClass::OneObjectAsset, ModelClass::ConesRingsPost, ModelClass::Funnel})
        for (std::uint64_t seed = 1; seed <= 6; ++seed) {
            const wild::WildModel model = wild::generate(modelClass, seed);
            CAPTURE(wild::className(modelClass));
            CAPTURE(seed);
            const double top = model.innerHeight();
            const double neck = hasNeck(modelClass) ? model.neckHeight() : 0.0;
            REQUIRE(top > 0);
            REQUIRE(neck >= 0);
            const double upperMiddle = 0.5 * (neck + top);
            const sandcore::Vec3 upper = toVec3(model.modelPointAt(upperMiddle, 0.0, 0.0));
            CHECK(model.insideGlass(upper, 0.0));
            CHECK(model.inUpperBulb(upper));
            CHECK_FALSE(model.inLowerBulb(upper));
            if (hasNeck(modelClass)) {
                const sandcore::Vec3 lower = toVec3(model.modelPointAt(0.5 * neck, 0.0, 1.0));
                CHECK(model.inLowerBulb(lower));
                CHECK_FALSE(model.inUpperBulb(lower));
                CHECK(model.neckRadius() < model.innerRadiusAt(upperMiddle));
            }
            const double far = 3.0 * model.largestExtent();
            CHECK_FALSE(model.insideGlass(toVec3(model.modelPointAt(upperMiddle, far, 0.3)), 0.0));
            CHECK_FALSE(model.insideGlass(toVec3(model.modelPointAt(-far, 0.0, 0.0)), 0.0));
            // Just outside the wall: outside, but within a tolerance a little larger than the step.
            const double wall = model.innerRadiusAt(upperMiddle), step = 0.02 * top;
            const sandcore::Vec3 beside = toVec3(model.modelPointAt(upperMiddle, wall + step, 2.0));
            CHECK_FALSE(model.insideGlass(beside, 0.0));
            CHECK(model.insideGlass(beside, 1.1 * step));
            // The frame helpers undo each other.
            const wild::AxisPosition position = model.axisPositionOf(model.modelPointAt(upperMiddle, 0.5 * wall, 1.0));
            CHECK(position.height == doctest::Approx(upperMiddle).epsilon(1e-9));
            CHECK(position.distance == doctest::Approx(0.5 * wall).epsilon(1e-9));
        }
}

TEST_CASE("wild models: the upper bulb's volume matches a count of sample points in it") {
    for (ModelClass modelClass : {ModelClass::ThickFramed, ModelClass::OpenBulbsPlates, ModelClass::Funnel}) {
        const wild::WildModel model = wild::generate(modelClass, 3);
        CAPTURE(wild::className(modelClass));
        const double from = std::max(0.0, model.neckHeight()), to = model.innerHeight();
        double widest = 0.0;
        for (int i = 0; i <= 200; ++i) widest = std::max(widest, model.innerRadiusAt(from + (to - from) * i / 200.0));
        const int n = 60;
        const double dh = (to - from) / n, dx = 2.0 * widest / n;
        std::int64_t inside = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k) {
                    const double x = -widest + (j + 0.5) * dx, z = -widest + (k + 0.5) * dx;
                    const wild::Point p = model.modelPointAt(from + (i + 0.5) * dh, std::hypot(x, z), std::atan2(z, x));
                    inside += model.inUpperBulb(toVec3(p)) ? 1 : 0;
                }
        CHECK(double(inside) * dh * dx * dx == doctest::Approx(model.upperBulbVolume()).epsilon(0.03));
    }
}

TEST_CASE("wild models: a closed single-wall glass voxelizes to cells the ground truth holds") {
    // The first closed, undamaged one-object glass among the seeds.
    for (std::uint64_t seed = 1; seed < 200; ++seed) {
        const wild::WildModel model = wild::generate(ModelClass::SingleWall, seed);
        if (model.objects.size() != 1 || model.damage.flippedFaces != 0 || model.damage.duplicatedFaces != 0 ||
            !sandcore::closednessOf(model.objects[0].mesh).closed)
            continue;
        CAPTURE(seed);
        const sandcore::VoxelizeResult voxels = sandcore::voxelize(model.objects[0].mesh, {});
        const double cell = 1.0 / voxels.placement.scale[0];
        std::int64_t upperCells = 0;
        for (int y = 0; y < voxels.mask.size.y; ++y)
            for (int z = 0; z < voxels.mask.size.z; ++z)
                for (int x = 0; x < voxels.mask.size.x; ++x) {
                    if (!voxels.mask.at(x, y, z)) continue;
                    const sandcore::Vec3 centre = toVec3(cellCentre(voxels.placement, x, y, z));
                    REQUIRE(model.insideGlass(centre, 0.01 * cell));
                    upperCells += model.inUpperBulb(centre) ? 1 : 0;
                }
        CHECK(double(upperCells) * cell * cell * cell == doctest::Approx(model.upperBulbVolume()).epsilon(0.1));
        return;
    }
    FAIL("no closed undamaged single-wall glass among 200 seeds");
}

TEST_CASE("wild models: the cones-and-discs glass has a neck narrower than half a cell at resolution 64") {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        const wild::WildModel model = wild::generate(ModelClass::ConesRingsPost, seed);
        const double cell = model.largestExtent() / 64.0;
        CHECK(2.0 * model.neckRadius() < 0.6 * cell);
        CHECK(2.0 * model.neckRadius() > 0.15 * cell);
        CHECK(model.objects.size() == 2);
    }
}

TEST_CASE("wild models: keyboard keys hold no cell centre at resolution 64 and many at 512") {
    int checked = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        const wild::WildModel model = wild::generate(ModelClass::Keyboard, seed);
        CAPTURE(seed);
        CHECK(model.objects.size() == 89);
        CHECK(model.smallestPartExtent() < 0.5 * model.largestExtent() / 64.0);
        // Faces written twice make the inside itself ambiguous; the placement is what is checked here.
        if (model.damage.duplicatedFaces != 0) continue;
        ++checked;
        const sandcore::TriangleMesh keys = mergedMesh(model);
        sandcore::VoxelizeSettings coarse;
        CHECK(sandcore::voxelize(keys, coarse).cellsInside == 0);
        sandcore::VoxelizeSettings fine;
        fine.resolution = 512;
        const sandcore::VoxelizeResult voxels = sandcore::voxelize(keys, fine);
        CHECK(voxels.cellsInside > 89);
        const double cell = 1.0 / voxels.placement.scale[0];
        for (int y = 0; y < voxels.mask.size.y; ++y)
            for (int z = 0; z < voxels.mask.size.z; ++z)
                for (int x = 0; x < voxels.mask.size.x; ++x)
                    if (voxels.mask.at(x, y, z)) REQUIRE(model.insideGlass(toVec3(cellCentre(voxels.placement, x, y, z)), 0.01 * cell));
    }
    CHECK(checked >= 4);
}

TEST_CASE("wild models: a character stands taller than wide, has open edges and the body is inside it") {
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        const wild::WildModel model = wild::generate(ModelClass::Character, seed);
        CAPTURE(seed);
        CHECK((model.upAxis == 2 || model.upAxis == 4));
        const sandcore::TriangleMesh body = mergedMesh(model);
        const sandcore::MeshBounds bounds = sandcore::boundsOf(body);
        const wild::Point up = model.upDirection();
        const int upAxis = up[1] != 0 ? 1 : 2, depthAxis = upAxis == 1 ? 2 : 1;
        const double height = bounds.extent(upAxis), width = bounds.extent(0), depth = bounds.extent(depthAxis);
        CHECK(height / width >= 1.2);
        CHECK(height / width <= 2.0);
        CHECK(depth < 0.5 * height);
        CHECK(sandcore::closednessOf(body).boundaryEdges > 0);
        // The chest, on the axis at two thirds of the height, is inside; a point beside the figure is not.
        CHECK(model.insideGlass(toVec3(model.modelPointAt(0.62 * height, 0.0, 0.0)), 0.0));
        CHECK_FALSE(model.insideGlass(toVec3(model.modelPointAt(0.62 * height, 2.0 * height, 0.0)), 0.0));
    }
}
