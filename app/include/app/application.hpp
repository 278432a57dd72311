// SPDX-License-Identifier: MIT
#pragma once
// The window application: the window loop over a scene host, a canvas controller, the
// renderer and the panels.

#include "app/imgui_layer.hpp"
#include "view/app_state.hpp"
#include "view/camera.hpp"
#include "view/file_chooser.hpp"
#include "view/input_routing.hpp"
#include "view/paint/canvas_controller.hpp"
#include "view/render/framebuffer.hpp"
#include "view/render/scene_renderer.hpp"
#include "view/window.hpp"

#include "scene/hourglass_timer.hpp"
#include "scene/scene_host.hpp"

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>

namespace sandglass {

/// How the application starts.
struct ApplicationOptions {
    WindowOptions window;            ///< size, visibility, vsync
    bool offscreen = false;          ///< draw into an offscreen framebuffer of the window's size (hidden runs)
    AppState initial;                ///< scene, display settings and simulation on/off at start
    int stepsBeforeStart = 0;        ///< simulation steps run before the first frame
    std::string digPath;             ///< a path "X,Y,Z ..." a body digs along from the first step (SceneHost::startDig)
    std::string digBody = "blade";   ///< blade, box, ball or a model file
    int digSpeed = 1;                ///< cells the digging body moves per step
    int frameLimit = 0;              ///< close after this many frames; 0 = run until closed
    std::filesystem::path screenshotFile; ///< with frameLimit: the last frame is saved here
    std::filesystem::path benchmarkFolder = "."; ///< where the B key writes benchmark.txt and .csv
    UndoLimits undo;                 ///< P7: strokes and bytes the canvas keeps for undo (32, 256 MiB)
    float cameraZoom = 1.0f;         ///< start closer (< 1) or farther (> 1) than the framing distance
    std::filesystem::path stateFile; ///< E1: open this saved state instead of building `initial.scene`
    std::filesystem::path screenshotFolder; ///< E4: where P saves; empty = the desktop's pictures folder
    std::optional<std::array<int, 2>> windowPosition; ///< I4: the window's top-left corner on the desktop; none = the window manager's choice
    std::filesystem::path panelLayoutFile; ///< I4: ImGui's imgui.ini for the panels' layout; empty = none kept
};

/// The window loop: poll -> new frame -> panels -> commands -> steps by the clock -> scene ->
/// panels drawn -> swap. The scene lives in a SceneHost, the canvas work in a CanvasController;
/// the loop routes input to them and draws. The same object renders hidden frames for
/// `sandglass render` and the frames the frame-rate benchmark measures.
class Application {
public:
    /// Opens the window and builds the scene (or opens options.stateFile); throws WindowError (no
    /// display / GL context), std::invalid_argument (bad scene settings), FileError or
    /// StateFileError (a state file that cannot be opened) or std::runtime_error (shader problem).
    explicit Application(ApplicationOptions options);
    ~Application();
    Application(const Application&) = delete;
    Application& operator=(const Application&) = delete;

    /// The main loop until the window closes, Esc, Exit or the frame limit; returns the exit code.
    int run();
    /// One whole frame of the running scene into the current target, with `elapsedSeconds` of
    /// wall time fed to the clock; does not swap.
    void renderFrame(double elapsedSeconds);
    /// One frame of another host (the frame benchmark's own scene) drawn with these settings,
    /// panels included when `panels`; the application's own scene and settings stay untouched.
    void renderHostFrame(SceneHost& host, const RenderSettings& render, bool panels, double elapsedSeconds);
    /// Shows the frame drawn (or, offscreen, waits until it is drawn).
    void finishFrame();
    /// The last frame drawn, read back from the target.
    RgbImage captureFrame() const;
    /// Framebuffer size of the current target, pixels.
    void targetSize(int& width, int& height) const;

    /// The canvas mouse path: the window's mouse handling calls it every frame in the canvas
    /// scene, tests call it with scripted samples. Returns true when grains changed.
    bool handleCanvasPointer(const PointerSample& sample);
    /// Obstacle placement with the mouse (after PaintingSettings "Place with the mouse" arms
    /// AppState::obstacleDrag): a left press on the canvas floor starts a box, moves stretch it,
    /// the release queues AddObstacle with the box (and the typed form's heights). The window's
    /// mouse handling calls it while armed; tests call it with scripted samples.
    void handleObstacleDrag(double x, double y, bool leftDown, const InputCapture& capture);
    /// The digger tool (AppState::digger): a left press on the canvas floor places its body there
    /// (or starts from where it stands), moves drag it through the sand a few cells a frame at the
    /// panel's depth, and the whole drag is one undo step. The window's mouse handling calls it
    /// while the tool is on; tests call it with scripted samples.
    void handleDiggerDrag(double x, double y, bool leftDown, const InputCapture& capture);
    /// The arrow keys while the digger tool is on: one cell along x or z; false for other keys.
    bool driveDiggerByKey(KeyCommand command);
    /// The canvas column under a cursor position (window coordinates) on the surface the
    /// painting settings pick (source or target); the same lookup a stroke makes.
    std::optional<CanvasColumn> columnUnderCursor(double cursorX, double cursorY);
    /// The view the canvas is picked in: the camera and the current window and target sizes.
    CanvasView canvasView() const;
    /// Loads a PNG or JPEG as the draft and shows it; on a bad file the status line gets the
    /// one-line reason and the previous draft stays. Returns true when it loaded.
    bool loadDraft(const std::string& path);
    /// Voxelizes a model file as the digger's body (placed at the next drag); false and the
    /// one-line reason in the status line for a file that is no model, the body kept as it was.
    bool loadDiggerBody(const std::string& path);
    /// E1: replaces the scene by a saved state; false (and the one-line error in the status line)
    /// when the file cannot be loaded, the running scene then unchanged.
    bool loadStateFile(const std::string& path);
    /// I3: opens a file as its kind says, as a drop on the window does: a .sand state at once, a
    /// PNG or JPEG as the draft (on a canvas, built first when another scene runs), any other
    /// file as a model (an hourglass, or the running sculpture). False when it failed at once.
    bool openFile(const std::string& path);
    /// Serves the commands the panels and keys queued (rebuild, reset, undo, draft, obstacles...).
    void serveCommands();
    /// A mouse button pressed or released at (x, y) window units: the GLFW callback calls this
    /// for every event, so several clicks between two frames each reach the panels.
    void queueMouseButton(int button, bool pressed, double x, double y);

    /// The frame benchmark's progress (B key, bench --render): rows done of rows, and whether
    /// Esc asked to stop it.
    struct BenchmarkProgress {
        bool running = false;
        bool cancelRequested = false;
        int rowsDone = 0;
        int rows = 0;
    };
    BenchmarkProgress& benchmarkProgress() { return benchmark_; }

    /// Runs simulation steps now, outside the clock (for scripted drawings and tests).
    void runSteps(int steps) { host_.runSteps(steps); }
    /// Share (0..1) of the last step's glide that frames draw now.
    float displayStepFraction() const { return host_.displayStepFraction(); }

    AppState& state() { return state_; }                          ///< the panels' view of the application
    const AppState& state() const { return state_; }              ///< as above, to read
    SceneHost& host() { return host_; }                           ///< the running scene, its builds and clock
    const sandcore::Scene& scene() const { return host_.scene(); } ///< the running scene
    const CanvasController& canvas() const { return canvas_; }    ///< strokes, draft and undo
    const SceneRenderer& renderer() const { return renderer_; }   ///< what the last frame drew
    SceneRenderer& renderer() { return renderer_; }               ///< as above, to switch GPU timing on
    OrbitCamera& camera() { return camera_; }                     ///< the view
    std::int64_t framesDrawn() const { return framesDrawn_; }     ///< frames since start
    const Window& window() const { return window_; }              ///< the window and its context
    const ApplicationOptions& options() const { return options_; } ///< how it was started

private:
    friend struct ApplicationCallbacks;
    // The frame (application.cpp).
    void bindTarget() const;
    void frameCamera();
    void buildWindows();
    void drawHost(SceneHost& host, const RenderSettings& render);
    // Input (application_input.cpp).
    void installInputCallbacks();
    void handleMouse();
    void handleKey(KeyCommand command);
    // Commands (application_commands.cpp).
    void serve(Command command);
    void adoptBuild(const BuildOutcome& outcome);
    void rememberModel(const std::string& path);
    void askToQuit();
    void runInteractiveBenchmark();
    // Files and screenshots (application_files.cpp).
    bool saveStateFile();
    void chooseFile();
    void serveChosenFile(const ChosenFile& chosen);
    bool saveScreenshot(const std::filesystem::path& file);
    void saveNumberedScreenshot(const RgbImage& image);
    // What is drawn over the scene, and per-frame extras (application_overlays.cpp,
    // application_obstacle_drag.cpp).
    void updateStatistics(double elapsedSeconds);
    void updateTimer();
    void updateTurnAnimation();
    void drawOverlays();
    void drawBrushOutline();
    void drawBenchmarkProgress();
    void drawObstacleBox();
    void keepDiggerAsSet(); // the panel's depth and heading, applied to the standing body
    std::optional<sandcore::InsideMask> chosenDiggerShape(); // the panel's body; none: no model loaded yet

    ApplicationOptions options_;
    AppState state_;
    Window window_;
    ImGuiLayer imgui_;
    std::optional<OffscreenTarget> offscreen_;
    SceneRenderer renderer_;
    SceneHost host_;
    CanvasController canvas_;
    HourglassTimer timer_;
    OrbitCamera camera_;
    std::optional<std::chrono::steady_clock::time_point> turnStarted_; // the view turns after a flip
    // Which host's grains and layout the renderer holds, so it is told only of real changes.
    const SceneHost* drawnHost_ = nullptr;
    std::uint64_t drawnContent_ = 0, drawnLayout_ = 0;
    double lastCursorX_ = 0.0, lastCursorY_ = 0.0;
    std::int64_t framesDrawn_ = 0;
    int screenshotsTaken_ = 0;               // the number of the last screenshot, where to look for a free one
    std::string screenshotFolderUsed_;       // the folder that number belongs to
    BenchmarkProgress benchmark_;
    std::optional<RgbImage> sceneOnlyFrame_; // this frame before the panels, for a screenshot without them
    bool quitRequested_ = false;             // the loop ends after this frame
    FileChooser fileChooser_;
    std::optional<sandcore::InsideMask> diggerModel_; // the model file's body (DiggerSettings::loadedModel)
    std::string draftAfterBuild_;            // an image opened on another scene: shown once the canvas is built
};

} // namespace sandglass
