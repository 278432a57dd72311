// SPDX-License-Identifier: MIT
// SPEC §6: `sandglass gui` (and `sandglass` alone) opens the window on a scene.
#include "app/cli/commands.hpp"
#include "app/cli/checked_options.hpp"
#include "app/cli/view_options.hpp"
#include "scene/file_io.hpp"
#include "app/paint_demo.hpp"
#include "app/remembered_settings.hpp"
#include "scene/draft_image.hpp"

#include <cstdio>
#include <functional>
#include <memory>

namespace sandglass {

namespace {

struct GuiOptions {
    ViewOptions view;
    bool run = false;
    int frames = 0;
    std::string screenshot;
    std::string benchmarkFolder = ".";
    std::string draft;
    std::string load; ///< E1: a saved state to open instead of the built scene
    std::string screenshotFolder; ///< E4: where P saves screenshots
    int paintDemoPasses = 0;
    int timerSeconds = 0;
    std::string panelTab; ///< the panel tab shown first
    bool showHelp = false; ///< open with the keys and mouse controls shown
    std::string file;      ///< I3: a .sand state, a model or a draft image to open
    bool noSettings = false; ///< I4: start from the defaults and remember nothing
};

// Whether an option was typed on the command line (then it wins over a remembered setting).
using GivenOption = std::function<bool(const char* option)>;

// I3: `sandglass FILE` opens the file as its kind says: a state, a draft on the canvas, or a model.
void openAtStart(GuiOptions& options, const GivenOption& given) {
    const std::filesystem::path file = options.file;
    if (file.extension() == ".sand") {
        if (!options.load.empty()) throw std::invalid_argument("a .sand FILE and --load both name a state to open");
        options.load = options.file;
        return;
    }
    if (given("--model") || given("--shape"))
        throw std::invalid_argument("FILE " + options.file + " and --model or --shape both say what to build");
    requireReadableRegularFile(file);
    if (isDraftImageFile(file)) {
        if (!options.draft.empty()) throw std::invalid_argument("FILE and --draft both name a draft image");
        options.view.scene.scene = "canvas";
        options.draft = options.file;
        return;
    }
    if (options.view.scene.scene == "canvas") options.view.scene.scene = "hourglass";
    options.view.scene.settings.request.modelPath = options.file;
}

// I4: what the last window was left with, where the command line leaves it open.
void applyRemembered(const UserSettings& remembered, const GivenOption& given, GuiOptions& options) {
    if (!given("--mode") && !given("--thesis-look")) options.view.mode = renderModeName(remembered.mode);
    if (!given("--palette")) options.view.palette = sandPaletteName(remembered.palette);
    if (!given("--light") && !given("--unlit") && !given("--thesis-look")) {
        options.view.light = remembered.lighting;
        options.view.unlit = !remembered.lighting;
    }
    if (!given("--size"))
        options.view.size = std::to_string(remembered.windowWidth) + "x" + std::to_string(remembered.windowHeight);
    const bool sceneChosen = !options.file.empty() || !options.load.empty() || !options.draft.empty() ||
                             given("--scene") || given("--model") || given("--shape");
    if (sceneChosen) return;
    options.view.scene.scene = sceneKindName(remembered.scene);
    std::error_code error;
    // A model that was moved or deleted since: the scene's bundled default instead.
    if (remembered.scene != sandcore::SceneKind::Canvas && !remembered.model.empty() &&
        std::filesystem::is_regular_file(remembered.model, error))
        options.view.scene.settings.request.modelPath = remembered.model;
}

int runGui(GuiOptions options, const GivenOption& given) {
    const std::filesystem::path folder = options.noSettings ? std::filesystem::path() : settingsFolder();
    UserSettings remembered;
    if (!folder.empty()) {
        std::string problem;
        remembered = readUserSettings(folder / "settings.json", problem);
        if (!problem.empty()) std::fprintf(stderr, "sandglass: %s\n", problem.c_str());
        applyRemembered(remembered, given, options);
    }
    ApplicationOptions settings = applicationOptionsFrom(options.view, 1280, 800);
    if (!folder.empty()) startAsRemembered(remembered, folder / "imgui.ini", settings);
    settings.initial.simulationRunning = options.run;
    settings.frameLimit = options.frames;
    settings.screenshotFile = options.screenshot;
    settings.benchmarkFolder = options.benchmarkFolder;
    settings.stateFile = options.load; // opened in place of the scene: nothing else is built first
    if (!options.screenshotFolder.empty()) settings.screenshotFolder = options.screenshotFolder;
    Application application(std::move(settings));
    // A draft asked for on the command line that cannot be read fails the run, like --load.
    if (!options.draft.empty() && !application.loadDraft(options.draft)) {
        std::fprintf(stderr, "sandglass: %s\n", application.state().statusLine.c_str());
        return 1;
    }
    application.state().openTab = options.panelTab;
    application.state().showHelp = options.showHelp;
    if (options.paintDemoPasses > 0)
        std::printf("paint demo: %lld grains poured\n", (long long)paintDraftDemo(application, options.paintDemoPasses));
    if (options.timerSeconds > 0) {
        // As if typed into the panel and started: the drain is measured, then the sand runs.
        application.state().timer.minutes = options.timerSeconds / 60;
        application.state().timer.seconds = options.timerSeconds % 60;
        application.state().commands.push(Command::StartTimer);
    }
    const std::int64_t grainsAtStart = application.scene().grainCount();
    const int exitCode = application.run();
    if (!folder.empty()) {
        // Never a reason to fail the run: the next start then begins from what was there.
        try {
            writeUserSettings(folder / "settings.json", settingsToRemember(application, remembered));
        } catch (const std::exception& error) {
            std::fprintf(stderr, "sandglass: settings not saved: %s\n", error.what());
        }
    }
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
    addNumberOption(*cmd, "--frames", options->frames, 0, 100'000'000, "close after this many frames (for tests and screenshots)");
    cmd->add_option("--screenshot", options->screenshot, "with --frames: save the last frame, panels included, as PNG");
    cmd->add_option("--screenshot-dir", options->screenshotFolder,
                    "where the P key saves sandglass-N.png (default: the desktop's pictures folder, else the current one)");
    cmd->add_option("--benchmark-dir", options->benchmarkFolder, "where the B key writes benchmark.txt and .csv")
        ->capture_default_str();
    auto* load = cmd->add_option("--load", options->load, "open a saved .sand state (simulate --save, Ctrl+S) instead of building a scene");
    for (const char* sceneOption : {"--scene", "--model", "--shape", "--res"}) load->excludes(sceneOption);
    cmd->add_option("--draft", options->draft, "canvas: show this PNG or JPEG as the draft image to paint over");
    cmd->add_option("--panel", options->panelTab, "open the panel on this tab")
        ->check(CLI::IsMember({"run", "view", "scene", "paint", "file"}));
    cmd->add_flag("--show-controls", options->showHelp, "open with the keys and mouse controls shown (F1 in the window)");
    cmd->add_option("file", options->file, "a .sand state, a model (opened as an hourglass) or a PNG/JPEG draft (on the canvas)");
    cmd->add_flag("--no-settings", options->noSettings,
                  "start from the defaults and remember nothing (settings live in $XDG_CONFIG_HOME/sandglass)");
    addNumberOption(*cmd, "--paint-demo", options->paintDemoPasses, 1, 50,
                    "canvas with --draft: pour this many layers of sand over the draft, colour from draft");
    addNumberOption(*cmd, "--timer", options->timerSeconds, 1, 999 * 60 + 59,
                    "hourglass: start a timer of this many seconds (the flow is set so the sand lasts that long)");
    cmd->callback([options, cmd, &exitCode] {
        const GivenOption given = [cmd](const char* option) { return cmd->count(option) > 0; };
        if (!options->file.empty()) openAtStart(*options, given);
        if (options->paintDemoPasses > 0 && (options->draft.empty() || options->view.scene.scene != "canvas"))
            throw std::invalid_argument("--paint-demo needs --scene canvas and --draft FILE");
        if (!options->screenshot.empty() && options->frames == 0)
            throw std::invalid_argument("--screenshot needs --frames N (the key P saves screenshots interactively)");
        // Checked before the window opens, so a run does not end in a failed write.
        if (!options->screenshot.empty()) requireWritableFileTarget(options->screenshot);
        if (!options->screenshotFolder.empty()) requireWritableFileTarget(std::filesystem::path(options->screenshotFolder) / "sandglass-1.png");
        if (!options->load.empty()) requireReadableRegularFile(options->load);
        exitCode = runGui(*options, given);
    });
}

int runDefaultWindow(const std::string& file, bool noSettings) {
    // The product's first impression: the default hourglass, already draining.
    GuiOptions options;
    options.run = true;
    options.file = file;
    options.noSettings = noSettings;
    const GivenOption nothingGiven = [](const char*) { return false; };
    if (!options.file.empty()) openAtStart(options, nothingGiven);
    if (!options.load.empty()) requireReadableRegularFile(options.load);
    return runGui(std::move(options), nothingGiven);
}

} // namespace sandglass
