// SPDX-License-Identifier: MIT
#include "bench/simulation_bench.hpp"

#include "scene/hex.hpp"
#include "scene/statistics.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <algorithm>
#include <chrono>

namespace sandbench {

namespace {

DrainRun drain(int resolution, bool sleeping, int threads, std::uint64_t seed) {
    using Clock = std::chrono::steady_clock;
    sandcore::HourglassShape shape;
    shape.height = resolution;
    shape.neckRadius = sandcore::defaultNeckRadius(resolution); // as `sandglass simulate` does
    sandcore::StepSettings step;
    step.seed = seed;
    step.threads = threads;
    step.sleeping = sleeping;
    sandcore::Scene scene = sandcore::makeHourglassScene(sandcore::makeHourglassMask(shape), {}, step);

    DrainRun run;
    run.resolution = resolution;
    run.grains = scene.grainCount();
    run.cells = std::int64_t(scene.grid(sandcore::GridLevel::Upper).cellCount()) +
                std::int64_t(scene.grid(sandcore::GridLevel::Lower).cellCount());
    run.sleeping = sleeping;
    run.threads = threads;
    std::vector<double> milliseconds;
    const auto start = Clock::now();
    while (!scene.settled()) {
        const auto before = Clock::now();
        scene.step();
        milliseconds.push_back(std::chrono::duration<double, std::milli>(Clock::now() - before).count());
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    run.steps = std::int64_t(milliseconds.size());
    run.medianMs = sandglass::medianOf(milliseconds);
    run.stepsPerSecond = seconds > 0 ? double(run.steps) / seconds : 0.0;
    run.conserved = scene.grid(sandcore::GridLevel::Upper).countGrains() +
                        scene.grid(sandcore::GridLevel::Lower).countGrains() ==
                    run.grains;
    run.hash = scene.stateHash();
    return run;
}

} // namespace

std::vector<DrainRun> measureDrains(const std::vector<int>& resolutions, const sandcore::StepSettings& step) {
    std::vector<DrainRun> runs;
    for (int resolution : resolutions)
        for (bool sleeping : {true, false})
            for (int threads : {1, step.threads}) runs.push_back(drain(resolution, sleeping, threads, step.seed));
    return runs;
}

Table drainTable(const std::vector<DrainRun>& runs) {
    Table table{{"res", "grains", "cells", "steps", "mode", "threads", "median ms/step", "steps/s", "conserved",
                 "same state as first run"},
                {}};
    for (const DrainRun& run : runs) {
        const auto first = std::find_if(runs.begin(), runs.end(),
                                        [&](const DrainRun& r) { return r.resolution == run.resolution; });
        table.rows.push_back({std::to_string(run.resolution), std::to_string(run.grains), std::to_string(run.cells),
                              std::to_string(run.steps), run.sleeping ? "sleeping" : "full sweep",
                              std::to_string(run.threads), fixed(run.medianMs, 3), fixed(run.stepsPerSecond, 0),
                              run.conserved ? "yes" : "NO",
                              first->hash == run.hash ? "yes (" + sandglass::toHex16(run.hash) + ")" : "NO"});
    }
    return table;
}

bool drainsAgree(const std::vector<DrainRun>& runs) {
    return std::all_of(runs.begin(), runs.end(), [&](const DrainRun& run) {
        const auto first = std::find_if(runs.begin(), runs.end(),
                                        [&](const DrainRun& r) { return r.resolution == run.resolution; });
        return run.conserved && run.hash == first->hash && run.steps == first->steps;
    });
}

} // namespace sandbench
