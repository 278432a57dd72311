#include "app/application.hpp"

#include "gui/panels.hpp"
#include "view/render/shader_program.hpp"

#include "sandcore/display_positions.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <system_error>

namespace sandglass {

namespace {

using Clock = std::chrono::steady_clock;

// Scenes are built off the main thread so the window stays responsive (SPEC G2).
sandcore::Scene buildSceneFor(const SceneSettings& settings) {
    sandcore::StepSettings step;
    step.seed = settings.seed;
    step.threads = std::max(1, settings.threads);
    return buildScene(settings.request, step);
}

std::vector<std::string> listModelFiles() {
    std::vector<std::string> files;
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::path(SANDGLASS_SOURCE_DIR) / "models";
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        const std::string extension = entry.path().extension().string();
        for (const char* known : {".obj", ".stl", ".ply", ".gltf", ".glb", ".off", ".fbx", ".dae", ".3ds"})
            if (extension == known) files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace

// GLFW calls plain functions; they find the application through the window's user pointer and
// forward every event to ImGui before routing it (ImGui's capture flags decide).
struct ApplicationCallbacks {
    static Application& of(GLFWwindow* window) { return *static_cast<Application*>(glfwGetWindowUserPointer(window)); }
    static InputCapture capture() {
        const ImGuiIO& io = ImGui::GetIO();
        return {io.WantCaptureMouse, io.WantCaptureKeyboard};
    }
    static void key(GLFWwindow* window, int key, int scancode, int action, int mods) {
        ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
        if (action == GLFW_RELEASE) return;
        const KeyCommand command = keyCommand(capture(), key, mods);
        const bool cameraKey = applyCameraCommand(command, of(window).camera_);
        if (!cameraKey && action == GLFW_PRESS) of(window).handleKey(command);
    }
    static void character(GLFWwindow* window, unsigned codepoint) {
        ImGui_ImplGlfw_CharCallback(window, codepoint);
        const KeyCommand command = characterCommand(capture(), codepoint);
        if (!applyCameraCommand(command, of(window).camera_)) of(window).handleKey(command);
    }
    static void scroll(GLFWwindow* window, double x, double y) {
        ImGui_ImplGlfw_ScrollCallback(window, x, y);
        applyScroll(capture(), float(y), of(window).camera_);
    }
    static void mouseButton(GLFWwindow* window, int button, int action, int mods) {
        ImGui_ImplGlfw_MouseButtonCallback(window, button, action, mods);
    }
    static void focus(GLFWwindow* window, int focused) { ImGui_ImplGlfw_WindowFocusCallback(window, focused); }
    static void enter(GLFWwindow* window, int entered) { ImGui_ImplGlfw_CursorEnterCallback(window, entered); }
    static void drop(GLFWwindow* window, int count, const char** paths) {
        if (count < 1) return;
        Application& app = of(window);
        // P5: an image dropped on the canvas is a draft; every other file is a model.
        if (app.scene_->kind() == sandcore::SceneKind::Canvas && isDraftImageFile(paths[0])) {
            app.state_.painting.draftPath = paths[0];
            app.state_.pending.loadDraft = true;
            return;
        }
        app.state_.scene.request.modelPath = paths[0];
        if (app.state_.scene.request.kind == sandcore::SceneKind::Canvas)
            app.state_.scene.request.kind = sandcore::SceneKind::Hourglass;
        app.state_.pending.rebuild = true;
    }
};

Application::Application(ApplicationOptions options)
    : options_(std::move(options)), state_(options_.initial), window_(options_.window),
      imgui_(window_.handle(), window_.contentScale()), renderer_(shaderDirectory()),
      canvasInput_(shaderDirectory(), options_.undo) {
    if (options_.offscreen) {
        int width = 0, height = 0;
        window_.framebufferSize(width, height);
        offscreen_.emplace(width, height);
    }
    GLFWwindow* handle = window_.handle();
    glfwSetWindowUserPointer(handle, this);
    glfwSetKeyCallback(handle, ApplicationCallbacks::key);
    glfwSetCharCallback(handle, ApplicationCallbacks::character);
    glfwSetScrollCallback(handle, ApplicationCallbacks::scroll);
    glfwSetMouseButtonCallback(handle, ApplicationCallbacks::mouseButton);
    glfwSetWindowFocusCallback(handle, ApplicationCallbacks::focus);
    glfwSetCursorEnterCallback(handle, ApplicationCallbacks::enter);
    glfwSetDropCallback(handle, ApplicationCallbacks::drop);

    state_.glRenderer = window_.glRenderer();
    state_.glVersion = window_.glVersion();
    state_.modelFiles = listModelFiles();
    state_.painting.draftFiles = listDraftFiles(std::filesystem::path(SANDGLASS_SOURCE_DIR) / "models");
    adoptScene(buildSceneFor(state_.scene));
    camera_.zoom(options_.cameraZoom);
    for (int i = 0; i < options_.stepsBeforeStart; ++i) scene_->step();
    lastStepOutsideClock_ = options_.stepsBeforeStart > 0;
    renderer_.sceneChanged();
    glfwGetCursorPos(handle, &lastCursorX_, &lastCursorY_);
}

Application::~Application() {
    if (pendingScene_.valid()) pendingScene_.wait();
    glfwSetWindowUserPointer(window_.handle(), nullptr);
}

void Application::adoptScene(sandcore::Scene scene) {
    scene_ = std::make_unique<sandcore::Scene>(std::move(scene));
    state_.runningSceneKind = scene_->kind();
    lastStepOutsideClock_ = false;
    renderer_.setScene(*scene_, state_.render.cellSize);
    canvasInput_.sceneReplaced();
    sandcore::Vec3 lo, hi;
    sandcore::sceneBounds(*scene_, {state_.render.cellSize, state_.render.jitter}, lo, hi);
    camera_.frame(lo, hi);
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
    while (!window_.shouldClose() && !state_.pending.quit) {
        glfwPollEvents();
        const auto now = Clock::now();
        renderFrame(std::chrono::duration<double>(now - last).count());
        last = now;
        const bool lastFrame = options_.frameLimit > 0 && framesDrawn_ >= options_.frameLimit;
        if (lastFrame && !options_.screenshotFile.empty()) saveScreenshot(options_.screenshotFile);
        if (state_.pending.screenshot) {
            state_.pending.screenshot = false;
            saveScreenshot("sandglass-" + std::to_string(++screenshotsTaken_) + ".png");
        }
        window_.swapBuffers();
        if (state_.pending.benchmark) {
            state_.pending.benchmark = false;
            runInteractiveBenchmark();
            last = Clock::now();
        }
        if (lastFrame) break;
    }
    return 0;
}

void Application::renderFrame(double elapsedSeconds) {
    imgui_.newFrame();
    handleMouse();
    if (state_.showGui) drawPanels(state_);
    camera_.setLensShift(state_.showGui ? state_.panelCoverage : 0.0f);
    serveCommands();
    stepSimulation(elapsedSeconds);
    updateDraftPlacement();
    bindTarget();
    int width = 0, height = 0;
    targetSize(width, height);
    renderer_.draw(*scene_, displayStepFraction(), state_.render, camera_, width, height,
                   window_.contentScale());
    if (pendingScene_.valid()) {
        // Progress indicator while a scene is built in the background.
        ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x * 0.5f, 20.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
        ImGui::Begin("##building", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
        const double seconds = std::chrono::duration<double>(Clock::now() - rebuildStarted_).count();
        ImGui::Text("building scene %c  %.1f s", "|/-\\"[int(seconds * 8.0) % 4], seconds);
        ImGui::End();
    }
    imgui_.render(state_.showGui || pendingScene_.valid());
    updateStatistics(elapsedSeconds);
    ++framesDrawn_;
}

void Application::handleMouse() {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_.handle(), &x, &y);
    const float dx = float(x - lastCursorX_), dy = float(y - lastCursorY_);
    lastCursorX_ = x;
    lastCursorY_ = y;
    GLFWwindow* handle = window_.handle();
    const bool alt = glfwGetKey(handle, GLFW_KEY_LEFT_ALT) == GLFW_PRESS || glfwGetKey(handle, GLFW_KEY_RIGHT_ALT) == GLFW_PRESS;
    const InputCapture capture = ApplicationCallbacks::capture();
    int width = 0, height = 0;
    glfwGetWindowSize(handle, &width, &height);
    const std::pair<int, MouseButton> buttons[] = {{GLFW_MOUSE_BUTTON_LEFT, MouseButton::Left},
                                                   {GLFW_MOUSE_BUTTON_MIDDLE, MouseButton::Middle},
                                                   {GLFW_MOUSE_BUTTON_RIGHT, MouseButton::Right}};
    for (const auto& [glfwButton, button] : buttons)
        if (glfwGetMouseButton(handle, glfwButton) == GLFW_PRESS)
            applyMouseDrag(capture, button, alt, dx, dy, float(height), camera_);
    if (scene_->kind() == sandcore::SceneKind::Canvas)
        handleCanvasPointer({x, y, glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS, alt, capture.mouse});
}

void Application::handleKey(KeyCommand command) {
    switch (command) {
    case KeyCommand::ToggleGui: state_.showGui = !state_.showGui; break;
    case KeyCommand::PrintFilledCells:
        std::printf("filled cells: %lld (upper %lld, lower %lld)\n", (long long)scene_->grainCount(),
                    (long long)scene_->counters().grainsUpper, (long long)scene_->counters().grainsLower);
        break;
    case KeyCommand::PrintFrameRate:
        std::printf("%.1f frames per second, %.2f ms per frame\n", state_.stats.framesPerSecond,
                    state_.stats.millisecondsPerFrame);
        break;
    case KeyCommand::RunBenchmark: state_.pending.benchmark = true; break;
    case KeyCommand::Quit: state_.pending.quit = true; break;
    case KeyCommand::Screenshot: state_.pending.screenshot = true; break;
    case KeyCommand::Undo: state_.pending.undo = true; break;
    default: break;
    }
    std::fflush(stdout);
}

void Application::serveCommands() {
    PendingCommands& pending = state_.pending;
    if (pendingScene_.valid() &&
        pendingScene_.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
        finishRebuild();
    // A request raised while a build runs stays pending and starts when that build is done.
    if (pending.rebuild && !pendingScene_.valid()) {
        startRebuild();
        pending.rebuild = false;
    }
    if (pending.reset) {
        scene_->reset();
        canvasInput_.sceneReplaced();
        renderer_.sceneChanged();
        state_.statusLine = "reset";
    }
    pending.reset = false;
    if (pending.singleStep) clock_.requestSingleStep();
    pending.singleStep = false;
    if (pending.frameCamera) {
        sandcore::Vec3 lo, hi;
        sandcore::sceneBounds(*scene_, {state_.render.cellSize, state_.render.jitter}, lo, hi);
        camera_.frame(lo, hi);
    }
    pending.frameCamera = false;
    servePaintingCommands();
}

void Application::startRebuild() {
    rebuildStarted_ = Clock::now();
    state_.statusLine.clear();
    pendingScene_ = std::async(std::launch::async, buildSceneFor, state_.scene);
}

void Application::finishRebuild() {
    if (state_.pending.rebuild) {
        // Newer settings arrived while it was built: the last request wins, this one is stale.
        try {
            pendingScene_.get();
        } catch (const std::exception&) {
            // its error no longer matters either
        }
        return;
    }
    try {
        adoptScene(pendingScene_.get());
        state_.statusLine = std::string("built ") + sceneKindName(scene_->kind()) + ", " +
                            std::to_string(scene_->grainCount()) + " grains";
    } catch (const std::exception& error) {
        state_.statusLine = error.what(); // the running scene stays as it was
    }
}

void Application::stepSimulation(double elapsedSeconds) {
    clock_.setRunning(state_.simulationRunning);
    clock_.setStepsPerSecond(state_.stepsPerSecond);
    const int due = clock_.advance(elapsedSeconds);
    if (due == 0) return;
    const auto start = Clock::now();
    for (int i = 0; i < due; ++i) scene_->step();
    // Paused, the clock's fraction stands still (often at 0): a single step would not show.
    lastStepOutsideClock_ = !clock_.running();
    const double milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count() / due;
    FrameStatistics& stats = state_.stats;
    stats.millisecondsPerStep = stats.millisecondsPerStep == 0.0f ? float(milliseconds)
                                                                  : 0.9f * stats.millisecondsPerStep + 0.1f * float(milliseconds);
    stats.stepsPerSecond = 0.95f * stats.stepsPerSecond +
                           0.05f * float(elapsedSeconds > 0.0 ? double(due) / elapsedSeconds : 0.0);
    renderer_.sceneChanged();
}

float Application::displayStepFraction() const {
    return lastStepOutsideClock_ ? 1.0f : float(clock_.stepFraction());
}

void Application::updateStatistics(double elapsedSeconds) {
    FrameStatistics& stats = state_.stats;
    const float milliseconds = float(elapsedSeconds * 1000.0);
    stats.frameMilliseconds[std::size_t(stats.historyNext)] = milliseconds;
    stats.historyNext = (stats.historyNext + 1) % FrameStatistics::kHistory;
    if (milliseconds > 0.0f) {
        stats.millisecondsPerFrame =
            stats.millisecondsPerFrame == 0.0f ? milliseconds : 0.9f * stats.millisecondsPerFrame + 0.1f * milliseconds;
        stats.framesPerSecond = 1000.0f / stats.millisecondsPerFrame;
    }
    if (!clock_.running()) stats.stepsPerSecond *= 0.95f;
    const sandcore::SceneCounters& counters = scene_->counters();
    stats.grains = scene_->grainCount();
    stats.grainsUpper = counters.grainsUpper;
    stats.grainsLower = counters.grainsLower;
    stats.movingGrains = counters.movesLastStep;
    stats.stepsDone = counters.stepsDone;
    stats.innerGrains = renderer_.stats().innerGrains;
    stats.subGrainsDrawn = renderer_.stats().subGrainsDrawn;
}

RgbImage Application::captureFrame() const {
    int width = 0, height = 0;
    targetSize(width, height);
    bindTarget();
    return readPixels(width, height);
}

void Application::saveScreenshot(const std::filesystem::path& file) {
    try {
        writePng(file, captureFrame());
        state_.statusLine = "saved " + file.string();
        std::printf("screenshot %s\n", file.string().c_str());
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        std::fprintf(stderr, "sandglass: %s\n", error.what());
    }
    std::fflush(stdout);
}

} // namespace sandglass
