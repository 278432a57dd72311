// SPDX-License-Identifier: MIT
#include "app/frame_benchmark_runner.hpp"

#include "view/render/thread_cpu_clock.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace sandglass {

BenchmarkReport runFrameBenchmark(Application& app, const std::vector<BenchmarkCase>& cases,
                                  const BenchmarkTiming& timing, const std::function<void()>& afterEachFrame) {
    using Clock = std::chrono::steady_clock;
    const SceneSettings& loaded = app.host().loaded();
    BenchmarkReport report;
    report.scene = std::string(sceneKindName(loaded.request.kind)) +
                   (loaded.request.shape.empty() ? "" : " (" + loaded.request.shape + ")") + ", resolution " +
                   std::to_string(loaded.request.resolution);
    report.glRenderer = app.state().glRenderer;
    report.glVersion = app.state().glVersion;
    app.targetSize(report.width, report.height);

    SceneHost host(loaded); // the benchmark's own scene: the user's stays as it is
    glfwSwapInterval(0);    // measure drawing, not the display's refresh
    auto last = Clock::now();
    RenderSettings render = app.state().render;
    double cpuMilliseconds = 0.0, drawCallMilliseconds = 0.0, uploadBytes = 0.0, uploadMilliseconds = 0.0;
    std::vector<double> frameMilliseconds; // wall time of each timed frame
    auto frame = [&] {
        glfwPollEvents();
        const auto now = Clock::now();
        frameMilliseconds.push_back(std::chrono::duration<double, std::milli>(now - last).count());
        const double cpuStart = threadCpuMilliseconds();
        app.renderHostFrame(host, render, true, std::chrono::duration<double>(now - last).count());
        last = now;
        // The swap is left out: a driver waits there for the GPU (GPU ms says how long it works).
        cpuMilliseconds += threadCpuMilliseconds() - cpuStart;
        app.finishFrame();
        uploadBytes += double(app.renderer().stats().uploadBytes);
        uploadMilliseconds += app.renderer().stats().uploadMilliseconds;
        drawCallMilliseconds += app.renderer().stats().drawCallCpuMilliseconds;
        if (afterEachFrame) afterEachFrame();
    };
    // The window shows which row runs and that Esc stops it (the key callback sets the request).
    Application::BenchmarkProgress& progress = app.benchmarkProgress();
    progress = {true, false, 0, int(cases.size())};
    app.renderer().timeGpu(true);
    struct EndProgress { // also when building the scene or a frame throws
        Application& app;
        Application::BenchmarkProgress& progress;
        ~EndProgress() {
            progress = {};
            app.renderer().timeGpu(false);
        }
    } endProgress{app, progress};
    for (const BenchmarkCase& setup : cases) {
        if (progress.cancelRequested) break;
        render = benchmarkRenderSettings(setup, render);
        // Every row starts from a full upper bulb, so each measures the same flowing sand
        // (a drained hourglass would upload nothing and flatter the later rows).
        host.reset();
        for (int i = 0; i < timing.warmupFrames; ++i) frame();
        BenchmarkRow row;
        row.setup = setup;
        host.takeStepTally();
        cpuMilliseconds = drawCallMilliseconds = uploadBytes = uploadMilliseconds = 0.0;
        app.renderer().takeGpuTime(); // the warm-up frames' time is no part of the row
        const auto start = Clock::now();
        last = start;
        frameMilliseconds.clear();
        double elapsed = 0.0;
        while (!progress.cancelRequested &&
               (row.frames < timing.minFrames || (row.frames < timing.maxFrames && elapsed < timing.maxSeconds))) {
            frame();
            ++row.frames;
            elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        }
        if (progress.cancelRequested) break; // a row cut short is no measurement
        row.seconds = elapsed;
        row.filledCells = host.scene().grainCount();
        const SceneHost::StepTally tally = host.takeStepTally();
        const double steps = double(std::max<std::int64_t>(tally.steps, 1));
        row.uploadBytesPerFrame = uploadBytes / row.frames;
        row.movesPerStep = double(tally.moves) / steps;
        row.cpuMillisecondsPerFrame = std::max(0.0, cpuMilliseconds - tally.stepMilliseconds) / row.frames;
        row.appCpuMillisecondsPerFrame =
            std::max(0.0, cpuMilliseconds - tally.stepMilliseconds - drawCallMilliseconds) / row.frames;
        row.upkeepMillisecondsPerStep = tally.steps > 0 ? (tally.upkeepMilliseconds + uploadMilliseconds) / steps : 0.0;
        row.gpuMillisecondsPerFrame = app.renderer().takeGpuTime().perFrame();
        std::sort(frameMilliseconds.begin(), frameMilliseconds.end());
        const std::size_t n = frameMilliseconds.size();
        row.medianFrameMilliseconds = n == 0 ? 0.0 : 0.5 * (frameMilliseconds[(n - 1) / 2] + frameMilliseconds[n / 2]);
        report.rows.push_back(row);
        std::printf("%-4s %2d grains/cell, light %-3s, inner %-3s%s%s: %8.1f fps, %10.0f B/frame, %7.2f CPU ms/frame, "
                    "%7.2f GPU ms/frame, median frame %.1f ms\n",
                    renderModeShortName(setup.mode), setup.grainsPerCell, setup.lighting ? "on" : "off",
                    setup.innerGrains ? "yes" : "no", setup.look.empty() ? "" : ", look ", setup.look.c_str(),
                    row.framesPerSecond(), row.uploadBytesPerFrame, row.cpuMillisecondsPerFrame,
                    row.gpuMillisecondsPerFrame, row.medianFrameMilliseconds);
        std::fflush(stdout);
        ++progress.rowsDone;
    }
    report.cancelled = progress.cancelRequested;
    glfwSwapInterval(app.options().window.vsync ? 1 : 0);
    return report;
}

} // namespace sandglass
