// Times the voxelizer on dense generated meshes (about 1.3 million triangles: an icosphere and a
// torus), split into its parts, so the closedness check can be weighed against ray casting:
//   cmake --build --preset release --target voxelize_timing && build/release/tools/voxelize_timing [RES] [THREADS] [ROUNDS]
// Prints medians of ROUNDS runs, and the cells inside, which must not change with the code.
#include "sandcore/mesh_shapes.hpp"
#include "sandcore/voxelizer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

using namespace sandcore;

namespace {

double medianMs(int rounds, const std::function<void()>& run) {
    std::vector<double> ms;
    for (int i = 0; i < rounds; ++i) {
        const auto start = std::chrono::steady_clock::now();
        run();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

void timeMesh(const char* name, const TriangleMesh& mesh, int resolution, int threads, int rounds) {
    VoxelizeSettings settings;
    settings.resolution = resolution;
    settings.threads = threads;
    VoxelizeResult result;
    const double weld = medianMs(rounds, [&] { (void)weldVertices(mesh); });
    const double closedness = medianMs(rounds, [&] { (void)closednessOf(mesh); });
    const double whole = medianMs(rounds, [&] { result = voxelize(mesh, settings); });
    std::printf("%-9s %9zu triangles  res %d  %d threads | weld %7.1f ms | closednessOf %7.1f ms | voxelize %7.1f ms | "
                "%lld cells inside, closed %s\n",
                name, mesh.triangles.size(), resolution, threads, weld, closedness, whole,
                static_cast<long long>(result.cellsInside), result.closedness.closed ? "yes" : "no");
}

} // namespace

int main(int argc, char** argv) {
    const int resolution = argc > 1 ? std::atoi(argv[1]) : 256;
    const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
    const int rounds = argc > 3 ? std::atoi(argv[3]) : 5;
    if (resolution < 1 || threads < 1 || rounds < 1) {
        std::fprintf(stderr, "usage: voxelize_timing [RES >= 1] [THREADS >= 1] [ROUNDS >= 1]\n");
        return 2;
    }
    timeMesh("icosphere", makeIcosphereMesh(8, 1.0f), resolution, threads, rounds);   // 1,310,720 triangles
    timeMesh("torus", makeTorusMesh(1.0f, 0.4f, 1024, 640), resolution, threads, rounds); // 1,310,720 triangles
    return 0;
}
