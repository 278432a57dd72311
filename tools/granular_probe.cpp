// SPDX-License-Identifier: MIT
// Measures the granular level from the command line while it is being tuned: the angle of a
// poured cone in 16 directions, the fall time, the discharge through hourglass necks and the
// cost against classic. Not part of the product; the bench report has the final figures.
//   granular_probe pour DEG GRAINS [WIDTH] [HEIGHT] [SEED] [g]  cone poured at one column of a
//                                             canvas: 16 rays, then 16 sectors of 5 rays each
//   granular_probe drain NECK [HEIGHT] [g]    discharge of a granular hourglass
//   granular_probe cost HEIGHT THREADS        ms per step, classic vs granular drain
//   granular_probe cost-in-turns HEIGHT THREADS  the same, both drains stepped in turns
//   granular_probe cost-kinds HEIGHT THREADS LEVEL...  drains in turns given one by one: c or g
//                                             (the rules)
//   granular_probe report DIR [quick]         the bench report's granular section alone (the full
//                                             report takes long): its files written into DIR, and
//                                             its section of DIR/README.md (from "## Granular
//                                             physics" to the line "Checks: ...") replaced
#include "bench/granular_report.hpp"
#include "sandcore/pile_slopes.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

using namespace sandcore;

namespace {

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

int pour(double degrees, int grains, int width, int height, std::uint64_t seed, double gravity) {
    StepSettings step;
    step.physics.gravity = float(gravity);
    step.seed = seed;
    step.physics.level = PhysicsLevel::Granular;
    step.physics.reposeDegrees = float(degrees);
    Scene scene = makeCanvasScene({{width, 4, width}, {width, height, width}}, step);
    const auto start = std::chrono::steady_clock::now();
    for (int added = 0; added < grains;) {
        added += scene.addGrain(GridLevel::Upper, pourCell(scene)) >= 0 ? 1 : 0;
        scene.step();
    }
    while (!scene.settled()) scene.step();
    const PileSlopes slopes = measurePileSlopes(scene.grid(GridLevel::Lower));
    std::printf("asked %.1f  grains %lld  steps %llu  %.1fs  peak %d at (%.1f, %.1f)\n", degrees,
                (long long)scene.grainCount(), (unsigned long long)scene.counters().stepsDone, seconds(start),
                slopes.peakHeight, slopes.peakX, slopes.peakZ);
    for (double d : slopes.degrees) std::printf(" %.2f", d);
    std::printf("\nmean %.2f min %.2f max %.2f\n", slopes.meanDegrees(), slopes.minDegrees(), slopes.maxDegrees());
    // The same directions, each the mean of 5 rays over its 22.5-degree sector: the flank's
    // grain-sized roughness, which one ray reads, averaged out.
    PileSlopeSettings sectors;
    sectors.raysPerDirection = 5;
    const PileSlopes smooth = measurePileSlopes(scene.grid(GridLevel::Lower), sectors);
    std::printf("sectors");
    for (double d : smooth.degrees) std::printf(" %.2f", d);
    std::printf("\nsector mean %.2f min %.2f max %.2f\n", smooth.meanDegrees(), smooth.minDegrees(), smooth.maxDegrees());
    return 0;
}

int drain(double neck, int height, double gravity, int threads) {
    StepSettings step;
    step.threads = threads;
    step.physics.level = PhysicsLevel::Granular;
    step.physics.gravity = float(gravity);
    Scene scene = makeHourglassScene(makeHourglassMask({height, float(neck), 0.0f}), {}, step);
    const std::int64_t total = scene.counters().grainsUpper;
    std::vector<std::int64_t> passed;
    const auto start = std::chrono::steady_clock::now();
    while (scene.counters().grainsUpper > 0 && passed.size() < 200000) {
        const std::int64_t before = scene.counters().grainsLower;
        scene.step();
        passed.push_back(scene.counters().grainsLower - before);
    }
    // CV over windows of 10 steps while 10% to 90% of the sand has passed.
    std::vector<double> rates;
    std::int64_t drained = 0, windowGrains = 0;
    int windowSteps = 0;
    for (std::int64_t p : passed) {
        drained += p;
        const double share = double(drained) / double(total);
        if (share < 0.1) continue;
        if (share > 0.9) break;
        windowGrains += p;
        if (++windowSteps == 10) {
            rates.push_back(double(windowGrains) / 10.0);
            windowGrains = 0;
            windowSteps = 0;
        }
    }
    const double mean = std::accumulate(rates.begin(), rates.end(), 0.0) / double(rates.size());
    double sq = 0;
    for (double r : rates) sq += (r - mean) * (r - mean);
    const double cv = std::sqrt(sq / double(rates.size() - 1)) / mean;
    std::printf("neck %.2f height %d g %.3f grains %lld steps %zu  rate %.3f (model %.3f)  CV %.2f%%  %.1fs\n", neck,
                height, gravity, (long long)total, passed.size(), mean, scene.neckFlowRate(), 100 * cv, seconds(start));
    // The rate in each tenth of the drain: where along it the cells fall short of the model.
    std::printf("rate by tenth of the sand passed:");
    std::int64_t tenthGrains = 0, tenthSteps = 0, sum = 0;
    int tenth = 0;
    for (std::int64_t p : passed) {
        sum += p, tenthGrains += p, ++tenthSteps;
        if (sum * 10 >= (tenth + 1) * total) {
            std::printf(" %.1f", double(tenthGrains) / double(tenthSteps));
            ++tenth, tenthGrains = 0, tenthSteps = 0;
        }
    }
    std::printf("\n");
    return 0;
}

double drainMsPerStep(int height, int threads, PhysicsLevel level, std::uint64_t& steps, std::uint64_t& hash) {
    StepSettings step;
    step.threads = threads;
    step.physics.level = level;
    Scene scene = makeHourglassScene(makeHourglassMask({height, defaultNeckRadius(height), 0.0f}), {}, step);
    const auto start = std::chrono::steady_clock::now();
    double visited = 0, moves = 0;
    while (!scene.settled() && scene.counters().stepsDone < 100000) {
        scene.step();
        visited += double(scene.counters().visitedLastStep);
        moves += double(scene.counters().movesLastStep);
    }
    steps = scene.counters().stepsDone;
    std::printf("  visited/step %.0f moves/step %.0f\n", visited / double(steps), moves / double(steps));
    hash = scene.stateHash();
    return 1000.0 * seconds(start) / double(steps);
}

int cost(int height, int threads) {
    for (PhysicsLevel level : {PhysicsLevel::Classic, PhysicsLevel::Granular}) {
        std::uint64_t steps = 0, hash = 0;
        const double ms = drainMsPerStep(height, threads, level, steps, hash);
        std::printf("%s: %llu steps, %.3f ms/step, hash %016llx\n", std::string(physicsLevelName(level)).c_str(),
                    (unsigned long long)steps, ms, (unsigned long long)hash);
    }
    return 0;
}

// Both levels' drains in one process, stepped in turns (sandbench::drainCostInTurns, the bench
// report's cost measure), so a busy machine slows both alike.
// One drain of a cost comparison: its rules, steps, time, moves, hash.
void printCost(const sandbench::DrainCost& cost) {
    std::printf("%s: %llu steps, %.3f ms/step, %.0f moves/step, hash %016llx%s\n",
                std::string(physicsLevelName(cost.level)).c_str(), (unsigned long long)cost.steps,
                cost.msPerStep, cost.movesPerStep, (unsigned long long)cost.hash, cost.conserved ? "" : " (grains lost)");
}

int costInTurns(int height, int threads) {
    StepSettings step;
    step.threads = threads;
    const auto costs = sandbench::drainCostInTurns(height, step);
    for (const auto& cost : costs) printCost(cost);
    std::printf("granular / classic: %.2fx\n", costs[1].msPerStep / costs[0].msPerStep);
    return 0;
}

// Drains in turns given one by one (sandbench::drainsInTurns): each LEVEL is the rules, c or g;
// prints each one's ms per step.
int costKinds(int height, int threads, int argc, char** argv) {
    StepSettings step;
    step.threads = threads;
    std::vector<PhysicsLevel> levels;
    for (int i = 4; i < argc; ++i) {
        const std::string level = argv[i];
        if (level != "c" && level != "g") {
            std::fprintf(stderr, "granular_probe: a drain is c or g; got '%s'\n", argv[i]);
            return 2;
        }
        levels.push_back(level == "g" ? PhysicsLevel::Granular : PhysicsLevel::Classic);
    }
    for (const auto& cost : sandbench::drainsInTurns(height, step, levels)) printCost(cost);
    return 0;
}

// The granular section of the bench report (sandbench::granularSection) into `dir`, as
// `sandglass bench --out DIR` writes it, spliced into DIR/README.md when that holds the section.
int report(const std::string& dir, bool quick) {
    sandbench::ReportOptions options;
    options.quick = quick;
    options.outDir = dir;
    std::filesystem::create_directories(options.outDir);
    const auto start = std::chrono::steady_clock::now();
    const sandbench::GranularSection section = sandbench::granularSection(options, std::cerr);
    const std::filesystem::path readme = options.outDir / "README.md";
    std::ifstream in(readme);
    std::stringstream text;
    text << in.rdbuf();
    std::string markdown = text.str();
    const std::size_t from = markdown.find("## Granular physics");
    const std::size_t to = from == std::string::npos ? from : markdown.find("\nChecks: ", from);
    if (from != std::string::npos && to != std::string::npos && from < to) {
        markdown.replace(from, to + 1 - from, section.markdown);
        std::ofstream(readme) << markdown;
        std::printf("replaced the granular section of %s\n", readme.string().c_str());
    } else {
        std::ofstream(options.outDir / "granular.md") << section.markdown;
        std::printf("no granular section in %s: wrote granular.md\n", readme.string().c_str());
    }
    std::printf("%s in %.1fs\n", section.passed ? "checks passed" : "some checks FAILED", seconds(start));
    return section.passed ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
    const std::string what = argc > 1 ? argv[1] : "";
    auto arg = [&](int i, double fallback) { return argc > i ? std::atof(argv[i]) : fallback; };
    if (what == "pour") return pour(arg(2, 33), int(arg(3, 40000)), int(arg(4, 120)), int(arg(5, 50)), std::uint64_t(arg(6, 1)), arg(7, 1.0));
    if (what == "drain") return drain(arg(2, 4), int(arg(3, 96)), arg(4, 0.05), int(arg(5, 1)));
    if (what == "cost") return cost(int(arg(2, 248)), int(arg(3, 2)));
    if (what == "cost-kinds") return costKinds(int(arg(2, 248)), int(arg(3, 2)), argc, argv);
    if (what == "cost-in-turns") return costInTurns(int(arg(2, 248)), int(arg(3, 2)));
    if (what == "report" && argc > 2) return report(argv[2], argc > 3 && std::string(argv[3]) == "quick");
    std::fprintf(stderr, "usage: granular_probe pour|drain|cost|cost-in-turns|cost-kinds|report ...\n");
    return 2;
}
