// SPDX-License-Identifier: MIT
// The application's frame: building it, the window loop, and drawing a scene host into the
// window or the offscreen target. Input: application_input.cpp; commands:
// application_commands.cpp; files and screenshots: application_files.cpp.
#include "app/application.hpp"

#include "gui/build_progress_window.hpp"
#include "gui/help_window.hpp"
#include "gui/panels.hpp"
#include "gui/quit_question.hpp"
#include "view/render/shader_program.hpp"

#include "scene/data_paths.hpp"
#include "scene/digger.hpp"
#include "scene/draft_image.hpp"
#include "scene/file_io.hpp"
#include "scene/state_file.hpp"

#include "sandcore/display_positions.hpp"
#include "sandcore/scenes.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <system_error>
#include <utility>

namespace sandglass {

namespace {

using Clock = std::chrono::steady_clock;
constexpr float kCanvasPitch = 1.3f; // radians above the horizon the canvas is seen from

std::vector<std::string> listModelFiles() {
    std::vector<std::string> files;
    std::error_code error;
    const std::filesystem::path folder = modelsFolder();
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        const std::string extension = entry.path().extension().string();
        for (const char* known : {".obj", ".stl", ".ply", ".gltf", ".glb", ".off", ".fbx", ".dae", ".3ds"})
            if (extension == known) files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// The scene a window starts with: a saved state when one is named (nothing else is built
// first), else the one its settings describe, with the defaults applied and checked once.
SceneHost startingHost(const ApplicationOptions& options) {
    if (!options.stateFile.empty()) {
        LoadedState loaded = loadState(options.stateFile);
        return SceneHost(std::move(loaded.scene), loaded.settings);
    }
    SceneSettings settings = options.initial.scene;
    applySceneDefaults(settings);
    return SceneHost(settings);
}

} // namespace

Application::Application(ApplicationOptions options)
    : options_(std::move(options)), state_(options_.initial), window_(options_.window),
      imgui_(window_.handle(), window_.contentScale()), renderer_(shaderDirectory()),
      host_(startingHost(options_)), canvas_(shaderDirectory(), options_.undo) {
    state_.statusLine = host_.modelNote(); // W5: what was done instead of an hourglass, from the first frame
    if (options_.offscreen) {
        int width = 0, height = 0;
        window_.framebufferSize(width, height);
        offscreen_.emplace(width, height);
    }
    GLFWwindow* handle = window_.handle();
    if (options_.windowPosition && options_.window.visible)
        glfwSetWindowPos(handle, (*options_.windowPosition)[0], (*options_.windowPosition)[1]);
    if (!options_.panelLayoutFile.empty()) imgui_.setIniFile(options_.panelLayoutFile);
    installInputCallbacks();

    state_.glRenderer = window_.glRenderer();
    state_.glVersion = window_.glVersion();
    state_.modelFiles = listModelFiles();
    state_.painting.draftFiles = listDraftFiles(modelsFolder());
    state_.scene = host_.loaded();
    state_.loaded = host_.loaded();
    state_.files.screenshotFolder =
        (options_.screenshotFolder.empty() ? defaultPicturesFolder() : options_.screenshotFolder).string();
    if (!options_.stateFile.empty()) {
        state_.files.statePath = options_.stateFile.string();
        state_.statusLine = "opened " + state_.files.statePath;
    }
    frameCamera();
    camera_.zoom(options_.cameraZoom);
    if (!options_.digPath.empty()) {
        const int width = scene().grid(sandcore::GridLevel::Lower).size().x;
        const int bed = sandcore::defaultSandboxBedDepth(sandcore::canvasSettingsForWidth(width));
        host_.startDig(makeDigBodyShape(options_.digBody, width, bed), parseDigPath(options_.digPath), options_.digSpeed);
    }
    host_.runSteps(options_.stepsBeforeStart);
    glfwGetCursorPos(handle, &lastCursorX_, &lastCursorY_);
}

Application::~Application() { glfwSetWindowUserPointer(window_.handle(), nullptr); }

void Application::frameCamera() {
    sandcore::Vec3 lo, hi;
    sandcore::sceneBounds(host_.scene(), {state_.render.cellSize, state_.render.jitter}, lo, hi);
    if (const auto& model = host_.modelDrawing()) includeInBounds(*model, scene().flipped(), state_.render.cellSize, lo, hi);
    camera_.frame(lo, hi);
    // The canvas is painted from above and a little from the front, so sand lands where the
    // cursor points and the piles still show their height.
    if (host_.kind() == sandcore::SceneKind::Canvas) camera_.rotate(-camera_.yaw(), kCanvasPitch - camera_.pitch());
}

void Application::targetSize(int& width, int& height) const {
    if (offscreen_) {
        width = offscreen_->width();
        height = offscreen_->height();
    } else {
        window_.framebufferSize(width, height);
    }
}

void Application::bindTarget() const {
    if (offscreen_)
        offscreen_->bind();
    else
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

int Application::run() {
    auto last = Clock::now();
    int exitCode = 0;
    while (!window_.shouldClose()) {
        glfwPollEvents();
        const auto now = Clock::now();
        renderFrame(std::chrono::duration<double>(now - last).count());
        last = now;
        const bool lastFrame = options_.frameLimit > 0 && framesDrawn_ >= options_.frameLimit;
        // A screenshot asked for on the command line that cannot be written fails the run.
        if (lastFrame && !options_.screenshotFile.empty() && !saveScreenshot(options_.screenshotFile)) exitCode = 1;
        // Commands that need a whole frame drawn first, or that end the loop.
        bool benchmark = false;
        for (Command command : state_.commands.take()) {
            if (command == Command::Screenshot) saveNumberedScreenshot(sceneOnlyFrame_ ? *sceneOnlyFrame_ : captureFrame());
            benchmark = benchmark || command == Command::Benchmark;
        }
        sceneOnlyFrame_.reset();
        finishFrame();
        if (benchmark) {
            runInteractiveBenchmark();
            last = Clock::now();
        }
        if (lastFrame || quitRequested_) break;
    }
    return exitCode;
}

void Application::finishFrame() {
    if (offscreen_)
        glFinish(); // nothing is shown, so wait for the drawing itself
    else
        window_.swapBuffers();
}

void Application::buildWindows() {
    if (state_.showGui) drawPanels(state_);
    drawQuitQuestion(state_);
    drawBuildProgress(state_);
    drawHelpWindow(state_);
    // The hint is for a person at a window; hidden windows (render, tests) draw the scene only.
    if (options_.window.visible && state_.showGui) drawHelpHint(state_);
}

void Application::renderFrame(double elapsedSeconds) {
    state_.uiScale = imgui_.setUiScale(state_.uiScale);
    imgui_.newFrame([this] { buildWindows(); });
    handleMouse();
    buildWindows();
    camera_.setLensShift(state_.showGui ? state_.panelCoverage : 0.0f);
    serveCommands();
    updateTimer();
    // The canvas runs while a stroke is drawn, so the first stroke shows sand even when paused.
    host_.setRunning(state_.simulationRunning || canvas_.input().painter().stroking());
    host_.setStepsPerSecond(state_.stepsPerSecond);
    host_.advance(elapsedSeconds);
    updateTurnAnimation();
    renderer_.setDraftPlacement(canvas_.draftPlacement(host_, state_.painting, state_.render.cellSize));
    drawHost(host_, state_.render);
    // E4: a screenshot shows the sand alone unless asked otherwise; the panels come after.
    if (state_.commands.contains(Command::Screenshot) && !state_.files.screenshotWithPanel) sceneOnlyFrame_ = captureFrame();
    drawOverlays();
    imgui_.render(true);
    updateStatistics(elapsedSeconds);
    ++framesDrawn_;
}

void Application::renderHostFrame(SceneHost& host, const RenderSettings& render, bool panels, double elapsedSeconds) {
    imgui_.newFrame();
    if (panels) drawPanels(state_); // what they queue waits for the application's own frames
    if (benchmark_.running) drawBenchmarkProgress();
    host.setRunning(true);
    host.setStepsPerSecond(state_.stepsPerSecond);
    host.advance(elapsedSeconds);
    renderer_.setDraftPlacement({});
    drawHost(host, render);
    imgui_.render(panels);
    ++framesDrawn_;
}

void Application::drawHost(SceneHost& host, const RenderSettings& render) {
    // The renderer hears only of real changes: a new layout rebuilds the hull, new grains re-upload.
    if (&host != drawnHost_ || host.layoutRevision() != drawnLayout_) {
        renderer_.setScene(host.scene(), host.kind(), render.cellSize, host.modelDrawing().get());
        drawnLayout_ = host.layoutRevision();
        drawnContent_ = 0;
    }
    // Steps and edits reach the renderer through the host's surface upkeep: a step lists what it
    // moved, anything else rebuilds it, and the renderer uploads everything after a rebuild.
    if (render.grainPath == GrainPath::GpuInterpolated) {
        // Only what the GPU cannot work out itself: where the cells' bits fit, no per-grain flags.
        renderer_.useSurface(&host.surfaceUpkeep(renderer_.gpuStore().trackingFor(host.scene(), render)));
    } else {
        renderer_.useSurface(nullptr);
        if (host.contentRevision() != drawnContent_) renderer_.sceneChanged();
    }
    drawnContent_ = host.contentRevision();
    drawnHost_ = &host;
    bindTarget();
    int width = 0, height = 0;
    targetSize(width, height);
    renderer_.draw(host.scene(), host.displayStepFraction(), render, camera_, width, height, window_.contentScale());
}

RgbImage Application::captureFrame() const {
    int width = 0, height = 0;
    targetSize(width, height);
    bindTarget();
    return readPixels(width, height);
}

CanvasView Application::canvasView() const {
    CanvasView view;
    targetSize(view.framebufferWidth, view.framebufferHeight);
    glfwGetWindowSize(window_.handle(), &view.windowWidth, &view.windowHeight);
    const float aspect = view.framebufferHeight > 0 ? float(view.framebufferWidth) / float(view.framebufferHeight) : 1.0f;
    view.view = camera_.view();
    view.projection = camera_.projection(aspect);
    view.cellSize = state_.render.cellSize;
    return view;
}

} // namespace sandglass
