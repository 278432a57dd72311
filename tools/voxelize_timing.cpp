// SPDX-License-Identifier: MIT
// Times the voxelizer on dense generated meshes (about 1.3 million triangles: an icosphere and a
// torus), next to the step-by-step public functions it replaces and to the cavity search that
// follows it for an hourglass model (surface cells and flood fill, S8):
//   cmake --build --preset release --target voxelize_timing && build/release/tools/voxelize_timing [RES] [THREADS] [ROUNDS]
// Prints, per part, the median and the best wall time of ROUNDS runs and the median CPU time of
// the process (all threads; on shared cores the wall time also holds time spent waiting for a
// core), and the cells inside, which must not change with the code.
//   voxelize_timing --write-ply DIR  writes the two meshes as binary PLY (DIR/icosphere.ply,
// DIR/torus.ply), for timing the first voxelize of a fresh process through the command line:
//   sandglass voxelize DIR/icosphere.ply --res 256 --threads 2 --scene sculpture --json
#include "sandcore/cavity.hpp"
#include "sandcore/mesh_shapes.hpp"
#include "sandcore/voxelizer.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

using namespace sandcore;

namespace {

double cpuMs() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return (double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) * 1e6 + double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec)) / 1e3;
}

struct Timing {
    double median = 0, best = 0, cpuMedian = 0; // ms
};

Timing timeRuns(int rounds, const std::function<void()>& run) {
    std::vector<double> wall, cpu;
    for (int i = 0; i < rounds; ++i) {
        const double cpuStart = cpuMs();
        const auto start = std::chrono::steady_clock::now();
        run();
        wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        cpu.push_back(cpuMs() - cpuStart);
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    return {wall[wall.size() / 2], wall.front(), cpu[cpu.size() / 2]};
}

void timeMesh(const char* name, const TriangleMesh& mesh, int resolution, int threads, int rounds) {
    VoxelizeSettings settings;
    settings.resolution = resolution;
    settings.threads = threads;
    VoxelizeResult result;
    const Timing steps = timeRuns(rounds, [&] { (void)closednessOf(mesh); });
    const Timing whole = timeRuns(rounds, [&] { result = voxelize(mesh, settings); });
    CavitySearch search;
    const Timing cavity = timeRuns(rounds, [&] {
        InsideMask walls = result.mask;
        const InsideMask surface = surfaceCells(toGridSpace(mesh, result.placement), result.placement.size);
        for (std::size_t n = 0; n < walls.inside.size(); ++n) walls.inside[n] |= surface.inside[n];
        search = findCavities(walls);
    });
    std::printf("%-9s %zu triangles res %d, %d threads (ms: median / best wall, median CPU)\n"
                "  voxelize      %7.1f / %7.1f  cpu %7.1f   %lld cells inside, closed %s\n"
                "  closednessOf  %7.1f / %7.1f  cpu %7.1f   (weld + edge walk of the step-by-step functions)\n"
                "  cavity search %7.1f / %7.1f  cpu %7.1f   surface cells + flood fill, %lld outside cells\n",
                name, mesh.triangles.size(), resolution, threads, whole.median, whole.best, whole.cpuMedian,
                static_cast<long long>(result.cellsInside), result.closedness.closed ? "yes" : "no", steps.median,
                steps.best, steps.cpuMedian, cavity.median, cavity.best, cavity.cpuMedian,
                static_cast<long long>(search.outsideCells));
}

// Binary little-endian PLY: float x y z per vertex, a uchar count and three int indices per face.
bool writeBinaryPly(const std::string& path, const TriangleMesh& mesh) {
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << mesh.vertices.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.triangles.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const Vec3& v : mesh.vertices) {
        const float xyz[3] = {v.x, v.y, v.z};
        out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
    }
    for (const auto& t : mesh.triangles) {
        const unsigned char corners = 3;
        const std::int32_t indices[3] = {std::int32_t(t[0]), std::int32_t(t[1]), std::int32_t(t[2])};
        out.write(reinterpret_cast<const char*>(&corners), 1);
        out.write(reinterpret_cast<const char*>(indices), sizeof indices);
    }
    return bool(out.flush());
}

TriangleMesh icosphere() { return makeIcosphereMesh(8, 1.0f); }          // 1,310,720 triangles
TriangleMesh torus() { return makeTorusMesh(1.0f, 0.4f, 1024, 640); } // 1,310,720 triangles

} // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::strcmp(argv[1], "--write-ply") == 0) {
        const std::string dir = argv[2];
        for (const auto& [name, mesh] : {std::pair{"icosphere", icosphere()}, std::pair{"torus", torus()}})
            if (!writeBinaryPly(dir + "/" + name + ".ply", mesh)) {
                std::fprintf(stderr, "voxelize_timing: cannot write %s/%s.ply\n", dir.c_str(), name);
                return 1;
            }
        return 0;
    }
    const int resolution = argc > 1 ? std::atoi(argv[1]) : 256;
    const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
    const int rounds = argc > 3 ? std::atoi(argv[3]) : 5;
    if (resolution < 1 || threads < 1 || rounds < 1) {
        std::fprintf(stderr, "usage: voxelize_timing [RES >= 1] [THREADS >= 1] [ROUNDS >= 1] | --write-ply DIR\n");
        return 2;
    }
    timeMesh("icosphere", icosphere(), resolution, threads, rounds);
    timeMesh("torus", torus(), resolution, threads, rounds);
    return 0;
}
