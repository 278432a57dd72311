// SPEC B1 inside the application: the same frames the user sees (simulation and panels on),
// timed per display configuration. Used by the B key and by `sandglass bench --render`.
#include "app/application.hpp"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <functional>

namespace sandglass {

BenchmarkReport Application::runBenchmark(const std::vector<BenchmarkCase>& cases, const BenchmarkTiming& timing) {
    using Clock = std::chrono::steady_clock;
    BenchmarkReport report;
    const SceneRequest& request = state_.scene.request;
    report.scene = std::string(sceneKindName(request.kind)) + (request.shape.empty() ? "" : " (" + request.shape + ")") +
                   ", resolution " + std::to_string(request.resolution);
    report.glRenderer = state_.glRenderer;
    report.glVersion = state_.glVersion;
    targetSize(report.width, report.height);

    const RenderSettings savedRender = state_.render;
    const bool savedRunning = state_.simulationRunning, savedGui = state_.showGui;
    // Every row resets the scene; the user's drawing or drained hourglass comes back afterwards.
    if (pendingScene_.valid()) {
        pendingScene_.wait();
        finishRebuild();
    }
    const sandcore::SceneSnapshot savedScene = scene_->snapshot();
    const sandcore::Scene* benchmarkedScene = scene_.get();
    const bool savedStepOutsideClock = lastStepOutsideClock_;
    glfwSwapInterval(0); // measure drawing, not the display's refresh
    auto finishFrame = [&] {
        if (offscreen_)
            glFinish(); // nothing is shown, so wait for the drawing itself
        else
            window_.swapBuffers();
    };
    auto last = Clock::now();
    auto frame = [&] {
        glfwPollEvents();
        const auto now = Clock::now();
        renderFrame(std::chrono::duration<double>(now - last).count());
        last = now;
        finishFrame();
    };
    auto restoreUserState = [&] {
        state_.render = savedRender;
        state_.simulationRunning = savedRunning;
        state_.showGui = savedGui;
        glfwSwapInterval(options_.window.vsync ? 1 : 0);
        if (scene_.get() != benchmarkedScene) return; // a rebuild replaced it meanwhile: keep the new one
        scene_->restore(savedScene);
        lastStepOutsideClock_ = savedStepOutsideClock;
        renderer_.sceneChanged();
    };
    try {
        runBenchmarkRows(cases, timing, frame, report);
    } catch (...) {
        restoreUserState();
        throw;
    }
    restoreUserState();
    return report;
}

void Application::runBenchmarkRows(const std::vector<BenchmarkCase>& cases, const BenchmarkTiming& timing,
                                   const std::function<void()>& frame, BenchmarkReport& report) {
    using Clock = std::chrono::steady_clock;
    for (const BenchmarkCase& setup : cases) {
        state_.render.mode = setup.mode;
        state_.render.grainsPerCell = setup.grainsPerCell;
        state_.render.lighting = setup.lighting;
        state_.render.innerGrains = setup.innerGrains;
        state_.simulationRunning = true;
        state_.showGui = true;
        // Every row starts from a full upper bulb, so each measures the same flowing sand
        // (a drained hourglass would upload nothing and flatter the later rows).
        scene_->reset();
        renderer_.sceneChanged();
        for (int i = 0; i < timing.warmupFrames; ++i) frame();
        BenchmarkRow row;
        row.setup = setup;
        const auto start = Clock::now();
        double elapsed = 0.0;
        while (row.frames < timing.minFrames || (row.frames < timing.maxFrames && elapsed < timing.maxSeconds)) {
            frame();
            ++row.frames;
            elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        }
        row.seconds = elapsed;
        row.filledCells = scene_->grainCount();
        report.rows.push_back(row);
        std::printf("%-4s %2d grains/cell, light %-3s, inner %-3s: %8.1f fps\n", renderModeShortName(setup.mode),
                    setup.grainsPerCell, setup.lighting ? "on" : "off", setup.innerGrains ? "yes" : "no",
                    row.framesPerSecond());
        std::fflush(stdout);
    }
}

void Application::runInteractiveBenchmark() {
    state_.statusLine = "benchmark running...";
    try {
        const BenchmarkReport report = runBenchmark(thesisBenchmarkCases(), BenchmarkTiming{});
        writeBenchmarkFiles(options_.benchmarkFolder, {report}, "key B in the window");
        state_.statusLine = "benchmark written to " + (options_.benchmarkFolder / "benchmark.txt").string();
        std::printf("%s\n", state_.statusLine.c_str());
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        std::fprintf(stderr, "sandglass: %s\n", error.what());
    }
}

} // namespace sandglass
