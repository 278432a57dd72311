// SPDX-License-Identifier: MIT
// SPEC C3: `sandglass render` simulates N steps, draws one frame in a hidden window and writes
// it as PNG; --json reports the frame rate of a few more frames of the same view. V8: --frames N
// then draws N frames stepping once before each, and reports what they uploaded and cost.
#include "app/cli/commands.hpp"
#include "app/cli/checked_options.hpp"
#include "app/cli/view_options.hpp"
#include "app/frame_benchmark.hpp"

#include <nlohmann/json.hpp>

#include "view/render/thread_cpu_clock.hpp"

#include <GL/glew.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>

namespace sandglass {

namespace {

struct RenderOptions {
    ViewOptions view;
    std::string out;
    int timedFrames = 10;
    int steppedFrames = 0;
    std::string grainPath = "gpu";
    bool json = false;
};

// What `--frames N` measured: frames drawn with one step before each.
struct SteppedFrames {
    int frames = 0;
    double uploadBytesPerFrame = 0.0; // mean over the frames after the first
    double movesPerStep = 0.0;
    double cpuMillisecondsPerFrame = 0.0; // the frame on the main thread, step excluded
    double appCpuMillisecondsPerFrame = 0.0; // of which outside the draw calls: the application's own work
    double gpuMillisecondsPerFrame = 0.0; // GPU time of the scene's drawing (timer queries)
    double frameMilliseconds = 0.0;       // wall time of the frame, step excluded
    double stepMilliseconds = 0.0;        // wall time of the step itself
    double upkeepMillisecondsPerStep = 0.0; // surface upkeep + the frame's grain upload, per step
    double surfaceMillisecondsPerStep = 0.0; // of which the inner flags and normals
};

SteppedFrames drawSteppedFrames(Application& application, int frames) {
    using Clock = std::chrono::steady_clock;
    SteppedFrames result;
    result.frames = frames;
    if (frames <= 0) return result;
    application.host().takeStepTally(); // only the steps below count
    application.renderer().takeGpuTime();
    double uploadBytes = 0.0, uploadMilliseconds = 0.0, cpu = 0.0, drawCalls = 0.0, wall = 0.0, stepWall = 0.0;
    for (int i = 0; i < frames; ++i) {
        const auto stepStart = Clock::now();
        application.runSteps(1);
        const auto frameStart = Clock::now();
        const double cpuStart = threadCpuMilliseconds();
        application.renderFrame(0.0);
        cpu += threadCpuMilliseconds() - cpuStart; // not the wait below, which some drivers spend spinning
        glFinish();
        wall += std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count();
        stepWall += std::chrono::duration<double, std::milli>(frameStart - stepStart).count();
        const RenderStats& stats = application.renderer().stats();
        if (i > 0) uploadBytes += double(stats.uploadBytes);
        uploadMilliseconds += stats.uploadMilliseconds;
        drawCalls += stats.drawCallCpuMilliseconds;
    }
    const SceneHost::StepTally tally = application.host().takeStepTally();
    const double steps = double(std::max<std::int64_t>(tally.steps, 1));
    result.uploadBytesPerFrame = frames > 1 ? uploadBytes / double(frames - 1) : 0.0;
    result.movesPerStep = double(tally.moves) / steps;
    result.cpuMillisecondsPerFrame = cpu / frames;
    result.appCpuMillisecondsPerFrame = std::max(0.0, cpu - drawCalls) / frames;
    result.gpuMillisecondsPerFrame = application.renderer().takeGpuTime().perFrame();
    result.frameMilliseconds = wall / frames;
    result.stepMilliseconds = stepWall / frames - tally.upkeepMilliseconds / steps;
    result.upkeepMillisecondsPerStep = (tally.upkeepMilliseconds + uploadMilliseconds) / steps;
    result.surfaceMillisecondsPerStep = tally.upkeepMilliseconds / steps;
    return result;
}

int runRender(const RenderOptions& options) {
    using Clock = std::chrono::steady_clock;
    ApplicationOptions settings = applicationOptionsFrom(options.view, 800, 800);
    settings.window.visible = false;
    settings.window.vsync = false;
    settings.offscreen = true; // a hidden window's own pixels are not guaranteed; an FBO's are
    settings.initial.showGui = false;
    settings.initial.simulationRunning = false;
    settings.initial.render.grainPath = options.grainPath == "cpu" ? GrainPath::CpuFullUpload : GrainPath::GpuInterpolated;
    Application application(std::move(settings));
    application.renderFrame(0.0);
    glFinish();
    writePng(options.out, application.captureFrame());

    // The same frame again a few times: the time it takes to draw this view, and the GPU's part.
    application.renderer().timeGpu(true);
    application.renderer().takeGpuTime();
    const auto start = Clock::now();
    for (int i = 0; i < options.timedFrames; ++i) {
        application.renderFrame(0.0);
        glFinish();
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const double frameMilliseconds = options.timedFrames > 0 ? 1000.0 * seconds / options.timedFrames : 0.0;
    const double framesPerSecond = frameMilliseconds > 0.0 ? 1000.0 / frameMilliseconds : 0.0;
    const double gpuFrameMilliseconds = application.renderer().takeGpuTime().perFrame();
    const SteppedFrames stepped = drawSteppedFrames(application, options.steppedFrames);
    const RenderSettings& render = application.state().render;
    if (options.json) {
        nlohmann::ordered_json out;
        out["fps"] = framesPerSecond;
        out["frame_ms"] = frameMilliseconds;
        out["gpu_frame_ms"] = gpuFrameMilliseconds;
        out["out"] = options.out;
        out["scene"] = options.view.scene.scene;
        out["mode"] = renderModeName(render.mode);
        out["grains_per_cell"] = render.grainsPerCell;
        out["light"] = render.lighting;
        out["lights"] = lightRigName(render.light);
        out["ambient_occlusion"] = render.ambientOcclusion;
        out["shadows"] = render.shadows;
        out["tone_mapping"] = render.toneMapping;
        out["glass_environment"] = render.glassEnvironment;
        out["normals"] = normalMethodName(render.normals);
        out["grains"] = application.scene().grainCount();
        out["steps"] = application.scene().counters().stepsDone;
        out["gl_renderer"] = application.state().glRenderer;
        out["gl_version"] = application.state().glVersion;
        out["grain_path"] = options.grainPath;
        if (stepped.frames > 0) {
            out["frames"] = stepped.frames;
            out["upload_bytes_per_frame"] = stepped.uploadBytesPerFrame;
            out["moves_per_step"] = stepped.movesPerStep;
            out["cpu_ms_per_frame"] = stepped.cpuMillisecondsPerFrame;
            out["app_cpu_ms_per_frame"] = stepped.appCpuMillisecondsPerFrame;
            out["gpu_ms_per_frame"] = stepped.gpuMillisecondsPerFrame;
            out["upkeep_ms_per_step"] = stepped.upkeepMillisecondsPerStep;
            out["surface_upkeep_ms_per_step"] = stepped.surfaceMillisecondsPerStep;
            out["stepped_frame_ms"] = stepped.frameMilliseconds;
            out["step_ms"] = stepped.stepMilliseconds;
        }
        std::cout << out.dump() << "\n";
    } else {
        std::cout << "wrote " << options.out << ": " << application.scene().grainCount() << " grains, "
                  << renderModeName(render.mode) << ", " << frameMilliseconds << " ms per frame (" << framesPerSecond
                  << " fps, " << gpuFrameMilliseconds << " ms of it on the GPU) on " << application.state().glRenderer
                  << "\n";
        if (stepped.frames > 0)
            std::cout << stepped.frames << " stepped frames: " << stepped.uploadBytesPerFrame << " bytes uploaded per frame, "
                      << stepped.movesPerStep << " moves per step, " << stepped.cpuMillisecondsPerFrame
                      << " CPU ms per frame (" << stepped.appCpuMillisecondsPerFrame << " outside the draw calls), "
                      << stepped.gpuMillisecondsPerFrame << " GPU ms per frame, "
                      << stepped.upkeepMillisecondsPerStep << " upkeep ms per step\n";
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
    addNumberOption(*cmd, "--frames", options->steppedFrames, 0, 100000,
                    "then draw N frames, one step before each, and report upload and CPU figures (default 0)");
    cmd->add_option("--grain-path", options->grainPath,
                    "gpu (only changes uploaded, positions on the GPU) or cpu (every grain uploaded, the earlier path)")
        ->check(CLI::IsMember({"gpu", "cpu"}))
        ->capture_default_str();
    cmd->add_flag("--json", options->json,
                  "print one JSON object (fps, frame_ms, gpu_frame_ms, ...; with --frames also upload_bytes_per_frame, "
                  "moves_per_step, cpu_ms_per_frame, app_cpu_ms_per_frame, gpu_ms_per_frame, upkeep_ms_per_step)");
    cmd->callback([options, &exitCode] { exitCode = runRender(*options); });
}

} // namespace sandglass
