// SPEC C4: `sandglass bench` writes the speed-against-error report (B2).
#include "cli/commands.hpp"

#include "bench/speed_error_report.hpp"

#include <iostream>
#include <memory>

namespace sandglass {

namespace {
struct BenchOptions {
    bool quick = false;
    std::string outDir = "bench-report";
};
} // namespace

void addBenchCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand("bench", "Write the speed-against-error report (Markdown, CSV, PNG plots)");
    cmd->add_flag("--quick", options->quick, "small resolutions only: under a minute, for CI");
    cmd->add_option("--out", options->outDir, "folder for the report")->capture_default_str();
    cmd->callback([options, &exitCode] {
        sandbench::ReportOptions report;
        report.quick = options->quick;
        report.outDir = options->outDir;
        report.commandLine = std::string("sandglass bench") + (options->quick ? " --quick" : "") + " --out " +
                             options->outDir;
        const bool passed = sandbench::writeSpeedErrorReport(report, std::cerr);
        std::cout << "report written to " << (report.outDir / "README.md").string() << "\n";
        if (!passed) std::cerr << "sandglass: some checks of the report failed (see the report)\n";
        exitCode = passed ? 0 : 1;
    });
}

} // namespace sandglass
