// SPDX-License-Identifier: MIT
// `sandglass bench`: without --render, the speed-against-error report (SPEC C4/B2: Markdown, CSV
// and PNG plots); with --render, the frame-rate benchmark B1 (thesis §4.3) on the thesis's
// benchmark scene (about 3,500 filled cells) and a large one, written as benchmark.txt + .csv.
#include "app/cli/commands.hpp"
#include "app/cli/checked_options.hpp"
#include "app/cli/view_options.hpp"
#include "app/cli/terminal_progress.hpp"
#include "app/frame_benchmark_runner.hpp"

#include "bench/speed_error_report.hpp"

#include <iostream>
#include <memory>
#include <sstream>

namespace sandglass {

namespace {

struct BenchOptions {
    bool render = false;
    bool quick = false;
    bool looks = false; // with render: the look rows, not the thesis's
    std::string out = "bench-report";
    std::vector<int> resolutions{37, 248};
    std::string size = "1024x768";
    BenchmarkTiming timing;
    sandcore::StepSettings step{1, 2, true, {}};
};

int runRenderBenchmark(const BenchOptions& options, const std::string& commandLine) {
    std::vector<BenchmarkReport> reports;
    for (int resolution : options.resolutions) {
        ViewOptions view;
        view.scene.settings.request.resolution = resolution;
        view.scene.settings.step = options.step;
        view.size = options.size;
        ApplicationOptions settings = applicationOptionsFrom(view, 1024, 768);
        settings.window.visible = false;
        settings.window.vsync = false;
        settings.offscreen = true;
        Application application(std::move(settings));
        std::cout << "hourglass, resolution " << resolution << ": " << application.scene().grainCount()
                  << " filled cells" << std::endl;
        std::vector<BenchmarkCase> cases = options.looks ? lookBenchmarkCases() : thesisBenchmarkCases();
        if (options.quick && !options.looks) cases.resize(4); // inner drawn, 1 grain per cell, no light: one row per mode
        reports.push_back(runFrameBenchmark(application, cases, options.timing));
    }
    writeBenchmarkFiles(options.out, reports, commandLine);
    std::cout << "wrote " << (std::filesystem::path(options.out) / "benchmark.txt").string() << " and benchmark.csv"
              << std::endl;
    return 0;
}

int runSpeedErrorReport(const BenchOptions& options) {
    sandbench::ReportOptions report;
    report.quick = options.quick;
    report.outDir = options.out;
    report.step = options.step;
    report.commandLine = std::string("sandglass bench") + (options.quick ? " --quick" : "") + " --out " + options.out;
    if (options.step.threads != 2) report.commandLine += " --threads " + std::to_string(options.step.threads);
    if (options.step.seed != 1) report.commandLine += " --seed " + std::to_string(options.step.seed);
    if (options.step.physics.level != sandcore::PhysicsLevel::Granular) report.commandLine += " --physics classic";
    bool passed = false;
    {
        ElapsedTicker ticker("bench", std::cerr); // the stages' lines scroll above the elapsed time
        passed = sandbench::writeSpeedErrorReport(report, ticker.stream());
    }
    std::cout << "report written to " << (report.outDir / "README.md").string() << "\n";
    if (!passed) std::cerr << "sandglass: some checks of the report failed (see the report)\n";
    return passed ? 0 : 1;
}

} // namespace

void addBenchCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bench", "Benchmarks: the speed-against-error report, or with --render the frame rates of every render mode");
    cmd->add_flag("--render", options->render, "frame-rate benchmark: every mode, light, inner grains, 1 and 20 "
                                               "grains per cell; writes benchmark.txt and benchmark.csv");
    cmd->add_flag("--look", options->looks,
                  "with --render: the default look against the thesis's default and against each studio element off");
    cmd->add_flag("--quick", options->quick,
                  "small resolutions, under a minute; with --render: one row per mode only");
    cmd->add_option("--out", options->out, "folder for the result files")->capture_default_str();
    addNumberListOption(*cmd, "--res", options->resolutions, kResolutionRange.min, 1024,
                        "with --render: hourglass resolutions to measure (default 37 248: about 3,500 and 1,000,000 grains)");
    cmd->add_option("--size", options->size, "with --render: framebuffer size, WxH pixels")->capture_default_str();
    addNumberOption(*cmd, "--max-frames", options->timing.maxFrames, 1, 1'000'000,
                    "with --render: frames per row at most (default 120)");
    addNumberOption(*cmd, "--seconds", options->timing.maxSeconds, 0.01, 3600.0,
                    "with --render: seconds per row at most, after 3 frames (default 2)");
    addNumberOption(*cmd, "--seed", options->step.seed, std::uint64_t{0}, ~std::uint64_t{0},
                    "seed of every simulated scene (default 1)");
    addNumberOption(*cmd, "--threads", options->step.threads, kThreadsRange.min, kThreadsRange.max,
                    "threads compared with one thread in the report; threads of the scene with --render (default 2)");
    auto physics = std::make_shared<std::string>("granular");
    cmd->add_option("--physics", *physics, "rules of the simulated scenes: classic or granular (the report's "
                                           "granular section measures both either way)")
        ->capture_default_str();
    addNumberOption(*cmd, "--repose", options->step.physics.reposeDegrees, float(kReposeRange.min),
                    float(kReposeRange.max), "granular: angle of repose in degrees (default 33)");
    addNumberOption(*cmd, "--gravity", options->step.physics.gravity, float(kGravityRange.min),
                    float(kGravityRange.max), "granular: gravity in cells per step squared (default 0.02)");
    cmd->callback([options, physics, &exitCode] {
        const auto level = sandcore::parsePhysicsLevel(*physics);
        if (!level) throw std::invalid_argument("--physics must be classic or granular, got '" + *physics + "'");
        options->step.physics.level = *level;
        if (!options->render) {
            exitCode = runSpeedErrorReport(*options);
            return;
        }
        std::ostringstream line;
        line << "sandglass bench --render" << (options->looks ? " --look" : "") << (options->quick ? " --quick" : "");
        line << " --out " << options->out << " --size " << options->size << " --threads " << options->step.threads
             << " --res";
        for (int r : options->resolutions) line << ' ' << r;
        exitCode = runRenderBenchmark(*options, line.str());
    });
}

} // namespace sandglass
