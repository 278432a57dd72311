// SPDX-License-Identifier: MIT
#pragma once
// SPEC I5: how far a scene build has come, and the user's wish to stop it. The build thread
// passes checkpoints between its phases; the window reads the phase and asks to cancel from its
// own thread. A build stops only at a checkpoint, so a long phase runs to its end first.

#include <atomic>
#include <exception>
#include <functional>
#include <utility>

namespace sandglass {

/// The phases of a build in the order they come; procedural shapes and the canvas go straight to Filling.
enum class BuildPhase {
    Loading,          ///< reading the model file and splitting it into parts
    Voxelizing,       ///< turning the model into cells
    FindingSandSpace, ///< the hourglass's bulbs and neck, or the sculpture's sand and obstacles
    Filling,          ///< cleaning the cells and building the scene with its sand
    Done,             ///< the scene is ready
};

/// What the window says a phase does: "loading the model", "voxelizing", ...
const char* buildPhaseName(BuildPhase phase);
/// The share (0..1) of a model build done when the phase starts; coarse, from the phases' usual lengths.
float buildShareAtStart(BuildPhase phase);

/// Thrown at a checkpoint of a build that was asked to stop.
class BuildCancelled : public std::exception {
public:
    const char* what() const noexcept override { return "cancelled"; } ///< always "cancelled"
};

/// The progress of one build, shared by the thread that builds and the one that watches.
class BuildProgress {
public:
    /// `onPhase` (may be empty) is called on the building thread as each phase is reached, before
    /// the cancel is looked at (tests hold a build at a phase through it).
    explicit BuildProgress(std::function<void(BuildPhase)> onPhase = {}) : onPhase_(std::move(onPhase)) {}

    /// Called by the build between phases: records `phase`, then throws BuildCancelled when
    /// cancel() was asked.
    void checkpoint(BuildPhase phase);
    /// Asks the build to stop at its next checkpoint; any thread.
    void cancel() { cancelled_ = true; }
    bool cancelRequested() const { return cancelled_; } ///< cancel() was called
    BuildPhase phase() const { return phase_; }          ///< the last phase reached
    float shareDone() const { return buildShareAtStart(phase_); } ///< 0..1, by phase

private:
    std::function<void(BuildPhase)> onPhase_;
    std::atomic<BuildPhase> phase_{BuildPhase::Loading};
    std::atomic<bool> cancelled_{false};
};

/// progress->checkpoint(phase), where a build is watched at all (progress may be null).
inline void checkpoint(BuildProgress* progress, BuildPhase phase) {
    if (progress) progress->checkpoint(phase);
}

} // namespace sandglass
