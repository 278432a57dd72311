// SPDX-License-Identifier: MIT
// SPEC H2: a model voxelizes to the same cells wherever and at whatever scale it was modelled.
// The model goes through a file and the loader, as a user's would. Set SANDGLASS_KEEP_TEST_FILES
// to a folder to keep the model files (to compare against another build).

#include "scene/mesh_loader.hpp"
#include "scene/model_voxelizer.hpp"

#include "support/temporary_folder.hpp"

#include "sandcore/mesh_shapes.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace sandglass;

namespace {

// A closed, bumpy, lopsided solid about 100 units across: a latitude-longitude sphere whose
// radius varies with direction, so no axis or symmetry makes the test easy.
std::string bumpySolidObj(double scale, double offset) {
    const int rings = 40, segments = 72;
    const double pi = std::acos(-1.0);
    std::string obj;
    char line[160];
    auto vertex = [&](double x, double y, double z) {
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", x * scale + offset, y * scale + offset, z * scale + offset);
        obj += line;
    };
    vertex(0, 50 * 1.1, 0); // north pole
    for (int r = 1; r < rings; ++r) {
        const double theta = pi * r / rings;
        for (int s = 0; s < segments; ++s) {
            const double phi = 2 * pi * s / segments;
            const double radius = 50 * (1 + 0.18 * std::sin(3 * theta) * std::cos(2 * phi) + 0.1 * std::cos(5 * phi) * std::sin(theta));
            vertex(radius * std::sin(theta) * std::cos(phi) * 0.8, radius * std::cos(theta) * 1.1, radius * std::sin(theta) * std::sin(phi));
        }
    }
    vertex(0, -50 * 1.1, 0); // south pole
    const int south = 2 + (rings - 1) * segments;
    auto ringVertex = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };
    for (int s = 0; s < segments; ++s) {
        obj += "f 1 " + std::to_string(ringVertex(1, s + 1)) + " " + std::to_string(ringVertex(1, s)) + "\n";
        obj += "f " + std::to_string(south) + " " + std::to_string(ringVertex(rings - 1, s)) + " " +
               std::to_string(ringVertex(rings - 1, s + 1)) + "\n";
    }
    for (int r = 1; r + 1 < rings; ++r)
        for (int s = 0; s < segments; ++s)
            obj += "f " + std::to_string(ringVertex(r, s)) + " " + std::to_string(ringVertex(r, s + 1)) + " " +
                   std::to_string(ringVertex(r + 1, s + 1)) + " " + std::to_string(ringVertex(r + 1, s)) + "\n";
    return obj;
}

std::string writeModel(const TemporaryFolder& folder, const std::string& name, const std::string& text) {
    std::ofstream(folder / name) << text;
    if (const char* keep = std::getenv("SANDGLASS_KEEP_TEST_FILES")) std::ofstream(std::filesystem::path(keep) / name) << text;
    return (folder / name).string();
}

} // namespace

TEST_CASE("H2: the same model moved 10^6, scaled 10^-6 or 10^8 gives the same inside cells") {
    const TemporaryFolder folder;
    sandcore::VoxelizeSettings settings;
    settings.resolution = 64;
    const auto cellsOf = [&](const std::string& name, double scale, double offset) {
        const ModelVoxelization v = voxelizeModelFile(writeModel(folder, name, bumpySolidObj(scale, offset)), settings,
                                                      ModelUse::MaskOnly);
        CHECK(v.voxels.closedness.closed);
        CHECK(v.voxels.volumeMeaningful);
        CHECK(std::abs(v.voxels.relativeError()) < 0.02);
        MESSAGE(name << ": " << v.voxels.cellsInside << " inside cells");
        return double(v.voxels.cellsInside);
    };
    const double unit = cellsOf("unit.obj", 1.0, 0.0);
    REQUIRE(unit > 50000);
    CHECK(std::abs(cellsOf("scaled-1e-6.obj", 1e-6, 0.0) / unit - 1) <= 0.001);
    CHECK(std::abs(cellsOf("scaled-1e8.obj", 1e8, 0.0) / unit - 1) <= 0.001);
    // assimp reads the file's coordinates in single precision: 0.5% where they sit at 10^6.
    CHECK(std::abs(cellsOf("moved-1e6.obj", 1.0, 1e6) / unit - 1) <= 0.005);
}

TEST_CASE("H2: a unit ball scaled by 10^-6 keeps every vertex (assimp's epsilon join merged them: -21% cells)") {
    const TemporaryFolder folder;
    const sandcore::TriangleMesh ball = sandcore::makeIcosphereMesh(3, 1.0f);
    const auto objOf = [&](double scale) {
        std::string obj;
        char line[128];
        for (const sandcore::Vec3& v : ball.vertices) {
            std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v.x * scale, v.y * scale, v.z * scale);
            obj += line;
        }
        for (const auto& t : ball.triangles)
            obj += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
        return obj;
    };
    sandcore::VoxelizeSettings settings;
    settings.resolution = 64;
    const auto unit = voxelizeModelFile(writeModel(folder, "ball.obj", objOf(1.0)), settings, ModelUse::MaskOnly);
    const auto tiny = voxelizeModelFile(writeModel(folder, "ball-1e-6.obj", objOf(1e-6)), settings, ModelUse::MaskOnly);
    CHECK(tiny.voxels.cellsInside == unit.voxels.cellsInside);
    CHECK(loadMesh((folder / "ball-1e-6.obj").string()).vertices.size() == ball.vertices.size());
}

TEST_CASE("H2: a model whose size single precision cannot resolve at its distance is refused as such") {
    const TemporaryFolder folder;
    const std::string path = writeModel(folder, "moved-1e9.obj", bumpySolidObj(1.0, 1e9));
    try {
        loadMesh(path);
        FAIL("a model at 10^9 was accepted");
    } catch (const ModelError& e) {
        const std::string message = e.what();
        CHECK(message.rfind(path + ": the coordinates cannot hold the model: its largest extent", 0) == 0);
        CHECK(message.find("single precision") != std::string::npos);
        CHECK(message.find("zero extent") == std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
    }
}

TEST_CASE("H2: millimetre-scale vertices are not merged and the loaded mesh sits about its centre") {
    const TemporaryFolder folder;
    // A 0.001-unit cube far from the origin: assimp's epsilon join merged its corners.
    std::string obj;
    for (int i = 0; i < 8; ++i)
        obj += "v " + std::to_string(12.0 + 0.001 * (i & 1)) + " " + std::to_string(3.0 + 0.001 * ((i >> 1) & 1)) + " " +
               std::to_string(-7.0 + 0.001 * ((i >> 2) & 1)) + "\n";
    obj += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    const sandcore::TriangleMesh mesh = loadMesh(writeModel(folder, "small-cube.obj", obj));
    CHECK(mesh.vertices.size() == 8);
    CHECK(mesh.triangles.size() == 12);
    CHECK(sandcore::closednessOf(mesh).closed);
    CHECK(std::abs(sandcore::signedVolume(mesh)) == doctest::Approx(1e-9).epsilon(1e-3));
    const sandcore::MeshBounds bounds = sandcore::boundsOf(mesh);
    for (int a = 0; a < 3; ++a) CHECK(std::abs(bounds.min[std::size_t(a)] + bounds.max[std::size_t(a)]) < 1e-9);
}
