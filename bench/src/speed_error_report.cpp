// SPDX-License-Identifier: MIT
#include "bench/speed_error_report.hpp"

#include "bench/granular_report.hpp"
#include "bench/plausibility.hpp"
#include "bench/report_files.hpp"
#include "bench/simulation_bench.hpp"
#include "bench/throughput_bench.hpp"
#include "bench/voxelization_bench.hpp"

#include "sandcore/display_positions.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <ostream>
#include <sstream>
#include <thread>

namespace sandbench {

namespace fs = std::filesystem;
using sandcore::GridLevel;

namespace {

std::string machineDescription() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    std::ostringstream text;
    text << model << ", " << std::thread::hardware_concurrency() << " hardware threads, compiler "
#if defined(__clang__)
         << "clang " << __clang_major__ << "." << __clang_minor__;
#elif defined(__GNUC__)
         << "g++ " << __GNUC__ << "." << __GNUC_MINOR__;
#else
         << "unknown";
#endif
    return text.str();
}

std::string today() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
    return text;
}

struct Section {
    std::string markdown;
    bool passed = true;
};

Section voxelizationSection(const ReportOptions& options, std::ostream& log) {
    const std::vector<int> resolutions = options.quick ? std::vector<int>{16, 32, 64}
                                                       : std::vector<int>{16, 32, 64, 128, 256};
    const int threads = options.step.threads, repeat = options.quick ? 1 : 3;
    log << "voxelization: sphere, hourglass and torus at " << resolutions.size() << " resolutions\n";
    const std::vector<VoxelRun> runs = measureVoxelization(resolutions, threads, repeat);
    const Table table = voxelTable(runs);
    writeCsv(table, options.outDir / "voxelization.csv");
    LinePlot plot{"voxelization", "Voxelization: time against volume error (labels: resolution)", "ms (" + std::to_string(threads) + " threads)",
                  "|relative volume error|", true, "left bottom", {}};
    for (const char* mesh : {"sphere", "hourglass", "torus"}) {
        PlotSeries series{mesh, {}, {}};
        for (const VoxelRun& run : runs)
            if (run.mesh == mesh) {
                series.points.push_back({run.milliseconds, std::max(std::abs(run.meshError), 1e-6)});
                series.labels.push_back(std::to_string(run.resolution));
            }
        plot.series.push_back(std::move(series));
    }
    const bool plotted = writeLinePlot(options.outDir, plot);
    if (!plotted) log << "sandglass: gnuplot could not draw voxelization.png\n";

    log << "voxelization: dense mesh and binning\n";
    const int denseResolution = options.quick ? 128 : 256, binningResolution = options.quick ? 64 : 128;
    const Table dense = denseMeshTable(denseResolution, threads, repeat);
    const Table binning = binningTable(binningResolution, threads, repeat);
    writeCsv(dense, options.outDir / "voxelization_dense.csv");
    writeCsv(binning, options.outDir / "voxelization_binning.csv");

    Section section;
    section.passed = plotted;
    section.markdown =
        "## Voxelization: time against volume error\n\n"
        "Each mesh is scaled so its largest extent spans `res` cells and voxelized with " + std::to_string(threads) + " threads (best of " +
        std::to_string(repeat) + "). The error is the voxel volume (inside cells) against the mesh's exact volume "
        "(sum of signed tetrahedra) and, for the sphere (icosphere of 20480 triangles) and the torus (ring radius 1, "
        "tube 0.4), against the exact solid, which also contains the tessellation's own error.\n\n" +
        toMarkdown(table) + "\n![time against error](voxelization.png)\n\n"
        "A closed mesh of about 200,000 triangles (a torus):\n\n" + toMarkdown(dense) +
        "\nTriangles binned by the rows they can hit, against testing every row with every triangle:\n\n" +
        toMarkdown(binning) + "\n";
    return section;
}

Section simulationSection(const ReportOptions& options, std::ostream& log) {
    const std::vector<int> resolutions = options.quick ? std::vector<int>{24, 32, 48}
                                                       : std::vector<int>{32, 48, 64, 96, 128, 160};
    log << "simulation: draining hourglasses at " << resolutions.size() << " resolutions\n";
    const std::vector<DrainRun> runs = measureDrains(resolutions, options.step);
    const Table table = drainTable(runs);
    writeCsv(table, options.outDir / "simulation.csv");

    LinePlot plot{"simulation", "Hourglass drain: median ms per step", "resolution (cells)", "ms per step", true,
                  "left top", {}};
    const int threads = options.step.threads;
    const std::pair<bool, int> kinds[] = {{true, 1}, {true, threads}, {false, 1}, {false, threads}};
    for (const auto& [sleeping, threads] : kinds) {
        PlotSeries series{std::string(sleeping ? "sleeping" : "full sweep") + ", " + std::to_string(threads) +
                              (threads == 1 ? " thread" : " threads"),
                          {}, {}};
        for (const DrainRun& run : runs)
            if (run.sleeping == sleeping && run.threads == threads) series.points.push_back({double(run.resolution), run.medianMs});
        plot.series.push_back(std::move(series));
    }
    const bool plotted = writeLinePlot(options.outDir, plot);

    Section section;
    section.passed = drainsAgree(runs) && plotted;
    if (!plotted) log << "sandglass: gnuplot could not draw simulation.png\n";
    section.markdown = "## Simulation: ms per step against resolution\n\n"
                       "The procedural hourglass (neck radius resolution/24) drained under the " +
                       std::string(sandcore::physicsLevelName(options.step.physics.level)) +
                       " rules until a step moves nothing, seed " + std::to_string(options.step.seed) +
                       ", with sleeping grains skipped and with a full sweep of every cell, on 1 and " +
                       std::to_string(threads) + " threads. Every run of one resolution must end in the same state (same hash, same number of "
                       "steps) and keep every grain.\n\n" +
                       toMarkdown(table) + "\nChecks: " +
                       (section.passed ? "all runs conserve their grains and agree on the final state."
                                       : "**FAILED**: a run lost grains or ended in another state.") +
                       "\n\n![ms per step](simulation.png)\n\n";
    return section;
}

Section throughputSection(const ReportOptions& options, std::ostream& log) {
    const int resolution = options.quick ? 64 : 248, threads = options.step.threads;
    log << "throughput: memory ceiling, then the " << resolution << "-cell hourglass drain on 1 and " << threads
        << " threads\n";
    const MemoryCeiling ceiling = measureMemoryCeiling(options.quick ? std::size_t{64} << 20 : std::size_t{256} << 20, threads);
    const std::vector<MoveRate> runs = measureMoveRates(resolution, {1, threads}, options.step);
    const Table rates = moveRateTable(runs, ceiling);
    writeCsv(rates, options.outDir / "throughput.csv");
    writeCsv(ceilingTable(ceiling), options.outDir / "memory_ceiling.csv");
    Section section;
    section.passed = std::all_of(runs.begin(), runs.end(), [&](const MoveRate& r) { return r.hash == runs.front().hash; });
    section.markdown =
        "## Throughput against the machine's ceiling\n\n"
        "Moves per second while the procedural hourglass at resolution " + std::to_string(resolution) +
        " drains until settled under the " + std::string(sandcore::physicsLevelName(options.step.physics.level)) +
        " rules (sleeping grains skipped), the runs taking turns of 16 steps in one process (so "
        "a burst of load from elsewhere hits every run alike; the other run's steps evict what a step would find "
        "in the caches, which on a quiet 2-thread host cost an earlier build's 2-thread step 6-8% against a run alone, "
        "docs/performance.md, Threads), next to what "
        "this machine's memory does at all, measured just before: a copy of a buffer larger than the caches and "
        "4-byte writes to random places in it. A move writes two cells of the grid (often in one cache line) and "
        "three fields of the grain's record, and reads up to ten cells; the last column but two says how many "
        "random writes the machine could have made in the time one move took.\n\n" +
        toMarkdown(ceilingTable(ceiling)) + "\n" + toMarkdown(rates) + "\nChecks: " +
        (section.passed ? "every run ended in the same state." : "**FAILED**: the runs ended in different states.") + "\n\n";
    return section;
}

Section plausibilitySection(const ReportOptions& options, std::ostream& log) {
    Section section;
    const int resolution = options.quick ? 64 : 128;
    log << "plausibility: discharge of a " << resolution << "-cell hourglass\n";
    sandcore::HourglassShape shape;
    shape.height = resolution;
    shape.neckRadius = sandcore::defaultNeckRadius(resolution);
    sandcore::Scene hourglass = sandcore::makeHourglassScene(sandcore::makeHourglassMask(shape));
    const DischargeSeries series = recordDischarge(hourglass, 10'000'000);
    const int window = 10;
    const std::vector<double> middle = windowedDischargeRates(series, window, 0.1, 0.9);
    const double variation = coefficientOfVariation(middle);
    const std::vector<double> all = windowedDischargeRates(series, window, 0.0, 1.0);
    Table dischargeCsv{{"step", "grains through the neck"}, {}};
    for (std::size_t i = 0; i < series.grainsPerStep.size(); ++i)
        dischargeCsv.rows.push_back({std::to_string(i + 1), std::to_string(series.grainsPerStep[i])});
    writeCsv(dischargeCsv, options.outDir / "discharge.csv");
    PlotSeries rate{"discharge rate", {}, {}};
    for (std::size_t i = 0; i < all.size(); ++i) rate.points.push_back({(double(i) + 0.5) * window, all[i]});
    const bool plotted = writeLinePlot(options.outDir, {"discharge", "Hourglass discharge (mean of " +
                                                           std::to_string(window) + " steps)",
                                                        "step", "grains per step", false, "right top", {rate}});

    log << "plausibility: repose angles\n";
    const ReposeAngles hourglassPile = measureReposeAngles(hourglass.grid(GridLevel::Lower));
    const int canvasSize = options.quick ? 48 : 96;
    sandcore::Scene canvas = sandcore::makeCanvasScene(
        {{canvasSize, 4, canvasSize}, {canvasSize, canvasSize / 2, canvasSize}});
    const int pour = options.quick ? 6000 : 40000;
    for (int i = 0; i < pour; ++i) {
        canvas.addGrain(GridLevel::Upper, sandcore::pourCell(canvas));
        canvas.step();
    }
    while (!canvas.settled()) canvas.step();
    const ReposeAngles canvasPile = measureReposeAngles(canvas.grid(GridLevel::Lower));

    log << "plausibility: display drift after 10^6 steps\n";
    sandcore::Scene small = sandcore::makeCanvasScene({{12, 3, 12}, {12, 8, 12}});
    const sandcore::DisplaySettings display{1.0f, 0.5f};
    for (int i = 0; i < 1'000'000; ++i) {
        if (i < 400) small.addGrain(GridLevel::Upper, sandcore::pourCell(small));
        small.step();
    }
    double drift = 0.0;
    for (std::uint32_t id = 0; id < small.grains().size(); ++id) {
        const sandcore::Vec3 shown = sandcore::grainDisplayPosition(small, id, 0.5f, display);
        const sandcore::Vec3 rest = sandcore::cellDisplayPoint(small, small.grains().level[id], small.grains().place[id].cell,
                                                               small.grains().identity[id], display);
        drift = std::max({drift, double(std::abs(shown.x - rest.x)), double(std::abs(shown.y - rest.y)),
                          double(std::abs(shown.z - rest.z))});
    }
    section.passed = drift == 0.0 && hourglass.counters().grainsUpper == 0 && plotted;
    if (!plotted) log << "sandglass: gnuplot could not draw discharge.png\n";

    Table table{{"measure", "sandglass", "real dry sand", "error"}, {}};
    double mean = 0.0;
    for (double r : middle) mean += r;
    mean = middle.empty() ? 0.0 : mean / double(middle.size());
    table.rows.push_back({"discharge rate, middle 80% of the drain (grains/step)", fixed(mean, 1),
                          "constant (Beverloo)", "CV " + fixed(100.0 * variation, 1) + "%"});
    auto reposeRow = [&](const std::string& what, double angle) {
        const double error = angle < 30.0 ? angle - 30.0 : angle > 35.0 ? angle - 35.0 : 0.0;
        std::string signedError = error > 0 ? "+" : "";
        signedError += fixed(error, 1) + " deg";
        table.rows.push_back({what, fixed(angle, 1) + " deg", "30-35 deg", signedError});
    };
    reposeRow("repose angle, hourglass pile, along the axes", hourglassPile.alongAxes);
    reposeRow("repose angle, hourglass pile, along the diagonals", hourglassPile.alongDiagonals);
    reposeRow("repose angle, poured cone, along the axes", canvasPile.alongAxes);
    reposeRow("repose angle, poured cone, along the diagonals", canvasPile.alongDiagonals);
    table.rows.push_back({"display drift after 10^6 steps (cells)", fixed(drift, 6), "0", fixed(drift, 6)});
    writeCsv(table, options.outDir / "plausibility.csv");

    section.markdown =
        "## Physical plausibility\n\n"
        "Discharge: the procedural hourglass at resolution " + std::to_string(resolution) + ", " +
        std::to_string(series.grainsAtStart) + " grains, drained in " + std::to_string(series.grainsPerStep.size()) +
        " steps; the rate is averaged over windows of " + std::to_string(window) +
        " steps and its coefficient of variation (CV) taken while 10% to 90% of the sand has passed. "
        "Repose: column heights of the settled pile along the 8 directions out of its peak, a least-squares "
        "line over each flank (" + std::to_string(hourglassPile.flanksMeasured) + " flanks of the hourglass pile, " +
        std::to_string(canvasPile.flanksMeasured) + " of a cone of " + std::to_string(pour) +
        " grains poured onto a " + std::to_string(canvasSize) + "-cell canvas floor). "
        "A grain slips one layer down to any of its 8 neighbour columns, so the steepest stable slope is one "
        "cell per cell along the axes (45 deg) and one cell per diagonal step of sqrt(2) cells along the "
        "diagonals (35.3 deg). Drift: the largest distance between a resting grain's drawn position and its "
        "cell's display point after 10^6 steps of a poured canvas (400 grains).\n\n" +
        toMarkdown(table) +
        (middle.empty() ? std::string()
                        : "\nThe discharge is not constant in this model: over the middle 80% it goes from " +
                              fixed(middle.front(), 1) + " to " + fixed(middle.back(), 1) +
                              " grains per step. The cellular rules carry no stress, so nothing saturates the "
                              "pressure above the neck as in real sand (the Janssen effect behind Beverloo's "
                              "law); how fast the crater above the neck is refilled depends on how much sand "
                              "stands around it.\n") +
        "\n![discharge](discharge.png)\n\n";
    return section;
}

} // namespace

bool writeSpeedErrorReport(const ReportOptions& options, std::ostream& log) {
    fs::create_directories(options.outDir);
    const auto start = std::chrono::steady_clock::now();
    const Section voxelization = voxelizationSection(options, log);
    const Section simulation = simulationSection(options, log);
    const Section throughput = throughputSection(options, log);
    const Section plausibility = plausibilitySection(options, log);
    const GranularSection granular = granularSection(options, log);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool passed =
        voxelization.passed && simulation.passed && throughput.passed && plausibility.passed && granular.passed;
    std::string text = "# sandglass: speed against error\n\n"
                       "Produced by `" + options.commandLine + "` on " + today() + " on " + machineDescription() +
                       " in " + fixed(seconds, 1) + " s" + (options.quick ? " (quick: small resolutions)" : "") +
                       ". Times are medians of whole runs on a shared machine: compare ratios within one report.\n\n" +
                       voxelization.markdown + simulation.markdown + throughput.markdown + plausibility.markdown + granular.markdown +
                       "Checks: " + (passed ? "all passed." : "**some FAILED** (see above).") + "\n";
    writeText(options.outDir / "README.md", text);
    return passed;
}

} // namespace sandbench
