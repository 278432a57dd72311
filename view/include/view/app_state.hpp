// SPDX-License-Identifier: MIT
#pragma once
// Everything the panels show and change. The panels read and write this struct and queue
// commands; the application carries the commands out after the panels are built. Nothing here
// points into the simulation's grids.

#include "view/file_chooser.hpp"
#include "view/render/render_settings.hpp"
#include "scene/scene_request.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sandglass {

/// Thesis §3.7 "Zeichnen" (canvas) controls, each with the thesis's default, plus SPEC P3, P6,
/// P7 and G2 obstacle placement.
struct PaintingSettings {
    bool erase = false;         ///< draw (default) or erase
    bool pickAtTarget = false;  ///< the mouse marks the source (default) or the target of falling sand
    bool thinLines = false;     ///< thick (default) or thin lines
    bool showDraft = false;     ///< draft image shown; default none
    int brushRadius = 0;        ///< cells around the picked column that also get sand; 0 = one column
    bool defaultSandColor = true;                        ///< new grains in the pale sand colours
    std::array<float, 3> sandColor{0.80f, 0.36f, 0.22f}; ///< RGB 0..1 of new grains when not default
    bool colorFromDraft = false; ///< P6: new grains take the draft's colour at their column
    std::string draftPath;       ///< the draft file the next loadDraft command reads
    std::string loadedDraft;     ///< the draft in use; empty = none
    std::vector<std::string> draftFiles; ///< models/draft_* files, for the draft list
    std::array<int, 3> obstacleMin{8, 0, 8};    ///< next obstacle's first cell (lower grid), inclusive
    std::array<int, 3> obstacleMax{16, 6, 16};  ///< next obstacle's last cell + 1 (lower grid), exclusive
    std::size_t undoSteps = 0;   ///< strokes that Undo can take back
    std::size_t undoBytes = 0;   ///< memory the kept strokes' snapshots use, compressed, bytes
    std::size_t redoSteps = 0;   ///< undone strokes that Redo can bring back
};

/// Where a panel window sits, top-left corner in window units; negative until first placed.
struct WindowPlacement {
    float x = -1.0f;
    float y = -1.0f;
};

/// A box dragged out on the canvas floor with the mouse (obstacle placement), in lower-grid columns.
struct ObstacleDrag {
    bool armed = false;    ///< the next left drag on the canvas places an obstacle instead of sand
    bool dragging = false; ///< the button is down and the box follows the cursor
    int startX = 0, startZ = 0, endX = 0, endZ = 0; ///< the columns at the drag's start and end
};

/// The digger tool: a moving body (sandcore/moving_body.hpp) dragged through the canvas's sand.
struct DiggerSettings {
    bool active = false;   ///< left drags and the arrow keys drive the digger instead of painting and turning the camera
    int body = 0;          ///< 0 blade, 1 box, 2 ball, 3 the model file loadedModel
    std::string modelPath; ///< the model file typed or chosen for the body (Command::LoadDiggerBody)
    std::string loadedModel; ///< the model file the body was voxelized from; empty: none yet
    int depth = 0;         ///< lower-grid layer of the body's bottom
    int heading = 0;       ///< quarter turns about the vertical, 0..3
    bool dragging = false; ///< the button is down and the body follows the cursor
};

/// SPEC E1, E2: where the File section saves, opens and exports.
struct FileSettings {
    std::string statePath = "sandglass.sand"; ///< the .sand file Save writes and Open reads
    std::string exportPath = "sand.ply";      ///< .ply, .vox, .obj, .stl or .glb for Export
    std::string screenshotFolder;             ///< E4: where P saves sandglass-N.png (set at start)
    bool screenshotWithPanel = false;         ///< E4: screenshots show the panels too
    std::string lastScreenshot;               ///< the file the last screenshot went to
    int unsavedEdits = 0;                     ///< U5: painting and obstacle changes since the last save or open (0 = nothing to lose)
    bool confirmQuit = false;                 ///< U5: the "quit without saving?" question is shown
    FileChoice choosing = FileChoice::OpenState; ///< what the next ChooseFile command opens the dialog for
    std::vector<std::string> recentFiles;     ///< I4: states, models and drafts opened or saved, newest first
    std::string openPath;                     ///< the file the next OpenFile command opens (a recent one)
};

/// What the panels and keys ask the application to do; served once per frame, in order.
enum class Command {
    Reset,             ///< refill the scene
    Rebuild,           ///< build a new scene from AppState::scene
    ApplyStepSettings, ///< seed, threads and physics of AppState::scene.step take effect on the next step
    SingleStep,        ///< one step while paused
    Screenshot,        ///< save this frame as PNG
    Benchmark,         ///< run the frame-rate benchmark
    Quit,              ///< close the window (asks first when there are unsaved edits)
    QuitNow,           ///< close the window without asking (the answer to that question)
    SaveAndQuit,       ///< save to FileSettings::statePath, then close when the save worked
    ChooseFile,        ///< open the desktop's file dialog for FileSettings::choosing
    FrameCamera,       ///< reset the camera to frame the scene
    Undo,              ///< take back the last stroke (Ctrl+Z)
    Redo,              ///< bring back the last undone stroke (Ctrl+Y, Ctrl+Shift+Z)
    SaveState,         ///< save the whole state to FileSettings::statePath (Ctrl+S)
    LoadState,         ///< replace the scene by the state in FileSettings::statePath (Ctrl+O)
    Export,            ///< export the sand to FileSettings::exportPath
    LoadDraft,         ///< load PaintingSettings::draftPath as the draft
    AddObstacle,       ///< add the box PaintingSettings::obstacleMin/Max to the canvas's lower grid
    ClearObstacles,    ///< remove every obstacle of the canvas
    Flip,              ///< turn the hourglass over (T)
    StartTimer,        ///< set the timer to TimerSettings::minutes:seconds on the sand as it is
    StopTimer,         ///< stop the timer
    OpenFile,          ///< open FileSettings::openPath as its kind says: a .sand state, a draft image or a model
    CancelBuild,       ///< stop the scene being built and keep the running one (I5)
    LoadDiggerBody,    ///< voxelize DiggerSettings::modelPath as the digger's body
};

/// Commands in the order they were raised.
class CommandQueue {
public:
    void push(Command command) { commands_.push_back(command); } ///< ask for a command
    /// True when the command is waiting.
    bool contains(Command command) const {
        return std::find(commands_.begin(), commands_.end(), command) != commands_.end();
    }
    /// Takes every waiting command, oldest first, leaving the queue empty.
    std::vector<Command> take() { return std::exchange(commands_, {}); }

private:
    std::vector<Command> commands_;
};

/// The hourglass as a timer: the duration chosen and where the timer stands.
struct TimerState {
    int minutes = 1;            ///< duration chosen, minutes part
    int seconds = 0;            ///< duration chosen, seconds part (0..59)
    bool set = false;           ///< a timer runs (or is being predicted)
    bool predicting = false;    ///< the drain is being measured on a worker thread
    bool finished = false;      ///< the sand has run out: time is up
    double elapsedSeconds = 0;  ///< sand run since the start, s
    double remainingSeconds = 0; ///< until the sand on top has run out, s
};

/// SPEC I5: the scene being built in the background, as the window shows it (refreshed every frame).
struct BuildStatus {
    std::string phase;       ///< what the build does now: "loading the model", "voxelizing", ...
    float shareDone = 0.0f;  ///< 0..1, by phase
    double seconds = 0.0;    ///< how long it has run, s
    bool cancelling = false; ///< Cancel was asked: it stops when its phase ends
};

/// Numbers for the statistics panel, refreshed every frame.
struct FrameStatistics {
    static constexpr int kHistory = 180;          ///< frames kept for the plot
    std::array<float, kHistory> frameMilliseconds{}; ///< ring buffer of frame times, ms
    int historyNext = 0;                          ///< next slot to write
    float framesPerSecond = 0.0f;                 ///< smoothed over about half a second
    float millisecondsPerFrame = 0.0f;            ///< smoothed frame time, ms
    float millisecondsPerStep = 0.0f;             ///< smoothed wall time of one simulation step, ms
    float stepsPerSecond = 0.0f;                  ///< steps actually run per second of wall time
    bool rateCapped = false;                      ///< the last frame could not run every step due (too slow)
    int maxStepsPerFrame = 0;                     ///< the cap of steps per frame
    std::int64_t grains = 0;                      ///< grains in the scene
    std::int64_t grainsUpper = 0;                 ///< filled cells of the upper grid
    std::int64_t grainsLower = 0;                 ///< filled cells of the lower grid
    std::int64_t movingGrains = 0;                ///< grains moved by the last step
    std::int64_t innerGrains = 0;                 ///< grains hidden by their neighbours (R13)
    std::int64_t subGrainsDrawn = 0;              ///< points or quads drawn in the last frame
    std::uint64_t stepsDone = 0;                  ///< steps since the last reset
};

/// The application's state, as far as the panels see it.
struct AppState {
    SceneSettings scene;            ///< what the next rebuild builds (the panel's choices)
    SceneSettings loaded;           ///< what the running scene was built from (set when a build is adopted)
    RenderSettings render;          ///< how grains are drawn
    PaintingSettings painting;      ///< canvas painting options
    TimerState timer;               ///< the hourglass as a timer
    FileSettings files;             ///< save, open and export paths
    bool simulationRunning = false; ///< thesis default: simulation off
    double stepsPerSecond = 30.0;   ///< flow speed (R9)
    bool showGui = true;            ///< Space hides the panels
    bool showHelp = false;          ///< F1, ? or the Help button: the keys and mouse controls
    bool showHelpHint = true;       ///< the one-line hint on where help is, until help is opened
    float uiScale = 1.0f;           ///< text and control size chosen in the panel (on top of the monitor's)
    ObstacleDrag obstacleDrag;      ///< a box being dragged out on the canvas floor
    DiggerSettings digger;          ///< the digger tool on the canvas
    float panelCoverage = 0.0f;     ///< share of the window's width the panel covers from the left edge
    WindowPlacement panelPlacement; ///< where the user put the panel (shown clamped to the window)
    WindowPlacement panelSize;      ///< the panel's size in the last frame (x width, y height)
    std::string openTab;            ///< a panel tab to select once ("run", "view", "scene", "paint", "file")
    std::string glRenderer;         ///< GL_RENDERER, for the statistics panel
    std::string glVersion;          ///< GL_VERSION
    std::string statusLine;         ///< the last message (error or confirmation) for the user
    std::vector<std::string> modelFiles; ///< files found in models/, for the model list
    std::string partsListPath;      ///< S7: the model file partsList was read from; empty = not read
    std::vector<PartSummary> partsList; ///< S7: that model's parts with their roles, for the checklist
    FrameStatistics stats;          ///< numbers shown in the statistics panel
    CommandQueue commands;          ///< requests to serve after the panels are built
    bool building = false;          ///< a scene is being built in the background
    BuildStatus build;              ///< how far that build is (while building)
};

} // namespace sandglass
