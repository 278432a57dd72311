// SPEC B1 inside the application: the same frames the user sees (simulation and panels on),
// timed per display configuration. Used by the B key and by `sandglass bench --render`.
#include "application.hpp"

#include <GLFW/glfw3.h>

#include <cstdio>

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
    state_.render = savedRender;
    state_.simulationRunning = savedRunning;
    state_.showGui = savedGui;
    glfwSwapInterval(options_.window.vsync ? 1 : 0);
    return report;
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
