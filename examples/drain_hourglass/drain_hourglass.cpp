// SPDX-License-Identifier: MIT
// An hourglass from a mesh, run until the sand has drained: the recipe an embedder follows.
// A lathe profile becomes a closed surface of revolution, the voxelizer finds the cells inside
// it, and makeHourglassScene splits them at the neck and fills the upper bulb. Prints the grains
// in the upper and lower grid as the sand runs, and once more when nothing moves any more.
#include <sandcore/sandcore.hpp>

#include <cstdio>
#include <vector>

int main() {
    // Two bulbs joined by a narrow neck, listed bottom to top (model units; any scale works).
    const std::vector<sandcore::ProfilePoint> profile = {
        {0.0f, 0.0f}, {0.8f, 0.05f}, {1.0f, 0.5f}, {0.8f, 1.2f}, {0.2f, 1.9f}, {0.12f, 2.0f},
        {0.2f, 2.1f}, {0.8f, 2.8f}, {1.0f, 3.5f}, {0.8f, 3.95f}, {0.0f, 4.0f}};
    const sandcore::TriangleMesh glass = sandcore::makeLatheMesh(profile, 48);

    sandcore::VoxelizeSettings voxels;
    voxels.resolution = 48; // cells along the glass's height
    const sandcore::VoxelizeResult inside = sandcore::voxelize(glass, voxels);

    sandcore::StepSettings step;
    step.threads = 2;
    sandcore::Scene scene = sandcore::makeHourglassScene(inside.mask, {}, step);
    std::printf("hourglass of %lld grains: upper %lld, lower %lld\n", (long long)scene.grainCount(),
                (long long)scene.counters().grainsUpper, (long long)scene.counters().grainsLower);

    constexpr int kMaxSteps = 100'000;
    while (!scene.settled() && scene.counters().stepsDone < kMaxSteps) {
        scene.step();
        if (scene.counters().stepsDone % 200 == 0)
            std::printf("step %5llu: upper %lld, lower %lld\n", (unsigned long long)scene.counters().stepsDone,
                        (long long)scene.counters().grainsUpper, (long long)scene.counters().grainsLower);
    }
    const sandcore::SceneCounters& done = scene.counters();
    std::printf("drained after %llu steps: upper %lld, lower %lld\n", (unsigned long long)done.stepsDone,
                (long long)done.grainsUpper, (long long)done.grainsLower);
    // The sand must all have run through: the example fails loudly if the library broke that.
    return done.grainsUpper == 0 && done.grainsLower == scene.grainCount() ? 0 : 1;
}
