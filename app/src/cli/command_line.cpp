// SPDX-License-Identifier: MIT
#include "app/cli/command_line.hpp"

#include "app/cli/commands.hpp"
#include "app/version.hpp"

#include <exception>
#include <iostream>
#include <stdexcept>

namespace sandglass {

namespace {

// One code for a wrong command line, one for work that failed; documented in every --help.
constexpr int kExitFailed = 1;
constexpr int kExitUsage = 2;
constexpr const char* kExitCodes =
    "Exit codes: 0 success; 1 the work failed (a file that cannot be read or written, a broken model, "
    "too little memory); 2 the command line is wrong (an unknown option, a value out of range).";

} // namespace

int runCommandLine(int argc, char** argv) {
    CLI::App app{"sandglass: real-time 3D sand (hourglass, sculpture, canvas). Without a subcommand it opens "
                 "the window on the default hourglass, or on FILE.",
                 "sandglass"};
    app.set_version_flag("--version", versionText());
    app.require_subcommand(0, 1);
    app.footer(kExitCodes);
    int exitCode = 0;
    std::string file;
    bool noSettings = false;
    app.add_option("file", file, "open this in the window: a .sand state, a model (as an hourglass) or a PNG/JPEG draft (on the canvas)");
    app.add_flag("--no-settings", noSettings, "start the window from the defaults and remember nothing");
    addSimulateCommand(app, exitCode);
    addVoxelizeCommand(app, exitCode);
    addGuiCommand(app, exitCode);
    addRenderCommand(app, exitCode);
    addBenchCommand(app, exitCode);
    for (CLI::App* command : app.get_subcommands({})) command->footer(kExitCodes);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line, not CLI11's two-line message: scripts and tests read the first line.
        std::cerr << "sandglass: " << e.what() << " (see --help)\n";
        return kExitUsage;
    } catch (const std::invalid_argument& e) {
        std::cerr << "sandglass: " << e.what() << "\n";
        return kExitUsage;
    } catch (const std::exception& e) {
        std::cerr << "sandglass: " << e.what() << "\n";
        return kExitFailed;
    }
    if (app.get_subcommands().empty()) {
        try {
            return runDefaultWindow(file, noSettings);
        } catch (const std::invalid_argument& e) {
            std::cerr << "sandglass: " << e.what() << "\n";
            return kExitUsage;
        } catch (const std::exception& e) {
            std::cerr << "sandglass: " << e.what() << "\n";
            return kExitFailed;
        }
    }
    return exitCode;
}

} // namespace sandglass
