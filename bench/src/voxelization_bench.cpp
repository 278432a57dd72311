// SPDX-License-Identifier: MIT
#include "bench/voxelization_bench.hpp"

#include "scene/mesh_loader.hpp"
#include "scene/scene_request.hpp"

#include "sandcore/mesh_shapes.hpp"
#include "sandcore/voxelizer.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

namespace sandbench {

using sandcore::TriangleMesh;
using sandcore::VoxelizeResult;
using sandcore::VoxelizeSettings;

namespace {

struct Timed {
    VoxelizeResult result;
    double milliseconds = 1e300;
};

Timed bestOf(const TriangleMesh& mesh, const VoxelizeSettings& settings, int repeat) {
    Timed best;
    for (int i = 0; i < repeat; ++i) {
        const auto start = std::chrono::steady_clock::now();
        VoxelizeResult result = sandcore::voxelize(mesh, settings);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (ms < best.milliseconds) best = {std::move(result), ms};
    }
    return best;
}

std::string percent(double share) {
    std::string text = share >= 0 ? "+" : "";
    return text + fixed(100.0 * share, 3) + "%";
}

// Unit sphere and a torus of ring radius 1, tube radius 0.4, finely tessellated so the mesh
// itself is close to the exact solid.
constexpr double kTorusMajor = 1.0, kTorusMinor = 0.4;

} // namespace

std::vector<VoxelRun> measureVoxelization(const std::vector<int>& resolutions, int threads, int repeat) {
    struct Subject {
        std::string name;
        TriangleMesh mesh;
        double exactVolume; // model units^3; 0 = none
    };
    const Subject subjects[] = {
        {"sphere", sandcore::makeIcosphereMesh(5, 1.0f), 4.0 / 3.0 * std::numbers::pi},
        {"hourglass", sandglass::loadMesh(sandglass::defaultModelPath()), 0.0},
        {"torus", sandcore::makeTorusMesh(float(kTorusMajor), float(kTorusMinor), 256, 128),
         2.0 * std::numbers::pi * std::numbers::pi * kTorusMajor * kTorusMinor * kTorusMinor},
    };
    std::vector<VoxelRun> runs;
    for (const Subject& subject : subjects)
        for (int resolution : resolutions) {
            VoxelizeSettings settings;
            settings.resolution = resolution;
            settings.threads = threads;
            const Timed timed = bestOf(subject.mesh, settings, repeat);
            VoxelRun run;
            run.mesh = subject.name;
            run.triangles = subject.mesh.triangles.size();
            run.resolution = resolution;
            run.milliseconds = timed.milliseconds;
            run.meshError = timed.result.relativeError();
            if (subject.exactVolume > 0) {
                const auto& scale = timed.result.placement.scale;
                const double cellsPerUnit3 = scale[0] * scale[1] * scale[2];
                const double exact = subject.exactVolume * cellsPerUnit3;
                run.analyticError = (double(timed.result.cellsInside) - exact) / exact;
                run.hasAnalytic = true;
            }
            runs.push_back(run);
        }
    return runs;
}

Table voxelTable(const std::vector<VoxelRun>& runs) {
    Table table{{"mesh", "triangles", "res", "ms", "error vs mesh volume", "error vs exact solid"}, {}};
    for (const VoxelRun& run : runs)
        table.rows.push_back({run.mesh, std::to_string(run.triangles), std::to_string(run.resolution),
                              fixed(run.milliseconds, 2), percent(run.meshError),
                              run.hasAnalytic ? percent(run.analyticError) : "-"});
    return table;
}

Table denseMeshTable(int resolution, int threads, int repeat) {
    const TriangleMesh dense = sandcore::makeTorusMesh(float(kTorusMajor), float(kTorusMinor), 320, 312);
    Table table{{"triangles", "res", "threads", "ms", "error vs mesh volume"}, {}};
    for (int t : {1, threads}) {
        VoxelizeSettings settings;
        settings.resolution = resolution;
        settings.threads = t;
        const Timed timed = bestOf(dense, settings, repeat);
        table.rows.push_back({std::to_string(dense.triangles.size()), std::to_string(resolution), std::to_string(t),
                              fixed(timed.milliseconds, 1), percent(timed.result.relativeError())});
    }
    return table;
}

Table binningTable(int resolution, int threads, int repeat) {
    Table table{{"mesh", "triangles", "res", "binned ms", "every row x every triangle ms", "speedup"}, {}};
    const std::pair<const char*, TriangleMesh> meshes[] = {
        {"sphere", sandcore::makeIcosphereMesh(5, 1.0f)},
        {"hourglass", sandglass::loadMesh(sandglass::defaultModelPath())}};
    for (const auto& [name, mesh] : meshes) {
        VoxelizeSettings settings;
        settings.resolution = resolution;
        settings.threads = threads;
        const double binned = bestOf(mesh, settings, repeat).milliseconds;
        settings.binning = false;
        const double everyRow = bestOf(mesh, settings, 1).milliseconds;
        table.rows.push_back({name, std::to_string(mesh.triangles.size()), std::to_string(resolution),
                              fixed(binned, 2), fixed(everyRow, 1), fixed(everyRow / binned, 0) + "x"});
    }
    return table;
}

} // namespace sandbench
