#include "app/cli/command_line.hpp"

#include "app/cli/commands.hpp"

#include <exception>
#include <iostream>

namespace sandglass {

int runCommandLine(int argc, char** argv) {
    CLI::App app{"sandglass: real-time 3D sand simulation (hourglass, sculpture, canvas)", "sandglass"};
    app.set_version_flag("--version", SANDGLASS_VERSION);
    app.require_subcommand(0, 1);
    int exitCode = 0;
    addSimulateCommand(app, exitCode);
    addVoxelizeCommand(app, exitCode);
    addGuiCommand(app, exitCode);
    addRenderCommand(app, exitCode);
    addBenchCommand(app, exitCode);
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
        return e.get_exit_code() != 0 ? e.get_exit_code() : 2;
    } catch (const std::exception& e) {
        std::cerr << "sandglass: " << e.what() << "\n";
        return 1;
    }
    if (app.get_subcommands().empty()) {
        try {
            return runDefaultWindow();
        } catch (const std::exception& e) {
            std::cerr << "sandglass: " << e.what() << "\n";
            return 1;
        }
    }
    return exitCode;
}

} // namespace sandglass
