// SPDX-License-Identifier: MIT
// Times SurfaceUpkeep::update on the million-grain hourglass drain as the renderer's GPU path
// uses it (bits only, optionally the column normals), with the caches evicted before each step as
// the frame drawn between two steps evicts them, and the stores of the moved places into a
// buffer of one 16-byte record per grain as the renderer makes them. Not part of the product.
//   upkeep_timing HEIGHT THREADS UPDATES [COLUMNS 0|1] [EVICT_MB]
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"
#include "sandcore/surface_upkeep.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace sandcore;

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

struct Place { // the renderer's GrainPlace: 16 bytes per grain
    std::uint32_t cell, level, cameFrom, movedStep;
};

} // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: upkeep_timing HEIGHT THREADS UPDATES [COLUMNS 0|1] [EVICT_MB]\n");
        return 2;
    }
    const int height = std::atoi(argv[1]);
    StepSettings step;
    step.threads = std::atoi(argv[2]);
    const int updates = std::atoi(argv[3]);
    const bool columns = argc > 4 && std::atoi(argv[4]) != 0;
    const int evictMegabytes = argc > 5 ? std::atoi(argv[5]) : 64;
    if (height < 8 || step.threads < 1 || updates < 1 || evictMegabytes < 0) {
        std::fprintf(stderr, "upkeep_timing: HEIGHT must be at least 8, THREADS and UPDATES at least 1, EVICT_MB not negative\n");
        return 2;
    }
    const std::size_t evictBytes = std::size_t(evictMegabytes) << 20;
    Scene scene = makeHourglassScene(makeHourglassMask({height, defaultNeckRadius(height), 0.0f}), {}, step);
    for (int i = 0; i < 400; ++i) scene.step();
    SurfaceUpkeep upkeep;
    upkeep.setTracking({false, false, columns});
    upkeep.rebuild(scene);
    upkeep.clearChanges();
    std::vector<Place> places(scene.grainCount());
    std::vector<char> evict(evictBytes);
    std::vector<double> updateMs, placesMs;
    double moves = 0.0, netChanges = 0.0;
    for (int i = 0; i < updates; ++i) {
        for (std::size_t b = 0; b < evict.size(); b += 64) evict[b] = char(evict[b] + 1);
        scene.step(); // its list of moves is warm for the update, the bits are not
        const auto start = std::chrono::steady_clock::now();
        upkeep.update(scene);
        updateMs.push_back(millisecondsSince(start));
        const auto placesStart = std::chrono::steady_clock::now();
        upkeep.forEachMovedPlace(scene.workers(), [&](const MovedPlace& p) {
            places[p.grain] = {p.cell, p.level, std::uint32_t(p.cameFrom), p.movedStep};
        });
        placesMs.push_back(millisecondsSince(placesStart));
        moves += double(scene.movedGrains().size());
        netChanges += double(upkeep.netChangesLastUpdate());
        upkeep.clearChanges();
    }
    std::printf("grains %lld  moves/step %.0f  net changes/step %.0f  update median %.3f ms  places median %.3f ms\n",
                (long long)scene.grainCount(), moves / updates, netChanges / updates, median(updateMs), median(placesMs));
    return 0;
}
