// SPDX-License-Identifier: MIT
// SPEC C1: `sandglass simulate` runs a scene headless and reports grains, moves, the state hash
// and the speed, as text or one JSON object.
#include "app/cli/checked_options.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/model_shape_json.hpp"
#include "app/cli/terminal_progress.hpp"
#include "app/cli/scene_options.hpp"
#include "scene/digger.hpp"
#include "scene/file_io.hpp"
#include "scene/hex.hpp"
#include "scene/hourglass_timer.hpp"
#include "scene/scene_export.hpp"
#include "scene/scene_request.hpp"
#include "scene/state_file.hpp"
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

// 10^12 steps: days of running at the fastest rates; beyond that a typo, not a request.
constexpr std::int64_t kMaxSteps = 1'000'000'000'000;

struct SimulateOptions {
    SceneOptions scene;
    std::int64_t steps = -1;
    bool untilSettled = false;
    std::int64_t maxSteps = 10'000'000;
    bool fullSweep = false;
    std::int64_t pour = 0;
    std::vector<std::int64_t> flipAt;
    double duration = 0.0;
    bool json = false;
    std::string load;       ///< E1: a state file to go on from instead of building a scene
    std::string save;       ///< E1: where to save the state after the run
    std::string exportFile; ///< E2: where to export the sand after the run (.ply .vox .obj .stl .glb)
    std::string trace; // CSV file: one row per step (SPEC PH7)
    std::string dig;            ///< a path "X,Y,Z X,Y,Z ..." a body is driven along (the digger)
    std::string digBody = "blade"; ///< blade, box, ball or a model file
    int digSpeed = 1;           ///< unit moves per step
};

// The scene to run: a loaded state (the file's seed and settings, unless given here) or a new build.
// A built scene carries the model's report (S7-S9); a loaded state has none.
BuiltScene sceneFor(const SimulateOptions& options, const CLI::App& command, SceneSettings& settings) {
    if (options.load.empty()) return buildSceneWithReport(settings);
    LoadedState loaded = loadState(options.load);
    if (command.count("--threads")) loaded.scene.setThreads(settings.step.threads);
    if (command.count("--seed")) loaded.scene.setSeed(settings.step.seed);
    if (options.fullSweep) loaded.scene.setSleeping(false);
    settings = loaded.settings;
    settings.step = loaded.scene.settings();
    return BuiltScene(std::move(loaded.scene));
}

int runSimulate(const SimulateOptions& options, const CLI::App& command) {
    using Clock = std::chrono::steady_clock;
    SceneSettings settings = sceneSettingsFrom(options.scene);
    settings.step.sleeping = !options.fullSweep;
    // Outputs are checked before the run, so a long run never ends in an unwritable path.
    if (!options.save.empty()) requireWritableFileTarget(options.save);
    if (!options.exportFile.empty()) {
        exportFormatOf(options.exportFile);
        requireWritableFileTarget(options.exportFile);
    }
    BuiltScene built = sceneFor(options, command, settings);
    sandcore::Scene& scene = built.scene;
    const bool canvas = settings.request.kind == sandcore::SceneKind::Canvas;
    if (options.pour > 0 && !canvas)
        throw std::invalid_argument("--pour releases sand on the canvas; use it with --scene canvas");

    // The digger: checked and placed before the run, so a bad path fails at once.
    std::unique_ptr<DigDrive> dig;
    std::vector<int> heightsBeforeDig;
    std::vector<sandcore::Int3> digPath;
    if (!options.dig.empty()) {
        if (!canvas) throw std::invalid_argument("--dig drives a body through a canvas; use it with --scene sandbox or canvas");
        digPath = parseDigPath(options.dig);
        const int width = scene.grid(sandcore::GridLevel::Lower).size().x;
        const int bed = sandcore::defaultSandboxBedDepth(sandcore::canvasSettingsForWidth(width));
        heightsBeforeDig = lowerColumnHeights(scene);
        dig = std::make_unique<DigDrive>(scene, makeDigBodyShape(options.digBody, width, bed), digPath, options.digSpeed);
    }
    std::int64_t digSteps = 0;

    const std::int64_t grainsInitial = scene.grainCount();
    if (options.pour > 0) {
        std::int64_t room = 0;
        for (sandcore::GridLevel level : {sandcore::GridLevel::Upper, sandcore::GridLevel::Lower})
            for (sandcore::CellValue cell : scene.grid(level).cells()) room += cell == sandcore::kEmpty;
        // The grids share one row, so their empty cells overcount by up to that row.
        room -= std::int64_t(scene.grid(sandcore::GridLevel::Lower).layerSize());
        if (options.pour > room)
            throw std::invalid_argument("--pour " + std::to_string(options.pour) + ": the canvas holds at most " +
                                        std::to_string(std::max<std::int64_t>(room, 0)) + " grains at --res " +
                                        std::to_string(settings.request.resolution));
    }
    // The timer: the drain of this very scene is predicted and the rate set to fit the duration.
    std::int64_t drainSteps = 0;
    double stepsPerSecondSet = 0.0;
    if (options.duration > 0.0) {
        drainSteps = predictDrainSteps(scene);
        stepsPerSecondSet = double(drainSteps) / options.duration;
    }
    std::vector<std::int64_t> flips = options.flipAt;
    std::sort(flips.begin(), flips.end());
    std::size_t nextFlip = 0;
    auto flipDue = [&](std::int64_t afterStep) {
        for (; nextFlip < flips.size() && flips[nextFlip] == afterStep; ++nextFlip)
            if (!scene.flip()) throw std::invalid_argument("--flip-at turns an hourglass; this scene cannot be turned");
    };
    flipDue(0);
    const std::int64_t steps = options.steps >= 0 ? options.steps : 1000;
    const std::int64_t stepLimit = options.untilSettled ? options.maxSteps : steps;
    const std::uint32_t pourAt = sandcore::pourCell(scene);
    StreamingMedian stepMilliseconds, digMilliseconds;
    std::int64_t moves = 0, visited = 0, done = 0, poured = 0;
    std::string trace = options.trace.empty() ? std::string() : "step,grains_upper,grains_lower,moves\n";
    const auto start = Clock::now();
    // On a terminal only: --json and piped output stay as they are.
    TerminalProgress progress("simulate", "steps");
    while (done < stepLimit) {
        progress.update(double(done), options.untilSettled ? 0.0 : double(stepLimit));
        // A pour waits while its cell is still taken, so every grain asked for is released.
        if (poured < options.pour && scene.addGrain(sandcore::GridLevel::Upper, pourAt) >= 0) ++poured;
        const auto before = Clock::now();
        // The body's moves count in the step's time: they are what digging costs a step.
        if (dig && !dig->done()) {
            dig->beforeStep(scene);
            digMilliseconds.add(std::chrono::duration<double, std::milli>(Clock::now() - before).count());
            ++digSteps;
            if (dig->done()) scene.removeBody(dig->body()); // lifted out at the end of its path
        }
        scene.step();
        stepMilliseconds.add(std::chrono::duration<double, std::milli>(Clock::now() - before).count());
        moves += scene.counters().movesLastStep;
        visited += scene.counters().visitedLastStep;
        ++done;
        if (!options.trace.empty()) {
            const sandcore::SceneCounters& c = scene.counters();
            trace += std::to_string(c.stepsDone) + ',' + std::to_string(c.grainsUpper) + ',' +
                     std::to_string(c.grainsLower) + ',' + std::to_string(c.movesLastStep) + '\n';
        }
        flipDue(done);
        if (options.untilSettled && poured >= options.pour && scene.settled()) break;
    }
    progress.finish();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (!options.trace.empty()) writeFileAtomically(options.trace, trace);
    const double stepsPerSecond = seconds > 0 ? double(done) / seconds : 0.0;
    const std::string hash = toHex16(scene.stateHash());
    const std::string sceneName = sceneNameOf(settings.request);
    const int threads = scene.settings().threads;
    if (!options.save.empty()) saveState(options.save, scene, settings.request);
    if (!options.exportFile.empty())
        exportScene(options.exportFile, scene, {{}, built.modelToWorld ? &*built.modelToWorld : nullptr});

    if (options.json) {
        nlohmann::ordered_json out;
        out["scene"] = sceneName;
        out["grains_initial"] = grainsInitial;
        out["grains"] = scene.grainCount();
        out["steps"] = done;
        out["moves"] = moves;
        out["cells_visited"] = visited;
        out["hash"] = hash;
        out["seconds"] = seconds;
        out["steps_per_second"] = stepsPerSecond;
        out["threads"] = threads;
        out["settled"] = scene.settled();
        out["sleeping"] = !options.fullSweep;
        out["physics"] = std::string(sandcore::physicsLevelName(settings.step.physics.level));
        out["median_ms_per_step"] = stepMilliseconds.median();
        out["grains_upper"] = scene.counters().grainsUpper;
        out["grains_lower"] = scene.counters().grainsLower;
        if (options.pour > 0) out["poured"] = poured;
        if (!flips.empty()) out["flips"] = nextFlip;
        if (options.duration > 0.0) {
            out["drain_steps"] = drainSteps;
            out["steps_per_second_set"] = stepsPerSecondSet;
            out["drain_seconds"] = double(done) / stepsPerSecondSet;
        }
        if (!options.load.empty()) out["loaded"] = options.load;
        if (!options.save.empty()) out["saved"] = options.save;
        if (!options.exportFile.empty()) out["exported"] = options.exportFile;
        if (dig) {
            out["dig_body"] = options.digBody;
            out["dig_speed"] = options.digSpeed;
            out["dig_steps"] = digSteps;
            out["dig_cells_moved"] = dig->cellsMoved();
            out["dig_legs_stopped"] = dig->legsStopped();
            out["dig_done"] = dig->done();
            out["grains_pushed"] = dig->grainsPushed();
            out["grains_pushed_per_step"] = digSteps > 0 ? double(dig->grainsPushed()) / double(digSteps) : 0.0;
            out["median_ms_dig_moves"] = digMilliseconds.median(); // the moves alone, part of median_ms_per_step
            out["trench_depth"] = trenchDepth(heightsBeforeDig, lowerColumnHeights(scene), digPath,
                                              scene.grid(sandcore::GridLevel::Lower).size());
        }
        addModelShapeJson(out, built);
        std::cout << out.dump() << "\n";
        return 0;
    }
    if (!built.note.empty()) std::printf("%s\n", built.note.c_str());
    std::printf("scene %s: %lld grains (%lld at start), %lld in the upper grid, %lld in the lower grid\n",
                sceneName.c_str(), (long long)scene.grainCount(), (long long)grainsInitial,
                (long long)scene.counters().grainsUpper, (long long)scene.counters().grainsLower);
    if (options.pour > 0)
        std::printf("poured %lld of %lld grains\n", (long long)poured, (long long)options.pour);
    std::printf("%lld steps, %lld moves, %s\n", (long long)done, (long long)moves,
                scene.settled() ? "settled" : "still moving");
    std::printf("%.3f s, %.1f steps/s, median %.3f ms per step, %d thread(s), %s\n", seconds, stepsPerSecond,
                stepMilliseconds.median(), threads, options.fullSweep ? "full sweep" : "sleeping grains skipped");
    std::printf("physics %s\n", std::string(sandcore::physicsLevelName(settings.step.physics.level)).c_str());
    if (options.duration > 0.0)
        std::printf("timer %.1f s: the drain takes %lld steps, so %.3f steps/s; these %lld steps last %.2f s\n",
                    options.duration, (long long)drainSteps, stepsPerSecondSet, (long long)done,
                    double(done) / stepsPerSecondSet);
    std::printf("state hash %s\n", hash.c_str());
    if (dig)
        std::printf("dig: %s moved %lld cells in %lld steps (%s), pushed %lld grains, left a trench %.2f cells deep\n",
                    options.digBody.c_str(), (long long)dig->cellsMoved(), (long long)digSteps,
                    dig->done() ? "path done" : "path not done", (long long)dig->grainsPushed(),
                    trenchDepth(heightsBeforeDig, lowerColumnHeights(scene), digPath,
                                scene.grid(sandcore::GridLevel::Lower).size()));
    if (!options.load.empty()) std::printf("went on from %s\n", options.load.c_str());
    if (!options.save.empty()) std::printf("saved the state to %s\n", options.save.c_str());
    if (!options.exportFile.empty()) std::printf("exported the sand to %s\n", options.exportFile.c_str());
    return 0;
}

} // namespace

void addSimulateCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<SimulateOptions>();
    CLI::App* cmd = app.add_subcommand("simulate", "Run a scene headless and report grains, moves, hash and speed");
    addSceneOptions(*cmd, options->scene);
    auto* steps = addNumberOption(*cmd, "--steps", options->steps, std::int64_t{0}, kMaxSteps,
                                  "number of steps (default 1000)");
    auto* settled = cmd->add_flag("--until-settled", options->untilSettled, "run until a step moves nothing");
    steps->excludes(settled);
    addNumberOption(*cmd, "--max-steps", options->maxSteps, std::int64_t{1}, kMaxSteps,
                    "with --until-settled: stop after this many steps at most (default 10000000)");
    cmd->add_flag("--full-sweep", options->fullSweep, "visit every cell each step (same result, slower)");
    addNumberOption(*cmd, "--pour", options->pour, std::int64_t{0}, std::int64_t{1} << 31,
                    "canvas: release one grain per step at the centre of the top, N grains in all");
    addNumberListOption(*cmd, "--flip-at", options->flipAt, std::int64_t{0}, kMaxSteps,
                        "turn the hourglass over after this step (repeatable; twice at one step turns it back)")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    addNumberOption(*cmd, "--duration", options->duration, 0.001, 1e7,
                    "timer: predict the drain's steps and set the rate so it lasts this many seconds");
    cmd->add_flag("--json", options->json, "print one JSON object");
    auto* load = cmd->add_option("--load", options->load,
                                 "go on from a saved .sand state instead of building a scene (--steps N runs N more)");
    for (const char* sceneOption : {"--scene", "--model", "--shape", "--res"}) load->excludes(sceneOption);
    cmd->add_option("--save", options->save, "after the run, save the whole state to this .sand file");
    cmd->add_option("--export", options->exportFile, "after the run, export the sand: .ply points, .vox voxels, .obj/.stl/.glb surface");
    cmd->add_option("--trace", options->trace, "write FILE.csv with one row per step: step,grains_upper,grains_lower,moves");
    auto* dig = cmd->add_option("--dig", options->dig,
                                "sandbox: drive a body along this path of cells, \"X,Y,Z X,Y,Z ...\" (its bottom middle cell)");
    cmd->add_option("--dig-body", options->digBody, "with --dig: blade (default), box, ball or a model file")->needs(dig);
    addNumberOption(*cmd, "--dig-speed", options->digSpeed, 1, kMaxDigSpeed,
                    "with --dig: cells the body moves per step (default 1)")
        ->needs(dig);
    cmd->callback([options, cmd, &exitCode] { exitCode = runSimulate(*options, *cmd); });
}

} // namespace sandglass
