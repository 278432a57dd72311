// SPDX-License-Identifier: MIT
#include "bench/throughput_bench.hpp"

#include "scene/hex.hpp"
#include "scene/statistics.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>
#include <thread>

namespace sandbench {

namespace {

using Clock = std::chrono::steady_clock;

// Steps a run takes before the next run's turn (see measureMoveRates).
constexpr int kStepsPerTurn = 16;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Writes `count` 4-byte values to pseudo-random places of cells (a power-of-two count); returns
// a value that depends on every write, so the compiler keeps them.
std::uint32_t randomWrites(std::uint32_t* cells, std::size_t mask, std::size_t count, std::uint64_t seed) {
    std::uint64_t state = seed * 0x9E3779B97F4A7C15ull + 1;
    for (std::size_t i = 0; i < count; ++i) {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        cells[state & mask] = std::uint32_t(i);
    }
    return cells[state & mask];
}

// Each thread writes to random places of its own part of cells (a power of two), so no two
// threads share a place.
double randomWriteRate(std::uint32_t* cells, std::size_t cellCount, int threads) {
    std::size_t part = cellCount;
    while (part * std::size_t(threads) > cellCount) part /= 2;
    const std::size_t writesPerThread = part / 2;
    std::vector<std::thread> workers;
    std::vector<std::uint32_t> sinks(std::size_t(threads), 0);
    auto work = [&](int t) {
        sinks[std::size_t(t)] = randomWrites(cells + std::size_t(t) * part, part - 1, writesPerThread, std::uint64_t(t) + 1);
    };
    const auto start = Clock::now();
    for (int t = 1; t < threads; ++t) workers.emplace_back(work, t);
    work(0);
    for (std::thread& w : workers) w.join();
    const double seconds = secondsSince(start);
    return seconds > 0 ? double(writesPerThread) * threads / seconds : 0.0;
}

MoveRate emptyRun(int resolution, int threads, const sandcore::Scene& scene) {
    MoveRate run;
    run.resolution = resolution;
    run.threads = threads;
    run.grains = scene.grainCount();
    return run;
}

} // namespace

MemoryCeiling measureMemoryCeiling(std::size_t bufferBytes, int threads) {
    MemoryCeiling ceiling;
    std::size_t cellCount = 1024;
    while (cellCount * 2 * sizeof(std::uint32_t) <= bufferBytes) cellCount *= 2; // a power of two
    ceiling.bufferBytes = cellCount * sizeof(std::uint32_t);
    ceiling.threads = threads;
    std::vector<std::uint32_t> source(cellCount, 1), target(cellCount, 0);
    double best = 0.0;
    for (int round = 0; round < 3; ++round) {
        const auto start = Clock::now();
        std::memcpy(target.data(), source.data(), ceiling.bufferBytes);
        const double seconds = secondsSince(start);
        if (seconds > 0) best = std::max(best, 2.0 * double(ceiling.bufferBytes) / seconds / 1e9);
        source[std::size_t(round)] = target[std::size_t(round) + 1]; // the copies depend on each other
    }
    ceiling.copyGigabytesPerSecond = best;
    ceiling.randomWritesPerSecond = randomWriteRate(target.data(), cellCount, 1);
    ceiling.randomWritesPerSecondThreads = randomWriteRate(target.data(), cellCount, threads);
    return ceiling;
}

std::vector<MoveRate> measureMoveRates(int resolution, const std::vector<int>& threads, const sandcore::StepSettings& step) {
    sandcore::HourglassShape shape;
    shape.height = resolution;
    shape.neckRadius = sandcore::defaultNeckRadius(resolution);
    sandcore::StepSettings oneThread = step;
    oneThread.threads = 1;
    const sandcore::Scene start = sandcore::makeHourglassScene(sandcore::makeHourglassMask(shape), {}, oneThread);
    std::vector<sandcore::Scene> scenes;
    std::vector<MoveRate> runs;
    std::vector<std::vector<double>> milliseconds(threads.size());
    for (int t : threads) {
        scenes.push_back(start.clone());
        scenes.back().setThreads(t);
        runs.push_back(emptyRun(resolution, t, start));
    }
    // The runs take turns in blocks of kStepsPerTurn steps: a burst of load from elsewhere still hits
    // every run alike, while a step mostly finds its own scene in the caches and its worker awake,
    // as in the application, where one scene is stepped. Turns of one step measure something else:
    // each step starts with the other scene's grids in the caches and, on 2 threads, a worker that
    // slept through the other scene's whole step.
    for (bool busy = true; busy;) {
        busy = false;
        for (std::size_t i = 0; i < scenes.size(); ++i)
            for (int turn = 0; turn < kStepsPerTurn && !scenes[i].settled(); ++turn) {
                busy = true;
                const auto before = Clock::now();
                scenes[i].step();
                const double seconds = secondsSince(before);
                milliseconds[i].push_back(1000.0 * seconds);
                runs[i].stepSeconds += seconds;
                runs[i].moves += scenes[i].counters().movesLastStep;
            }
    }
    for (std::size_t i = 0; i < runs.size(); ++i) {
        runs[i].steps = std::int64_t(milliseconds[i].size());
        runs[i].medianMs = sandglass::medianOf(milliseconds[i]);
        runs[i].movesPerSecond = runs[i].stepSeconds > 0 ? double(runs[i].moves) / runs[i].stepSeconds : 0.0;
        runs[i].hash = scenes[i].stateHash();
    }
    return runs;
}

Table ceilingTable(const MemoryCeiling& ceiling) {
    Table table{{"measure", "value"}, {}};
    table.rows.push_back({"memory copy (read + write), " + std::to_string(ceiling.bufferBytes >> 20) + " MiB buffer",
                          fixed(ceiling.copyGigabytesPerSecond, 1) + " GB/s"});
    table.rows.push_back({"random 4-byte writes, 1 thread", fixed(ceiling.randomWritesPerSecond / 1e6, 1) + " M/s"});
    table.rows.push_back({"random 4-byte writes, " + std::to_string(ceiling.threads) + " threads",
                          fixed(ceiling.randomWritesPerSecondThreads / 1e6, 1) + " M/s"});
    return table;
}

Table moveRateTable(const std::vector<MoveRate>& runs, const MemoryCeiling& ceiling) {
    Table table{{"res", "grains", "threads", "steps", "moves", "median ms/step", "moves/s (M)",
                 "random writes/s of the machine (M)", "random writes the machine could do per move",
                 "speed-up over 1 thread", "same state"},
                {}};
    const MoveRate* single = nullptr;
    for (const MoveRate& run : runs)
        if (run.threads == 1) single = &run;
    for (const MoveRate& run : runs) {
        const double writes = run.threads == 1 ? ceiling.randomWritesPerSecond : ceiling.randomWritesPerSecondThreads;
        const double speedUp = single && run.stepSeconds > 0 ? single->stepSeconds / run.stepSeconds : 0.0;
        table.rows.push_back({std::to_string(run.resolution), std::to_string(run.grains), std::to_string(run.threads),
                              std::to_string(run.steps), std::to_string(run.moves), fixed(run.medianMs, 3),
                              fixed(run.movesPerSecond / 1e6, 1), fixed(writes / 1e6, 1),
                              run.movesPerSecond > 0 ? fixed(writes / run.movesPerSecond, 1) : "-",
                              single ? fixed(speedUp, 2) + "x" : "-",
                              single && single->hash == run.hash ? "yes (" + sandglass::toHex16(run.hash) + ")" : "NO"});
    }
    return table;
}

} // namespace sandbench
