// SPEC C3: `sandglass render` simulates N steps, draws one frame in a hidden window and writes
// it as PNG; --json reports the frame rate of a few more frames of the same view.
#include "app/cli/commands.hpp"
#include "app/cli/checked_options.hpp"
#include "app/cli/view_options.hpp"

#include <nlohmann/json.hpp>

#include <GL/glew.h>

#include <chrono>
#include <iostream>
#include <memory>

namespace sandglass {

namespace {

struct RenderOptions {
    ViewOptions view;
    std::string out;
    int timedFrames = 10;
    bool json = false;
};

int runRender(const RenderOptions& options) {
    using Clock = std::chrono::steady_clock;
    ApplicationOptions settings = applicationOptionsFrom(options.view, 800, 800);
    settings.window.visible = false;
    settings.window.vsync = false;
    settings.offscreen = true; // a hidden window's own pixels are not guaranteed; an FBO's are
    settings.initial.showGui = false;
    settings.initial.simulationRunning = false;
    Application application(std::move(settings));
    application.renderFrame(0.0);
    glFinish();
    writePng(options.out, application.captureFrame());

    // The same frame again a few times: the time it takes to draw this view.
    const auto start = Clock::now();
    for (int i = 0; i < options.timedFrames; ++i) {
        application.renderFrame(0.0);
        glFinish();
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const double frameMilliseconds = options.timedFrames > 0 ? 1000.0 * seconds / options.timedFrames : 0.0;
    const double framesPerSecond = frameMilliseconds > 0.0 ? 1000.0 / frameMilliseconds : 0.0;
    const RenderSettings& render = application.state().render;
    if (options.json) {
        nlohmann::ordered_json out;
        out["fps"] = framesPerSecond;
        out["frame_ms"] = frameMilliseconds;
        out["out"] = options.out;
        out["scene"] = options.view.scene.scene;
        out["mode"] = renderModeName(render.mode);
        out["grains_per_cell"] = render.grainsPerCell;
        out["light"] = render.lighting;
        out["grains"] = application.scene().grainCount();
        out["steps"] = application.scene().counters().stepsDone;
        out["gl_renderer"] = application.state().glRenderer;
        out["gl_version"] = application.state().glVersion;
        std::cout << out.dump() << "\n";
    } else {
        std::cout << "wrote " << options.out << ": " << application.scene().grainCount() << " grains, "
                  << renderModeName(render.mode) << ", " << frameMilliseconds << " ms per frame (" << framesPerSecond
                  << " fps) on " << application.state().glRenderer << "\n";
    }
    return 0;
}

} // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Simulate N steps, draw one frame offscreen and write a PNG");
    addViewOptions(*cmd, options->view);
    cmd->add_option("--out", options->out, "PNG file to write")->required();
    addNumberOption(*cmd, "--timed-frames", options->timedFrames, 0, 100000,
                    "frames drawn again to measure fps and frame_ms (default 10)");
    cmd->add_flag("--json", options->json, "print one JSON object (fps, frame_ms, ...)");
    cmd->callback([options, &exitCode] { exitCode = runRender(*options); });
}

} // namespace sandglass
