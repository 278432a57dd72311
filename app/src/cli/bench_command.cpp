// `sandglass bench`: without --render, the speed-against-error report (SPEC C4/B2: Markdown, CSV
// and PNG plots); with --render, the frame-rate benchmark B1 (thesis §4.3) on the thesis's
// benchmark scene (about 3,500 filled cells) and a large one, written as benchmark.txt + .csv.
#include "app/cli/commands.hpp"
#include "app/cli/view_options.hpp"

#include "bench/speed_error_report.hpp"

#include <iostream>
#include <memory>
#include <sstream>

namespace sandglass {

namespace {

struct BenchOptions {
    bool render = false;
    bool quick = false;
    std::string out = "bench-report";
    std::vector<int> resolutions{37, 248};
    std::string size = "1024x768";
    BenchmarkTiming timing;
};

int runRenderBenchmark(const BenchOptions& options, const std::string& commandLine) {
    std::vector<BenchmarkReport> reports;
    for (int resolution : options.resolutions) {
        ViewOptions view;
        view.resolution = resolution;
        view.size = options.size;
        ApplicationOptions settings = applicationOptionsFrom(view, 1024, 768);
        settings.window.visible = false;
        settings.window.vsync = false;
        settings.offscreen = true;
        Application application(std::move(settings));
        std::cout << "hourglass, resolution " << resolution << ": " << application.scene().grainCount()
                  << " filled cells" << std::endl;
        std::vector<BenchmarkCase> cases = thesisBenchmarkCases();
        if (options.quick) cases.resize(4); // inner drawn, 1 grain per cell, no light: one row per mode
        reports.push_back(application.runBenchmark(cases, options.timing));
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
    report.commandLine = std::string("sandglass bench") + (options.quick ? " --quick" : "") + " --out " + options.out;
    const bool passed = sandbench::writeSpeedErrorReport(report, std::cerr);
    std::cout << "report written to " << (report.outDir / "README.md").string() << "\n";
    if (!passed) std::cerr << "sandglass: some checks of the report failed (see the report)\n";
    return passed ? 0 : 1;
}

} // namespace

void addBenchCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bench", "Benchmarks: the speed-against-error report (B2), or with --render the frame-rate benchmark (B1)");
    cmd->add_flag("--render", options->render, "frame-rate benchmark B1: every mode, light, inner grains, 1 and 20 "
                                               "grains per cell; writes benchmark.txt and benchmark.csv");
    cmd->add_flag("--quick", options->quick,
                  "B2: small resolutions, under a minute (CI smoke test); B1: one row per mode only");
    cmd->add_option("--out", options->out, "folder for the result files")->capture_default_str();
    cmd->add_option("--res", options->resolutions,
                    "B1: hourglass resolutions to measure (37: 3,460 cells, 248: 995,072)")
        ->capture_default_str()
        ->check(CLI::Range(8, 1024));
    cmd->add_option("--size", options->size, "B1: framebuffer size, WxH pixels")->capture_default_str();
    cmd->add_option("--max-frames", options->timing.maxFrames, "B1: frames per row at most")->capture_default_str();
    cmd->add_option("--seconds", options->timing.maxSeconds, "B1: seconds per row at most (after 3 frames)")
        ->capture_default_str();
    cmd->callback([options, &exitCode] {
        if (!options->render) {
            exitCode = runSpeedErrorReport(*options);
            return;
        }
        std::ostringstream line;
        line << "sandglass bench --render" << (options->quick ? " --quick" : "");
        line << " --out " << options->out << " --size " << options->size << " --res";
        for (int r : options->resolutions) line << ' ' << r;
        exitCode = runRenderBenchmark(*options, line.str());
    });
}

} // namespace sandglass
