// SPDX-License-Identifier: MIT
#include "scene/mesh_loader.hpp"
#include "scene/model_voxelizer.hpp"
#include "scene/scene_request.hpp"

#include "sandcore/scenes.hpp"

#include "support/temporary_folder.hpp"

#include <doctest/doctest.h>

#include <atomic>
#include <filesystem>
#include <sys/stat.h>
#include <thread>
#include <vector>
#include <fstream>
#include <string>

using namespace sandglass;

namespace {

// A fresh folder per test case for the files it writes.
struct TempDir {
    TemporaryFolder folder; // uniquely named, removed at the end
    std::filesystem::path path = folder.path();
    explicit TempDir(const std::string&) {}
    std::string write(const std::string& file, const std::string& text) const {
        std::ofstream(path / file) << text;
        return (path / file).string();
    }
};

const char* const kCubeObj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                             "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

std::string errorOf(const std::string& path) {
    try {
        loadMesh(path);
    } catch (const ModelError& e) {
        return e.what();
    }
    return "no error";
}

} // namespace

TEST_CASE("a quad-faced OBJ cube loads as 12 triangles on 8 joined vertices") {
    TempDir dir("cube");
    const sandcore::TriangleMesh mesh = loadMesh(dir.write("cube.obj", kCubeObj));
    CHECK(mesh.triangles.size() == 12);
    CHECK(mesh.vertices.size() == 8);
    CHECK(sandcore::closednessOf(mesh).closed);
    CHECK(std::abs(sandcore::signedVolume(mesh)) == doctest::Approx(1.0));
}

TEST_CASE("STL and PLY files load too") {
    TempDir dir("formats");
    const std::string stl = dir.write("tri.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                                 "vertex 0 1 1\nendloop\nendfacet\nendsolid t\n");
    CHECK(loadMesh(stl).triangles.size() == 1);
    const std::string ply = dir.write("tri.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                                 "end_header\n0 0 0\n1 0 0\n0 1 1\n3 0 1 2\n");
    CHECK(loadMesh(ply).triangles.size() == 1);
}

TEST_CASE("every S1 bad input names the file and the cause") {
    TempDir dir("bad");
    const std::string missing = (dir.path / "missing.obj").string();
    CHECK(errorOf(missing) == missing + ": no such file");
    CHECK(errorOf(dir.path.string()) == dir.path.string() + ": is a folder, not a file");

    const std::string garbage = dir.write("garbage.obj", std::string("\x01\x02\x03 this is not a model \xff\xfe", 26));
    CHECK(errorOf(garbage).rfind(garbage + ": ", 0) == 0);
    CHECK(errorOf(garbage) != "no error");

    const std::string points = dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\nl 1 2\n");
    CHECK(errorOf(points) == points + ": contains no triangles (only points or lines, or nothing)");

    const std::string nan = dir.write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 1\nv 1 1 1\nf 1 2 3\nf 1 3 4\n");
    CHECK(errorOf(nan) == nan + ": vertex 1 has a NaN or infinite coordinate");

    const std::string flat = dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    CHECK(errorOf(flat) == flat + ": has zero extent along z (a flat model encloses no volume)");
}

TEST_CASE("a resolution beyond memory or the grid limit fails before allocating") {
    TempDir dir("huge");
    const std::string cube = dir.write("cube.obj", kCubeObj);
    sandcore::VoxelizeSettings settings;
    settings.resolution = 64;
    // 64^3 cells need about 12 MiB as an hourglass: a 1 MiB limit must refuse it.
    try {
        voxelizeModelFile(cube, settings, ModelUse::Hourglass, 1u << 20);
        FAIL("no error for a model larger than memory");
    } catch (const ModelError& e) {
        CHECK(std::string(e.what()).rfind(cube + ": too large for memory at resolution 64: a 64x64x64 grid needs", 0) == 0);
    }
    settings.resolution = 2000; // 8e9 cells > 2^31
    CHECK_THROWS_WITH_AS(voxelizeModelFile(cube, settings, ModelUse::MaskOnly),
                         (cube + ": grid of 2000x2000x2000 = 8000000000 cells exceeds the limit of 2^31 cells").c_str(),
                         ModelError);
    CHECK(voxelizeModelFile(cube, {}, ModelUse::MaskOnly).voxels.cellsInside == 64 * 64 * 64);
}

TEST_CASE("a bad model leaves the running scene untouched") {
    TempDir dir("untouched");
    sandcore::StepSettings step;
    SceneRequest request;
    request.modelPath = defaultModelPath();
    request.resolution = 32;
    sandcore::Scene running = buildScene({request, step});
    for (int i = 0; i < 20; ++i) running.step();
    const std::uint64_t hash = running.stateHash();
    const std::int64_t grains = running.grainCount();

    request.modelPath = dir.write("points.obj", "v 0 0 0\nv 1 0 0\np 1 2\n");
    try {
        running = buildScene({request, step}); // the assignment never happens
        FAIL("no error for a points-only model");
    } catch (const ModelError& e) {
        CHECK(std::string(e.what()) == request.modelPath + ": contains no triangles (only points or lines, or nothing)");
    }
    CHECK(running.stateHash() == hash);
    CHECK(running.grainCount() == grains);
}

TEST_CASE("models load in a child process while other threads allocate, as in the GUI") {
    // The GUI builds scenes on a worker thread while others run: the import starts a child from a
    // multi-threaded process, and the child must neither deadlock nor disturb the parent.
    TempDir dir("threads");
    const std::string cube = dir.write("cube.obj", kCubeObj);
    std::atomic<bool> stop{false};
    std::vector<std::thread> busy;
    for (int t = 0; t < 2; ++t)
        busy.emplace_back([&stop] {
            std::vector<std::string> churn;
            while (!stop.load()) {
                churn.emplace_back(1000, 'x');
                if (churn.size() > 100) churn.clear();
            }
        });
    int loaded = 0;
    std::string error;
    try {
        for (int i = 0; i < 8; ++i) loaded += loadMesh(cube, {10.0}).triangles.size() == 12;
    } catch (const ModelError& e) {
        error = e.what();
    }
    stop = true;
    for (std::thread& t : busy) t.join();
    CHECK(error == "");
    CHECK(loaded == 8);
}

TEST_CASE("a FIFO given as a model is refused at once instead of blocking the import") {
    TempDir dir("fifo");
    const std::string fifo = (dir.path / "model.obj").string();
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    CHECK(errorOf(fifo) == fifo + ": is a FIFO (named pipe), not a regular file");
}
