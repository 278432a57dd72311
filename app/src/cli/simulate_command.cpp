// SPEC C1: `sandglass simulate` runs a scene headless and reports grains, moves, the state hash
// and the speed, as text or one JSON object.
#include "app/cli/commands.hpp"
#include "scene/hex.hpp"
#include "scene/scene_request.hpp"
#include "scene/statistics.hpp"

#include "sandcore/scenes.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace sandglass {

namespace {

struct SimulateOptions {
    std::string scene = "hourglass";
    SceneRequest request;
    std::int64_t steps = -1;
    bool untilSettled = false;
    std::int64_t maxSteps = 10'000'000;
    std::uint64_t seed = 1;
    int threads = 1;
    bool fullSweep = false;
    std::int64_t pour = 0;
    bool json = false;
};

int runSimulate(SimulateOptions& options) {
    using Clock = std::chrono::steady_clock;
    options.request.kind = parseSceneKind(options.scene);
    requireNoShapeForCanvas(options.request);
    if (options.steps < 0 && !options.untilSettled) options.steps = 1000;
    if (!options.request.modelPath.empty() && options.request.kind == sandcore::SceneKind::Canvas)
        throw std::invalid_argument("--model shapes an hourglass or a sculpture; the canvas has no model");
    if (options.pour > 0 && options.request.kind != sandcore::SceneKind::Canvas)
        throw std::invalid_argument("--pour releases sand on the canvas; use it with --scene canvas");

    sandcore::StepSettings step;
    step.seed = options.seed;
    step.threads = options.threads;
    step.sleeping = !options.fullSweep;
    sandcore::Scene scene = buildScene(options.request, step);

    const std::int64_t grainsInitial = scene.grainCount();
    const std::int64_t stepLimit = options.untilSettled ? options.maxSteps : options.steps;
    const std::uint32_t pourAt = sandcore::pourCell(scene);
    std::vector<double> stepMilliseconds;
    stepMilliseconds.reserve(std::size_t(std::min<std::int64_t>(stepLimit, 1'000'000)));
    std::int64_t moves = 0, visited = 0, done = 0;
    const auto start = Clock::now();
    while (done < stepLimit) {
        if (done < options.pour) scene.addGrain(sandcore::GridLevel::Upper, pourAt);
        const auto before = Clock::now();
        scene.step();
        stepMilliseconds.push_back(std::chrono::duration<double, std::milli>(Clock::now() - before).count());
        moves += scene.counters().movesLastStep;
        visited += scene.counters().visitedLastStep;
        ++done;
        if (options.untilSettled && done >= options.pour && scene.settled()) break;
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const double stepsPerSecond = seconds > 0 ? double(done) / seconds : 0.0;
    const std::string hash = toHex16(scene.stateHash());

    if (options.json) {
        nlohmann::ordered_json out;
        out["scene"] = options.scene;
        out["grains_initial"] = grainsInitial;
        out["grains"] = scene.grainCount();
        out["steps"] = done;
        out["moves"] = moves;
        out["cells_visited"] = visited;
        out["hash"] = hash;
        out["seconds"] = seconds;
        out["steps_per_second"] = stepsPerSecond;
        out["threads"] = options.threads;
        out["settled"] = scene.settled();
        out["sleeping"] = !options.fullSweep;
        out["median_ms_per_step"] = medianOf(stepMilliseconds);
        out["grains_upper"] = scene.counters().grainsUpper;
        out["grains_lower"] = scene.counters().grainsLower;
        std::cout << out.dump() << "\n";
        return 0;
    }
    std::printf("scene %s: %lld grains (%lld at start), %lld in the upper grid, %lld in the lower grid\n",
                options.scene.c_str(), (long long)scene.grainCount(), (long long)grainsInitial,
                (long long)scene.counters().grainsUpper, (long long)scene.counters().grainsLower);
    std::printf("%lld steps, %lld moves, %s\n", (long long)done, (long long)moves,
                scene.settled() ? "settled" : "still moving");
    std::printf("%.3f s, %.1f steps/s, median %.3f ms per step, %d thread(s), %s\n", seconds, stepsPerSecond,
                medianOf(stepMilliseconds), options.threads, options.fullSweep ? "full sweep" : "sleeping grains skipped");
    std::printf("state hash %s\n", hash.c_str());
    return 0;
}

} // namespace

void addSimulateCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<SimulateOptions>();
    CLI::App* cmd = app.add_subcommand("simulate", "Run a scene headless and report grains, moves, hash and speed");
    cmd->add_option("--scene", options->scene, "hourglass, sculpture or canvas")->capture_default_str();
    cmd->add_option("--shape", options->request.shape,
                    "procedural shape: sphere, cube or hourglass (default: hourglass for the hourglass, sphere for "
                    "the sculpture)");
    cmd->add_option("--model", options->request.modelPath,
                    "model file (OBJ, STL, PLY, glTF, ... ) for the hourglass vessel or the sculpture");
    cmd->add_flag("--stretch", options->request.stretch, "model: scale every axis to --res cells (aspect not kept)");
    cmd->add_flag("--robust", options->request.robust, "model: majority-vote inside test for open meshes");
    cmd->add_option("--noise", options->request.noiseThreshold,
                    "model: noNoise removes cells with at most this many inside face neighbours (-1 = off)")
        ->capture_default_str()
        ->check(CLI::Range(-1, 5));
    cmd->add_option("--res", options->request.resolution,
                    "cells along the shape's largest extent (default 64; the canvas: its width, default 60)")
        ->check(CLI::Range(1, 1 << 20));
    cmd->add_option("--neck", options->request.neckRadius, "neck radius of the procedural hourglass, cells (0 = auto)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--fill", options->request.fillFraction, "share of the upper bulb filled at the start (0..1]")
        ->capture_default_str();
    auto* steps = cmd->add_option("--steps", options->steps, "number of steps (default 1000)")->check(CLI::NonNegativeNumber);
    auto* settled = cmd->add_flag("--until-settled", options->untilSettled, "run until a step moves nothing");
    steps->excludes(settled);
    cmd->add_option("--max-steps", options->maxSteps, "upper bound for --until-settled")->capture_default_str();
    cmd->add_option("--seed", options->seed, "seed of the slip randomness")->capture_default_str();
    cmd->add_option("--threads", options->threads, "worker threads (the result does not depend on it)")
        ->capture_default_str()
        ->check(CLI::Range(1, 256));
    cmd->add_flag("--full-sweep", options->fullSweep, "visit every cell each step (R5 off; same result, slower)");
    cmd->add_option("--pour", options->pour, "canvas: release one grain per step at the centre for N steps")
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag("--json", options->json, "print one JSON object");
    cmd->callback([options, &exitCode] { exitCode = runSimulate(*options); });
}

} // namespace sandglass
