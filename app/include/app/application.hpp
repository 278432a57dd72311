#pragma once
// The window application (SPEC G1-G4): the ImGui main loop of poll -> new frame -> panels ->
// commands -> simulation steps by the SimClock -> scene -> panels drawn -> swap. The same
// object renders hidden frames for `sandglass render` and runs the B1 benchmark.

#include "view/app_state.hpp"
#include "view/camera.hpp"
#include "app/frame_benchmark.hpp"
#include "app/imgui_layer.hpp"
#include "view/input_routing.hpp"
#include "view/paint/canvas_input.hpp"
#include "view/render/framebuffer.hpp"
#include "view/render/scene_renderer.hpp"
#include "view/window.hpp"

#include "sandcore/scene.hpp"
#include "sandcore/sim_clock.hpp"

#include <chrono>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <optional>

namespace sandglass {

/// How the application starts.
struct ApplicationOptions {
    WindowOptions window;            ///< size, visibility, vsync
    bool offscreen = false;          ///< draw into an offscreen framebuffer of the window's size (hidden runs)
    AppState initial;                ///< scene, display settings and simulation on/off at start
    int stepsBeforeStart = 0;        ///< simulation steps run before the first frame
    int frameLimit = 0;              ///< close after this many frames; 0 = run until closed
    std::filesystem::path screenshotFile; ///< with frameLimit: the last frame is saved here
    std::filesystem::path benchmarkFolder = "."; ///< where the B key writes benchmark.txt and .csv
    UndoLimits undo;                 ///< P7: strokes and bytes the canvas keeps for undo (32, 256 MiB)
    float cameraZoom = 1.0f;         ///< start closer (< 1) or farther (> 1) than the framing distance
};

class Application {
public:
    /// Opens the window and builds the scene; throws WindowError (no display / GL context),
    /// std::invalid_argument (bad scene settings) or std::runtime_error (shader problem).
    explicit Application(ApplicationOptions options);
    ~Application();
    Application(const Application&) = delete;
    Application& operator=(const Application&) = delete;

    /// The main loop until the window closes, Esc, Exit or the frame limit; returns the exit code.
    int run();
    /// One whole frame into the current target, with `elapsedSeconds` of wall time fed to the
    /// clock; does not swap.
    void renderFrame(double elapsedSeconds);
    /// The last frame drawn, read back from the target.
    RgbImage captureFrame() const;
    /// Runs the B1 cases on the current scene (simulation and GUI on) and returns the rows;
    /// afterwards the scene is as it was before (each row resets it to measure the same flow).
    BenchmarkReport runBenchmark(const std::vector<BenchmarkCase>& cases, const BenchmarkTiming& timing);

    /// The canvas mouse path (SPEC P1-P4): the window's mouse handling calls it every frame in
    /// the canvas scene, tests call it with scripted samples. Returns true when grains changed.
    bool handleCanvasPointer(const PointerSample& sample);
    /// P1: the canvas column under a cursor position (window coordinates) on the surface the
    /// painting settings pick (source or target); the same lookup a stroke makes.
    std::optional<CanvasColumn> columnUnderCursor(double cursorX, double cursorY);
    /// The view the canvas is picked in: the camera and the current window and target sizes.
    CanvasView canvasView() const;
    /// P5: loads a PNG or JPEG as the draft and shows it; on a bad file the status line gets the
    /// one-line reason and the previous draft stays. Returns true when it loaded.
    bool loadDraft(const std::string& path);
    /// Serves the commands the panels and keys raised (rebuild, reset, undo, draft, obstacles...).
    void serveCommands();
    /// Runs simulation steps now, outside the clock (for scripted drawings and tests).
    void runSteps(int steps);
    /// True while a scene is being built in the background (a rebuild request waits for it).
    bool rebuilding() const { return pendingScene_.valid(); }
    const CanvasInput& canvasInput() const { return canvasInput_; } ///< picker and painter state
    /// Share (0..1) of the last step's glide that frames draw now: the clock's fraction while it
    /// runs the steps, 1 (grains at their new cells) after steps made outside it (a single step
    /// while paused, runSteps, the steps before the first frame of `sandglass render`).
    float displayStepFraction() const;
    const SceneRenderer& renderer() const { return renderer_; } ///< what the last frame drew

    AppState& state() { return state_; }                         ///< panels' view of the application
    const sandcore::Scene& scene() const { return *scene_; }     ///< the running scene
    OrbitCamera& camera() { return camera_; }                    ///< the view
    std::int64_t framesDrawn() const { return framesDrawn_; }    ///< frames since start
    const Window& window() const { return window_; }             ///< the window and its context

private:
    friend struct ApplicationCallbacks;
    void targetSize(int& width, int& height) const;
    void bindTarget() const;
    void handleMouse();
    void handleKey(KeyCommand command);
    void servePaintingCommands();
    PaintSettings paintSettings() const;
    void updateDraftPlacement();
    void startRebuild();
    void finishRebuild();
    void adoptScene(sandcore::Scene scene);
    void stepSimulation(double elapsedSeconds);
    void updateStatistics(double elapsedSeconds);
    void saveScreenshot(const std::filesystem::path& file);
    void runInteractiveBenchmark();
    void runBenchmarkRows(const std::vector<BenchmarkCase>& cases, const BenchmarkTiming& timing,
                          const std::function<void()>& frame, BenchmarkReport& report);

    ApplicationOptions options_;
    AppState state_;
    Window window_;
    ImGuiLayer imgui_;
    std::optional<OffscreenTarget> offscreen_;
    SceneRenderer renderer_;
    CanvasInput canvasInput_;
    std::unique_ptr<sandcore::Scene> scene_;
    std::future<sandcore::Scene> pendingScene_;
    std::chrono::steady_clock::time_point rebuildStarted_;
    sandcore::SimClock clock_;
    // The last step did not come from the running clock, whose fraction would show it undone.
    bool lastStepOutsideClock_ = false;
    OrbitCamera camera_;
    double lastCursorX_ = 0.0, lastCursorY_ = 0.0;
    std::int64_t framesDrawn_ = 0;
    int screenshotsTaken_ = 0;
};

} // namespace sandglass
