// SPDX-License-Identifier: MIT
#include "app/application.hpp"

#include "app/frame_benchmark_runner.hpp"
#include "app/user_settings.hpp"
#include "gui/build_progress_window.hpp"
#include "gui/help_window.hpp"
#include "gui/panels.hpp"
#include "gui/quit_question.hpp"
#include "view/render/shader_program.hpp"

#include "scene/canvas_surface.hpp"
#include "scene/data_paths.hpp"
#include "scene/draft_image.hpp"
#include "scene/file_io.hpp"
#include "scene/scene_export.hpp"
#include "scene/state_file.hpp"

#include "sandcore/display_positions.hpp"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
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

bool isStateFile(const std::filesystem::path& path) { return path.extension() == ".sand"; }

// Where the file dialog starts for a choice: the path the panel holds for it.
std::string startPathFor(const AppState& state, FileChoice choice) {
    switch (choice) {
    case FileChoice::OpenState:
    case FileChoice::SaveState: return state.files.statePath;
    case FileChoice::Export: return state.files.exportPath;
    case FileChoice::Model: return state.scene.request.modelPath;
    case FileChoice::Draft: return state.painting.draftPath;
    case FileChoice::ScreenshotFolder: return state.files.screenshotFolder + "/";
    }
    return {};
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
        // Every press and release is kept, so clicks between two slow frames all count.
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window, &x, &y);
        of(window).queueMouseButton(button, action == GLFW_PRESS, x, y);
    }
    static void close(GLFWwindow* window) {
        // The window's close button asks first too, when there are unsaved edits (U5).
        if (of(window).state_.files.unsavedEdits == 0) return;
        glfwSetWindowShouldClose(window, GLFW_FALSE);
        of(window).state_.files.confirmQuit = true; // a second click keeps the question up
    }
    static void focus(GLFWwindow* window, int focused) { ImGui_ImplGlfw_WindowFocusCallback(window, focused); }
    static void enter(GLFWwindow* window, int entered) { ImGui_ImplGlfw_CursorEnterCallback(window, entered); }
    static void drop(GLFWwindow* window, int count, const char** paths) {
        if (count < 1) return;
        of(window).openFile(paths[0]);
    }
};

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
    glfwSetWindowUserPointer(handle, this);
    glfwSetKeyCallback(handle, ApplicationCallbacks::key);
    glfwSetCharCallback(handle, ApplicationCallbacks::character);
    glfwSetScrollCallback(handle, ApplicationCallbacks::scroll);
    glfwSetMouseButtonCallback(handle, ApplicationCallbacks::mouseButton);
    glfwSetWindowFocusCallback(handle, ApplicationCallbacks::focus);
    glfwSetCursorEnterCallback(handle, ApplicationCallbacks::enter);
    glfwSetDropCallback(handle, ApplicationCallbacks::drop);
    glfwSetWindowCloseCallback(handle, ApplicationCallbacks::close);

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
    if (scene().kind() == sandcore::SceneKind::Canvas) camera_.rotate(-camera_.yaw(), kCanvasPitch - camera_.pitch());
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

void Application::queueMouseButton(int button, bool pressed, double x, double y) {
    imgui_.queueMouseTransition({button, pressed, x, y});
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
    renderer_.setDraftPlacement(canvas_.draftPlacement(host_.scene(), state_.painting, state_.render.cellSize));
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
        renderer_.setScene(host.scene(), render.cellSize, host.modelDrawing().get());
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
    const bool leftPaints = scene().kind() == sandcore::SceneKind::Canvas;
    for (const auto& [glfwButton, button] : buttons)
        if (glfwGetMouseButton(handle, glfwButton) == GLFW_PRESS)
            applyMouseDrag(capture, button, alt, leftPaints, dx, dy, float(height), camera_);
    if (scene().kind() != sandcore::SceneKind::Canvas) return;
    const bool leftDown = glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    // While an obstacle is being placed, the left button drags its box instead of pouring sand.
    if (state_.obstacleDrag.armed || state_.obstacleDrag.dragging)
        handleObstacleDrag(x, y, leftDown && !alt, capture);
    else
        handleCanvasPointer({x, y, leftDown, alt, capture.mouse});
}

void Application::handleKey(KeyCommand command) {
    switch (command) {
    case KeyCommand::ToggleGui: state_.showGui = !state_.showGui; break;
    case KeyCommand::PrintFilledCells:
        std::printf("filled cells: %lld (upper %lld, lower %lld)\n", (long long)scene().grainCount(),
                    (long long)scene().counters().grainsUpper, (long long)scene().counters().grainsLower);
        break;
    case KeyCommand::PrintFrameRate:
        std::printf("%.1f frames per second, %.2f ms per frame\n", state_.stats.framesPerSecond,
                    state_.stats.millisecondsPerFrame);
        break;
    case KeyCommand::RunBenchmark:
        if (!benchmark_.running) state_.commands.push(Command::Benchmark);
        break;
    case KeyCommand::Quit:
        // Esc during the frame benchmark ends the benchmark, and during a build the build, not the program.
        if (benchmark_.running)
            benchmark_.cancelRequested = true;
        else if (state_.building && !state_.build.cancelling && !state_.files.confirmQuit)
            state_.commands.push(Command::CancelBuild);
        else
            state_.commands.push(Command::Quit);
        break;
    case KeyCommand::Help: state_.showHelp = !state_.showHelp; break;
    case KeyCommand::Screenshot: state_.commands.push(Command::Screenshot); break;
    case KeyCommand::Undo: state_.commands.push(Command::Undo); break;
    case KeyCommand::Flip: state_.commands.push(Command::Flip); break;
    case KeyCommand::Redo: state_.commands.push(Command::Redo); break;
    case KeyCommand::Save: state_.commands.push(Command::SaveState); break;
    case KeyCommand::Open: state_.commands.push(Command::LoadState); break;
    default: break;
    }
    std::fflush(stdout);
}

void Application::adoptBuild(const BuildOutcome& outcome) {
    state_.statusLine = outcome.message;
    const std::string draft = std::exchange(draftAfterBuild_, {});
    if (!outcome.adopted) {
        // The running scene stays, and the panel shows it again rather than the choice that failed.
        state_.scene = state_.loaded;
        return;
    }
    rememberModel(host_.loaded().request.modelPath);
    state_.loaded = host_.loaded();
    state_.files.unsavedEdits = 0; // the edits went with the scene they were made in
    canvas_.sceneReplaced();
    timer_.stop();
    turnStarted_.reset();
    camera_.setTurn(0.0f);
    frameCamera();
    if (!draft.empty() && scene().kind() == sandcore::SceneKind::Canvas) loadDraft(draft);
}

void Application::rememberModel(const std::string& path) {
    // The bundled models have their own list in the Scene tab; recent files are the user's.
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::weakly_canonical(modelsFolder(), error);
    if (path.empty() || (!error && std::filesystem::weakly_canonical(path, error).parent_path() == folder)) return;
    addRecentFile(state_.files.recentFiles, path);
}

bool Application::openFile(const std::string& path) {
    // A .sand file opens straight away: the state path changes only when it opens, so a file
    // that fails to open is never the one the next Save writes over.
    if (isStateFile(path)) return loadStateFile(path);
    if (isDraftImageFile(path)) {
        if (scene().kind() == sandcore::SceneKind::Canvas) return loadDraft(path);
        // An image is painted over on the canvas: build one, then show the draft on it.
        state_.scene.request.kind = sandcore::SceneKind::Canvas;
        state_.scene.request.modelPath.clear();
        state_.scene.request.shape.clear();
        state_.scene.request.resolution = defaultResolution(sandcore::SceneKind::Canvas);
        draftAfterBuild_ = path;
        state_.commands.push(Command::Rebuild);
        return true;
    }
    // Every other file is a model, built as an hourglass unless a sculpture runs.
    state_.scene.request.modelPath = path;
    state_.scene.request.shape.clear();
    if (state_.scene.request.kind == sandcore::SceneKind::Canvas) state_.scene.request.kind = sandcore::SceneKind::Hourglass;
    state_.commands.push(Command::Rebuild);
    return true;
}

void Application::serveCommands() {
    if (const auto outcome = host_.pollBuild()) adoptBuild(*outcome);
    if (const std::optional<ChosenFile> chosen = fileChooser_.poll()) serveChosenFile(*chosen);
    // Screenshots and the benchmark wait for the frame; run() takes them.
    std::vector<Command> later;
    for (Command command : state_.commands.take()) {
        if (command == Command::Screenshot || command == Command::Benchmark)
            later.push_back(command);
        else
            serve(command);
    }
    for (Command command : later) state_.commands.push(command);
    state_.building = host_.building();
    if (const BuildProgress* progress = host_.buildProgress())
        state_.build = {buildPhaseName(progress->phase()), progress->shareDone(), host_.buildSeconds(),
                        progress->cancelRequested()};
    else
        state_.build = {};
    canvas_.publishUndoState(state_.painting);
}

void Application::serve(Command command) {
    switch (command) {
    case Command::Rebuild:
        try {
            SceneSettings settings = state_.scene;
            // The panel keeps the last model chosen when the user switches to the canvas; it has none.
            if (settings.request.kind == sandcore::SceneKind::Canvas) {
                settings.request.modelPath.clear();
                settings.request.shape.clear();
            }
            applySceneDefaults(settings);
            state_.statusLine.clear();
            host_.requestBuild(settings);
        } catch (const std::exception& error) {
            state_.statusLine = error.what();
            state_.scene = state_.loaded;
        }
        break;
    case Command::ApplyStepSettings: host_.applyStepSettings(state_.scene.step); break;
    case Command::Reset:
        host_.reset();
        canvas_.sceneReplaced();
        timer_.stop();
        state_.statusLine = "reset";
        break;
    case Command::Flip:
        if (!host_.flip()) {
            state_.statusLine = "only an hourglass turns over";
            break;
        }
        // The sand is already mirrored; the view starts upside down and turns back upright.
        turnStarted_ = Clock::now();
        updateTurnAnimation();
        timer_.sceneTurned(scene());
        state_.statusLine = "turned over";
        break;
    case Command::StartTimer:
        try {
            timer_.start(scene(), 60.0 * state_.timer.minutes + state_.timer.seconds);
            state_.statusLine = "timer set: measuring the drain...";
        } catch (const std::exception& error) {
            state_.statusLine = error.what();
        }
        break;
    case Command::StopTimer: timer_.stop(); break;
    case Command::SingleStep: host_.requestSingleStep(); break;
    case Command::CancelBuild:
        if (!host_.building()) break;
        host_.cancelBuild();
        state_.build.cancelling = true;
        state_.statusLine = "cancelling the build...";
        break;
    case Command::FrameCamera: frameCamera(); break;
    case Command::Undo:
    case Command::Redo: {
        const bool undo = command == Command::Undo;
        const bool changed = undo ? canvas_.undo(host_) : canvas_.redo(host_);
        if (changed) ++state_.files.unsavedEdits;
        state_.statusLine = changed ? (undo ? "undone" : "redone") : (undo ? "nothing to undo" : "nothing to redo");
        break;
    }
    case Command::SaveState: saveStateFile(); break;
    case Command::LoadState: loadStateFile(state_.files.statePath); break;
    case Command::Export:
        try {
            exportScene(state_.files.exportPath, host_.scene(),
                        {{state_.render.cellSize, state_.render.jitter}, host_.modelToWorld()});
            state_.statusLine = "exported to " + state_.files.exportPath;
        } catch (const std::exception& error) {
            state_.statusLine = error.what();
        }
        break;
    case Command::LoadDraft: loadDraft(state_.painting.draftPath); break;
    case Command::OpenFile: openFile(state_.files.openPath); break;
    case Command::AddObstacle: {
        const std::uint64_t layout = host_.layoutRevision();
        state_.statusLine = canvas_.addObstacle(host_, state_.painting.obstacleMin, state_.painting.obstacleMax);
        if (host_.layoutRevision() != layout) ++state_.files.unsavedEdits;
        break;
    }
    case Command::ClearObstacles:
        canvas_.clearObstacles(host_);
        if (scene().kind() == sandcore::SceneKind::Canvas) ++state_.files.unsavedEdits;
        state_.statusLine = "obstacles removed";
        break;
    case Command::Quit: askToQuit(); break;
    case Command::QuitNow: quitRequested_ = true; break;
    case Command::SaveAndQuit:
        if (saveStateFile()) quitRequested_ = true;
        else state_.files.confirmQuit = false; // the status line says why; the work stays open
        break;
    case Command::ChooseFile: {
        const std::string problem = fileChooser_.open(state_.files.choosing, startPathFor(state_, state_.files.choosing));
        if (!problem.empty()) state_.statusLine = problem;
        break;
    }
    case Command::Screenshot:
    case Command::Benchmark: break; // served by run() after the frame
    }
}

bool Application::saveStateFile() {
    try {
        saveState(state_.files.statePath, host_.scene(), state_.loaded.request);
        state_.files.unsavedEdits = 0;
        state_.statusLine = "saved to " + state_.files.statePath;
        addRecentFile(state_.files.recentFiles, state_.files.statePath);
        return true;
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        return false;
    }
}

void Application::askToQuit() {
    // U5: edits not yet saved are not thrown away without a question; Esc again cancels it.
    if (state_.files.unsavedEdits == 0) {
        quitRequested_ = true;
        return;
    }
    state_.files.confirmQuit = !state_.files.confirmQuit;
}

void Application::serveChosenFile(const ChosenFile& chosen) {
    if (chosen.path.empty()) return; // cancelled: nothing changes
    switch (chosen.choice) {
    case FileChoice::OpenState:
        loadStateFile(chosen.path);
        break;
    case FileChoice::SaveState:
        state_.files.statePath = chosen.path;
        saveStateFile();
        break;
    case FileChoice::Export:
        state_.files.exportPath = chosen.path;
        serve(Command::Export);
        break;
    case FileChoice::Model:
        state_.scene.request.modelPath = chosen.path;
        state_.scene.request.shape.clear();
        if (state_.scene.request.kind == sandcore::SceneKind::Canvas) state_.scene.request.kind = sandcore::SceneKind::Hourglass;
        serve(Command::Rebuild);
        break;
    case FileChoice::Draft: loadDraft(chosen.path); break;
    case FileChoice::ScreenshotFolder:
        state_.files.screenshotFolder = chosen.path;
        state_.statusLine = "screenshots go to " + chosen.path;
        break;
    }
}

bool Application::loadStateFile(const std::string& path) {
    try {
        LoadedState loaded = loadState(path);
        // The running scene stays untouched unless the whole file loaded.
        host_.adoptLoaded(std::move(loaded.scene), loaded.settings);
        state_.files.statePath = path;
        state_.loaded = host_.loaded();
        state_.scene = state_.loaded;
        canvas_.sceneReplaced();
        timer_.stop();
        turnStarted_.reset();
        camera_.setTurn(0.0f);
        frameCamera();
        state_.files.unsavedEdits = 0;
        state_.statusLine = "opened " + path;
        addRecentFile(state_.files.recentFiles, path);
        return true;
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        return false;
    }
}

bool Application::loadDraft(const std::string& path) {
    try {
        renderer_.setDraftImage(canvas_.loadDraft(path));
        state_.painting.loadedDraft = path;
        state_.painting.draftPath = path;
        state_.painting.showDraft = true;
        state_.statusLine = "draft " + path;
        if (std::filesystem::path(path).parent_path() != modelsFolder()) addRecentFile(state_.files.recentFiles, path);
        return true;
    } catch (const std::exception& error) {
        state_.statusLine = error.what(); // the previous draft, if any, stays in use
        return false;
    }
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

std::optional<CanvasColumn> Application::columnUnderCursor(double cursorX, double cursorY) {
    return canvas_.columnUnderCursor(host_, cursorX, cursorY, canvasView(), state_.painting);
}

bool Application::handleCanvasPointer(const PointerSample& sample) {
    const bool changed = canvas_.handlePointer(host_, sample, canvasView(), state_.painting);
    if (changed) ++state_.files.unsavedEdits;
    canvas_.publishUndoState(state_.painting);
    return changed;
}

RgbImage Application::captureFrame() const {
    int width = 0, height = 0;
    targetSize(width, height);
    bindTarget();
    return readPixels(width, height);
}

bool Application::saveScreenshot(const std::filesystem::path& file) {
    try {
        writePng(file, captureFrame());
        std::error_code error;
        const std::filesystem::path shown = std::filesystem::absolute(file, error);
        state_.statusLine = "saved " + (error ? file : shown).string();
        std::printf("screenshot %s\n", file.string().c_str());
        std::fflush(stdout);
        return true;
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        std::fprintf(stderr, "sandglass: %s\n", error.what());
        return false;
    }
}

void Application::saveNumberedScreenshot(const RgbImage& image) {
    // E4: the first free sandglass-N.png in the chosen folder; an earlier file is never replaced.
    try {
        // Numbers count from 1 again in a folder newly chosen.
        if (state_.files.screenshotFolder != screenshotFolderUsed_) screenshotsTaken_ = 0;
        screenshotFolderUsed_ = state_.files.screenshotFolder;
        const std::filesystem::path file = writeNewNumberedFile(state_.files.screenshotFolder, "sandglass", ".png",
                                                                encodePng(image), screenshotsTaken_ + 1);
        const std::string number = file.stem().string().substr(std::string("sandglass-").size());
        screenshotsTaken_ = std::stoi(number);
        std::error_code error;
        const std::filesystem::path shown = std::filesystem::absolute(file, error);
        state_.files.lastScreenshot = (error ? file : shown).string();
        state_.statusLine = "screenshot saved to " + state_.files.lastScreenshot;
        std::printf("screenshot %s\n", state_.files.lastScreenshot.c_str());
        std::fflush(stdout);
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        std::fprintf(stderr, "sandglass: %s\n", error.what());
    }
}

void Application::runInteractiveBenchmark() {
    state_.statusLine = "benchmark running...";
    try {
        const BenchmarkReport report = runFrameBenchmark(*this, thesisBenchmarkCases(), BenchmarkTiming{});
        if (report.cancelled) {
            state_.statusLine = "benchmark cancelled";
            std::printf("%s\n", state_.statusLine.c_str());
            std::fflush(stdout);
            return;
        }
        writeBenchmarkFiles(options_.benchmarkFolder, {report}, "key B in the window");
        state_.statusLine = "benchmark written to " + (options_.benchmarkFolder / "benchmark.txt").string();
        std::printf("%s\n", state_.statusLine.c_str());
    } catch (const std::exception& error) {
        state_.statusLine = error.what();
        std::fprintf(stderr, "sandglass: %s\n", error.what());
    }
}

} // namespace sandglass
