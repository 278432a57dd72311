// SPDX-License-Identifier: MIT
#pragma once
// The running scene of an application, without GL: the scene, the next one being built on a
// worker thread (the last request wins, the running scene stays until the new one is ready),
// and the clock that turns wall time into steps. Whoever draws or edits the scene watches its
// revisions instead of being told about every change.

#include "scene/digger.hpp"
#include "scene/scene_request.hpp"

#include "sandcore/scene.hpp"
#include "sandcore/sim_clock.hpp"
#include "sandcore/surface_upkeep.hpp"

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>

namespace sandglass {

/// What became of a build when it finished.
struct BuildOutcome {
    bool adopted = false; ///< the new scene runs now; false: it failed and the old scene stays
    bool cancelled = false; ///< SPEC I5: stopped by cancelBuild; the old scene stays
    std::string message;  ///< "built hourglass, 17848 grains" or the one-line error
};

/// Steps actually run per second of wall time, measured over the last second or so (frames
/// that ran no step count too, so the readout is the true rate).
class StepRateMeter {
public:
    /// Records that a frame of `elapsedSeconds` advanced the simulation by `steps` steps (whole
    /// steps run plus the change of the glide's fraction, so the rate has no rounding steps).
    void addFrame(double elapsedSeconds, double steps);
    double stepsPerSecond() const; ///< steps over the window's wall time; 0 before any time passed
    void clear();                  ///< forget the history (after a pause or a new scene)

private:
    struct Frame {
        double seconds;
        double steps;
    };
    std::deque<Frame> frames_;
    double seconds_ = 0.0;
    double steps_ = 0.0;
};

class SceneHost {
public:
    /// Builds the scene now, on this thread; throws as buildScene does.
    explicit SceneHost(const SceneSettings& settings);
    /// Runs a scene made elsewhere (a loaded state file) with the settings it was built from,
    /// drawn as modelled when its model file still gives its grids (as adoptLoaded).
    SceneHost(sandcore::Scene scene, const SceneSettings& settings);
    ~SceneHost();
    SceneHost(const SceneHost&) = delete;
    SceneHost& operator=(const SceneHost&) = delete;

    const sandcore::Scene& scene() const { return *scene_; } ///< the running scene
    /// The running scene for an edit (painting, obstacles, undo); counts as a change of its grains.
    sandcore::Scene& editScene();
    /// As editScene, for edits that also change which cells are INVALID (obstacles).
    sandcore::Scene& editLayout();
    /// S10: the running scene's model as modelled (upright world cells); null for a procedural
    /// scene, a canvas, or a loaded scene whose model file is gone or changed.
    const std::shared_ptr<const ModelDrawing>& modelDrawing() const { return drawing_; }
    /// W5: why the running scene's model gave no hourglass and what was done instead; empty otherwise.
    const std::string& modelNote() const { return modelNote_; }
    /// W6: how the running scene's model became world cells; null without a model.
    const ModelToWorld* modelToWorld() const { return modelToWorld_ ? &*modelToWorld_ : nullptr; }
    /// The settings the running scene was built from: what the panel shows as loaded.
    const SceneSettings& loaded() const { return loaded_; }
    /// Which of the three scenes runs (loaded().request.kind): what menus, painting and drawing go by.
    sandcore::SceneKind kind() const { return loaded_.request.kind; }

    /// E1: runs a scene that was loaded from a state file in place of the running one, with the
    /// settings it was built from; a build still running replaces it when done, as any request.
    /// S10: a scene from a model file is drawn as modelled again when the file still gives the
    /// same grids (else, or when it cannot be read, the voxel hull is drawn).
    void adoptLoaded(sandcore::Scene scene, const SceneSettings& settings);

    /// Starts building `settings` on a worker thread. While a build runs, the newest request
    /// waits and starts when it is done; the ones in between are dropped.
    void requestBuild(const SceneSettings& settings);
    bool building() const { return build_.valid(); } ///< a build runs or waits
    bool buildWaiting() const { return waiting_.has_value(); } ///< a newer request waits for the running build
    double buildSeconds() const;                    ///< how long the current build has run, s
    /// SPEC I5: the running build's phase, share done and cancel; null while none runs.
    const BuildProgress* buildProgress() const { return building() ? progress_.get() : nullptr; }
    /// SPEC I5: stops the running build at its next phase and drops a waiting request; the
    /// running scene stays as it is (pollBuild then reports the build cancelled).
    void cancelBuild();
    /// Called on the build thread as each later build reaches a phase (tests hold a build there).
    void setBuildPhaseListener(std::function<void(BuildPhase)> listener) { phaseListener_ = std::move(listener); }
    /// Adopts a finished build (or reports its error); nothing while none has finished.
    std::optional<BuildOutcome> pollBuild();
    /// Waits for every requested build and adopts the last; the outcome of the last, if any.
    std::optional<BuildOutcome> finishBuilds();

    /// Seed, threads and sleeping of later steps, without a rebuild (none changes a step's
    /// result but the seed).
    void applyStepSettings(const sandcore::StepSettings& step);

    /// The clock: on or off, flow speed in steps per second, and the cap of steps per frame.
    void setRunning(bool running);
    bool running() const { return clock_.running(); } ///< true while the clock makes steps
    void setStepsPerSecond(double stepsPerSecond) { clock_.setStepsPerSecond(stepsPerSecond); } ///< flow speed
    void requestSingleStep() { clock_.requestSingleStep(); } ///< one step at the next advance, even paused
    /// Feeds elapsed wall time to the clock and runs the steps that are due; returns how many ran.
    int advance(double elapsedSeconds);
    /// Runs steps now, outside the clock (scripted drawings, tests, `render --steps`).
    void runSteps(int steps);
    /// R10 reset: refills the scene; the clock keeps running or not as it was.
    void reset();
    /// Turns the hourglass over (T1); false for a sculpture or a canvas.
    bool flip();
    /// The digger (digger.hpp) on the running scene: the body is placed now and moves along the
    /// path before each later step, then is lifted out. Throws std::invalid_argument as DigDrive
    /// does. A new scene drops it.
    void startDig(sandcore::InsideMask shape, std::vector<sandcore::Int3> path, int speed);
    /// The digger started last, or null (none, or a new scene since).
    const DigDrive* dig() const { return dig_.get(); }
    /// Steps the clock may run in one frame to keep its rate when frames are slow.
    static constexpr int kMaxStepsPerFrame = 64;
    /// True when the last frame had more steps due than kMaxStepsPerFrame: the rate was not kept.
    bool rateCapped() const { return clock_.capped(); }

    /// Share (0..1) of the last step's glide that frames draw now: the clock's fraction while it
    /// runs the steps, 1 (grains at their new cells) after steps made outside it.
    float displayStepFraction() const;
    double millisecondsPerStep() const { return millisecondsPerStep_; } ///< smoothed wall time of one step, ms
    double stepsPerSecond() const { return rate_.stepsPerSecond(); }  ///< the true rate of the last second

    /// The inner flags and normals of the running scene (R12, R13), kept by every step around
    /// the cells it changed and rebuilt after any other change (edit, reset, flip, new scene),
    /// with the changes since the drawer's last clearChanges(). gradientNormals: keep the
    /// occupancy-gradient normals too (switching rebuilds).
    sandcore::SurfaceUpkeep& surfaceUpkeep(bool gradientNormals);
    /// As above, keeping what `tracking` asks for (the renderer's GrainGpuStore::trackingFor:
    /// without per-grain flags where the GPU works them out from the bits); switching rebuilds.
    sandcore::SurfaceUpkeep& surfaceUpkeep(sandcore::SurfaceTracking tracking);
    /// What the steps since the last call did: how many, the grains they moved, and the wall
    /// time of the surface upkeep after them (ms; steps before the surface was first asked for
    /// or after an edit have none).
    struct StepTally {
        std::int64_t steps = 0;
        std::int64_t moves = 0;
        double upkeepMilliseconds = 0.0;
        double stepMilliseconds = 0.0; ///< wall time of the steps themselves
    };
    StepTally takeStepTally();

    /// Changes whenever the grains change (a step, reset, edit or new scene).
    std::uint64_t contentRevision() const { return contentRevision_; }
    /// Changes whenever the cells' layout changes (a new scene, an obstacle edit).
    std::uint64_t layoutRevision() const { return layoutRevision_; }

private:
    void adopt(BuiltScene built, const SceneSettings& settings);
    void startBuild(SceneSettings settings);
    void stepOnce();

    std::unique_ptr<sandcore::Scene> scene_;
    SceneSettings loaded_;
    std::shared_ptr<const ModelDrawing> drawing_;
    std::optional<ModelToWorld> modelToWorld_;
    std::string modelNote_;
    std::future<BuiltScene> build_;
    std::shared_ptr<BuildProgress> progress_; // build_'s, shared with its thread
    std::function<void(BuildPhase)> phaseListener_;
    SceneSettings building_;                 // what build_ builds
    std::optional<SceneSettings> waiting_;   // the newest request made while build_ ran
    std::chrono::steady_clock::time_point buildStarted_;
    sandcore::SimClock clock_;
    bool lastStepOutsideClock_ = false; // the running clock's fraction would show that step undone
    double millisecondsPerStep_ = 0.0;
    StepRateMeter rate_;
    std::uint64_t contentRevision_ = 1, layoutRevision_ = 1;
    sandcore::SurfaceUpkeep upkeep_;
    std::unique_ptr<DigDrive> dig_;      // startDig; null when none
    bool upkeepStale_ = true;            // a change other than a step: rebuild before use
    StepTally tally_;                    // since takeStepTally
};

} // namespace sandglass
