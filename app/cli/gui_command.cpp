// SPEC §6: `sandglass gui` (and `sandglass` alone) opens the window on a scene.
#include "cli/commands.hpp"
#include "cli/view_options.hpp"

#include <cstdio>
#include <memory>

namespace sandglass {

namespace {

struct GuiOptions {
    ViewOptions view;
    bool run = false;
    int frames = 0;
    std::string screenshot;
    std::string benchmarkFolder = ".";
};

int runGui(const GuiOptions& options) {
    ApplicationOptions settings = applicationOptionsFrom(options.view, 1280, 800);
    settings.initial.simulationRunning = options.run;
    settings.frameLimit = options.frames;
    settings.screenshotFile = options.screenshot;
    settings.benchmarkFolder = options.benchmarkFolder;
    Application application(std::move(settings));
    const std::int64_t grainsAtStart = application.scene().grainCount();
    const int exitCode = application.run();
    if (options.frames > 0)
        std::printf("frames %lld, steps %llu, grains %lld (at start %lld)\n", (long long)application.framesDrawn(),
                    (unsigned long long)application.scene().counters().stepsDone,
                    (long long)application.scene().grainCount(), (long long)grainsAtStart);
    return exitCode;
}

} // namespace

void addGuiCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<GuiOptions>();
    CLI::App* cmd = app.add_subcommand("gui", "Open the window on a scene (the default without a subcommand)");
    addViewOptions(*cmd, options->view);
    cmd->add_flag("--run", options->run, "start with the simulation on (the thesis starts with it off)");
    cmd->add_option("--frames", options->frames, "close after this many frames (for tests and screenshots)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--screenshot", options->screenshot, "with --frames: save the last frame as PNG");
    cmd->add_option("--benchmark-dir", options->benchmarkFolder, "where the B key writes benchmark.txt and .csv")
        ->capture_default_str();
    cmd->callback([options, &exitCode] {
        if (!options->screenshot.empty() && options->frames == 0)
            throw std::invalid_argument("--screenshot needs --frames N (the key P saves screenshots interactively)");
        exitCode = runGui(*options);
    });
}

int runDefaultWindow() {
    // The product's first impression: the default hourglass, already draining.
    GuiOptions options;
    options.run = true;
    return runGui(options);
}

} // namespace sandglass
