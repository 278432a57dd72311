// Voxelizer speed against error (SPEC B2, voxelization part), printed as Markdown tables:
//   build/release/bench/voxelize_bench [--threads N] [--repeat N]
// 1. resolution 16..256: time and volume error for a sphere (exact volume 4/3 pi r^3 also shown)
//    and the bundled hourglass; 2. a closed mesh of about 200,000 triangles at 256 cells;
// 3. binning against testing every row with every triangle at 128 cells.
#include "model/mesh_loader.hpp"
#include "scene_request.hpp"

#include "sandcore/mesh_shapes.hpp"
#include "sandcore/voxelizer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

using namespace sandcore;

namespace {

struct Timed {
    VoxelizeResult result;
    double milliseconds; // best of the repeats
};

Timed timeVoxelize(const TriangleMesh& mesh, const VoxelizeSettings& settings, int repeat) {
    Timed best{{}, 1e300};
    for (int i = 0; i < repeat; ++i) {
        const auto start = std::chrono::steady_clock::now();
        VoxelizeResult result = voxelize(mesh, settings);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (ms < best.milliseconds) best = {std::move(result), ms};
    }
    return best;
}

void resolutionTable(const char* name, const TriangleMesh& mesh, int threads, int repeat, double analyticRadius) {
    std::printf("\n### %s (%zu triangles, %d thread(s))\n\n", name, mesh.triangles.size(), threads);
    std::printf("| resolution | grid | cells inside | ms | error vs mesh volume |%s\n|---|---|---|---|---|%s\n",
                analyticRadius > 0 ? " error vs 4/3 pi r^3 |" : "", analyticRadius > 0 ? "---|" : "");
    for (int resolution : {16, 32, 64, 128, 256}) {
        VoxelizeSettings settings;
        settings.resolution = resolution;
        settings.threads = threads;
        const Timed t = timeVoxelize(mesh, settings, repeat);
        const Int3 g = t.result.mask.size;
        std::printf("| %d | %dx%dx%d | %lld | %.2f | %+.4f%% |", resolution, g.x, g.y, g.z,
                    (long long)t.result.cellsInside, t.milliseconds, 100.0 * t.result.relativeError());
        if (analyticRadius > 0) {
            const double r = analyticRadius * t.result.placement.scale[0];
            const double exact = 4.0 / 3.0 * std::numbers::pi * r * r * r;
            std::printf(" %+.4f%% |", 100.0 * (double(t.result.cellsInside) - exact) / exact);
        }
        std::printf("\n");
    }
}

} // namespace

int main(int argc, char** argv) {
    int threads = 2, repeat = 3;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--threads") threads = std::max(1, std::atoi(argv[i + 1]));
        else if (flag == "--repeat") repeat = std::max(1, std::atoi(argv[i + 1]));
        else {
            std::fprintf(stderr, "voxelize_bench: unknown option %s (--threads N, --repeat N)\n", argv[i]);
            return 2;
        }
    }
    try {
        resolutionTable("Sphere (icosphere, 5 subdivisions)", makeIcosphereMesh(5, 1.0f), threads, repeat, 1.0);
        resolutionTable("Hourglass (models/hourglass.obj)", sandglass::loadMesh(sandglass::defaultModelPath()), threads,
                        repeat, 0.0);

        // About 200,000 triangles: a torus of 320 x 312 quads.
        const TriangleMesh dense = makeTorusMesh(1.0f, 0.4f, 320, 312);
        std::printf("\n### Dense closed mesh at 256 cells\n\n| triangles | threads | ms | error |\n|---|---|---|---|\n");
        for (int t : {1, threads}) {
            VoxelizeSettings settings;
            settings.resolution = 256;
            settings.threads = t;
            const Timed timed = timeVoxelize(dense, settings, repeat);
            std::printf("| %zu | %d | %.1f | %+.4f%% |\n", dense.triangles.size(), t, timed.milliseconds,
                        100.0 * timed.result.relativeError());
        }

        std::printf("\n### Binning against every row x every triangle, 128 cells, %d thread(s)\n\n", threads);
        std::printf("| mesh | triangles | binned ms | every row ms | speedup |\n|---|---|---|---|---|\n");
        for (const auto& [name, mesh] : {std::pair<const char*, TriangleMesh>{"sphere", makeIcosphereMesh(5, 1.0f)},
                                         {"hourglass", sandglass::loadMesh(sandglass::defaultModelPath())}}) {
            VoxelizeSettings settings;
            settings.resolution = 128;
            settings.threads = threads;
            const double binned = timeVoxelize(mesh, settings, repeat).milliseconds;
            settings.binning = false;
            const double brute = timeVoxelize(mesh, settings, 1).milliseconds;
            std::printf("| %s | %zu | %.2f | %.1f | %.0fx |\n", name, mesh.triangles.size(), binned, brute, brute / binned);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "voxelize_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
