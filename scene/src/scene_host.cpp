// SPDX-License-Identifier: MIT
#include "scene/scene_host.hpp"

#include <algorithm>
#include <utility>

namespace sandglass {

namespace {
using Clock = std::chrono::steady_clock;
constexpr double kRateWindowSeconds = 1.0;
} // namespace

void StepRateMeter::addFrame(double elapsedSeconds, double steps) {
    if (!(elapsedSeconds >= 0.0)) return;
    frames_.push_back({elapsedSeconds, steps});
    seconds_ += elapsedSeconds;
    steps_ += steps;
    // Keep about one second of frames, never fewer than one.
    while (frames_.size() > 1 && seconds_ - frames_.front().seconds >= kRateWindowSeconds) {
        seconds_ -= frames_.front().seconds;
        steps_ -= frames_.front().steps;
        frames_.pop_front();
    }
}

double StepRateMeter::stepsPerSecond() const { return seconds_ > 0.0 ? steps_ / seconds_ : 0.0; }

void StepRateMeter::clear() {
    frames_.clear();
    seconds_ = 0.0;
    steps_ = 0.0;
}

SceneHost::SceneHost(const SceneSettings& settings) {
    clock_.setMaxStepsPerFrame(kMaxStepsPerFrame);
    SceneSettings checked = settings;
    applySceneDefaults(checked);
    adopt(buildSceneWithReport(checked), checked);
}

SceneHost::SceneHost(sandcore::Scene scene, const SceneSettings& settings) {
    clock_.setMaxStepsPerFrame(kMaxStepsPerFrame);
    adoptLoaded(std::move(scene), settings);
}

SceneHost::~SceneHost() {
    // A build still running holds no reference to this host; stop it and wait so its thread ends.
    cancelBuild();
    if (build_.valid()) build_.wait();
}

sandcore::Scene& SceneHost::editScene() {
    ++contentRevision_;
    upkeepStale_ = true;
    return *scene_;
}

sandcore::Scene& SceneHost::editLayout() {
    ++layoutRevision_;
    return editScene();
}

void SceneHost::adopt(BuiltScene built, const SceneSettings& settings) {
    scene_ = std::make_unique<sandcore::Scene>(std::move(built.scene));
    dig_.reset(); // its body stood in the scene that went
    drawing_ = std::move(built.drawing);
    modelToWorld_ = built.modelToWorld;
    modelNote_ = built.note;
    loaded_ = settings;
    lastStepOutsideClock_ = false;
    rate_.clear();
    ++contentRevision_;
    ++layoutRevision_;
    upkeepStale_ = true;
}

namespace {

// The drawing of the model a loaded scene was built from: the build is made again and its
// drawing kept only when its grids are the loaded scene's (turned over, the grids swap).
std::shared_ptr<const ModelDrawing> drawingOfLoaded(const sandcore::Scene& loaded, const SceneSettings& settings) {
    if (settings.request.modelPath.empty()) return nullptr;
    try {
        const BuiltScene again = buildSceneWithReport(settings);
        const sandcore::GridLevel upper = loaded.flipped() ? sandcore::GridLevel::Lower : sandcore::GridLevel::Upper;
        const sandcore::GridLevel lower = loaded.flipped() ? sandcore::GridLevel::Upper : sandcore::GridLevel::Lower;
        const bool same = again.scene.grid(sandcore::GridLevel::Upper).size() == loaded.grid(upper).size() &&
                          again.scene.grid(sandcore::GridLevel::Lower).size() == loaded.grid(lower).size();
        return same ? again.drawing : nullptr;
    } catch (const std::exception&) {
        return nullptr; // the model file is gone or broken: the loaded scene still runs, with its voxel hull
    }
}

} // namespace

void SceneHost::adoptLoaded(sandcore::Scene scene, const SceneSettings& settings) {
    BuiltScene loaded(std::move(scene));
    loaded.drawing = drawingOfLoaded(loaded.scene, settings);
    adopt(std::move(loaded), settings);
}

void SceneHost::startBuild(SceneSettings settings) {
    building_ = settings;
    buildStarted_ = Clock::now();
    progress_ = std::make_shared<BuildProgress>(phaseListener_);
    // Scenes are built off the main thread so the window stays responsive.
    build_ = std::async(std::launch::async, [settings = std::move(settings), progress = progress_] {
        return buildSceneWithReport(settings, progress.get());
    });
}

void SceneHost::cancelBuild() {
    waiting_.reset();
    if (build_.valid()) progress_->cancel();
}

void SceneHost::requestBuild(const SceneSettings& settings) {
    if (build_.valid())
        waiting_ = settings; // the last request wins
    else
        startBuild(settings);
}

double SceneHost::buildSeconds() const {
    return build_.valid() ? std::chrono::duration<double>(Clock::now() - buildStarted_).count() : 0.0;
}

std::optional<BuildOutcome> SceneHost::pollBuild() {
    if (!build_.valid() || build_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
    BuildOutcome outcome;
    try {
        BuiltScene built = build_.get();
        if (waiting_) {
            // Newer settings arrived while this one was built: it is stale, build those instead.
            startBuild(*std::exchange(waiting_, std::nullopt));
            return std::nullopt;
        }
        const std::string note = built.note;
        adopt(std::move(built), building_);
        outcome.adopted = true;
        outcome.message = std::string("built ") + sceneKindName(kind()) + ", " +
                          std::to_string(scene_->grainCount()) + " grains";
        if (!note.empty()) outcome.message += "; " + note; // W5: what was done instead of an hourglass
    } catch (const std::exception& error) {
        if (waiting_) {
            startBuild(*std::exchange(waiting_, std::nullopt)); // its error no longer matters either
            return std::nullopt;
        }
        // The running scene stays as it was.
        outcome.cancelled = dynamic_cast<const BuildCancelled*>(&error) != nullptr;
        outcome.message = outcome.cancelled ? "build cancelled; the running scene is kept" : error.what();
    }
    return outcome;
}

std::optional<BuildOutcome> SceneHost::finishBuilds() {
    std::optional<BuildOutcome> last;
    while (build_.valid()) {
        build_.wait();
        if (auto outcome = pollBuild()) last = outcome;
    }
    return last;
}

void SceneHost::applyStepSettings(const sandcore::StepSettings& step) {
    scene_->setSeed(step.seed);
    scene_->setThreads(std::clamp(step.threads, kThreadsRange.min, kThreadsRange.max));
    scene_->setSleeping(step.sleeping);
    // The rules change only when asked: switching wakes every grain and stops every fall.
    if (!(step.physics == scene_->settings().physics)) scene_->setPhysics(step.physics);
    loaded_.step = scene_->settings();
}

void SceneHost::setRunning(bool running) {
    if (running != clock_.running()) rate_.clear();
    clock_.setRunning(running);
}

int SceneHost::advance(double elapsedSeconds) {
    const double fractionBefore = clock_.stepFraction();
    const int due = clock_.advance(elapsedSeconds);
    rate_.addFrame(elapsedSeconds, double(due) + clock_.stepFraction() - fractionBefore);
    if (due == 0) return 0;
    const auto start = Clock::now();
    const double upkeepBefore = tally_.upkeepMilliseconds;
    for (int i = 0; i < due; ++i) stepOnce();
    const double upkeep = tally_.upkeepMilliseconds - upkeepBefore;
    const double milliseconds = (std::chrono::duration<double, std::milli>(Clock::now() - start).count() - upkeep) / due;
    millisecondsPerStep_ = millisecondsPerStep_ == 0.0 ? milliseconds : 0.9 * millisecondsPerStep_ + 0.1 * milliseconds;
    // Paused, the clock's fraction stands still (often at 0): a single step would not show.
    lastStepOutsideClock_ = !clock_.running();
    ++contentRevision_;
    return due;
}

void SceneHost::runSteps(int steps) {
    if (steps <= 0) return;
    for (int i = 0; i < steps; ++i) stepOnce();
    lastStepOutsideClock_ = true;
    ++contentRevision_;
}

void SceneHost::reset() {
    scene_->reset();
    lastStepOutsideClock_ = false;
    ++contentRevision_;
    upkeepStale_ = true;
}

bool SceneHost::flip() {
    if (!scene_->flip()) return false;
    lastStepOutsideClock_ = true; // the grains sit in their new cells; the view turns instead
    ++contentRevision_;
    upkeepStale_ = true;
    ++layoutRevision_;
    return true;
}

// One step, then the upkeep around what it moved (timed apart: it is the drawing's cost).
void SceneHost::stepOnce() {
    // The upkeep reads the last step's places from the scene's list until they are drawn; a step
    // before that overwrites the list, so they are copied first.
    if (!upkeepStale_ && upkeep_.movedPlaceCount() != 0) {
        const auto start = Clock::now();
        upkeep_.retainMoves();
        tally_.upkeepMilliseconds += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    }
    if (dig_ && !dig_->done()) {
        dig_->beforeStep(editScene()); // pushed grains moved outside the step: the upkeep rebuilds
        if (dig_->done()) scene_->removeBody(dig_->body());
    }
    const auto stepStart = Clock::now();
    scene_->step();
    tally_.stepMilliseconds += std::chrono::duration<double, std::milli>(Clock::now() - stepStart).count();
    ++tally_.steps;
    tally_.moves += scene_->counters().movesLastStep;
    if (upkeepStale_) return; // rebuilt when next asked for
    const auto start = Clock::now();
    upkeep_.update(*scene_);
    tally_.upkeepMilliseconds += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

sandcore::SurfaceUpkeep& SceneHost::surfaceUpkeep(bool gradientNormals) {
    return surfaceUpkeep(sandcore::SurfaceTracking{true, gradientNormals, true});
}

sandcore::SurfaceUpkeep& SceneHost::surfaceUpkeep(sandcore::SurfaceTracking tracking) {
    if (upkeepStale_ || upkeep_.kept() != tracking) {
        upkeep_.setTracking(tracking);
        upkeep_.rebuild(*scene_);
        upkeepStale_ = false;
    }
    return upkeep_;
}

SceneHost::StepTally SceneHost::takeStepTally() {
    const StepTally taken = tally_;
    tally_ = {};
    return taken;
}

float SceneHost::displayStepFraction() const {
    return lastStepOutsideClock_ ? 1.0f : float(clock_.stepFraction());
}

void SceneHost::startDig(sandcore::InsideMask shape, std::vector<sandcore::Int3> path, int speed) {
    dig_.reset();
    dig_ = std::make_unique<DigDrive>(editScene(), std::move(shape), std::move(path), speed);
}

} // namespace sandglass
