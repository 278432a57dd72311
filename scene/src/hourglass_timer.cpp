// SPDX-License-Identifier: MIT
#include "scene/hourglass_timer.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

namespace sandglass {

namespace {
// Steps the scene itself until a step moves nothing (at least one step: a scene that has not
// stepped yet, or was just turned, is not settled).
std::int64_t runUntilSettled(sandcore::Scene& scene, std::int64_t maxSteps) {
    std::int64_t steps = 0;
    while (steps < maxSteps) {
        scene.step();
        ++steps;
        if (scene.settled()) break;
    }
    return steps;
}
} // namespace

std::int64_t predictDrainSteps(const sandcore::Scene& scene, std::int64_t maxSteps) {
    sandcore::Scene copy = scene.clone();
    return runUntilSettled(copy, maxSteps);
}

HourglassTimer::~HourglassTimer() {
    if (prediction_.valid()) prediction_.wait();
}

void HourglassTimer::predict(const sandcore::Scene& scene) {
    if (prediction_.valid()) prediction_.wait(); // an older question no longer matters
    predictedFrom_ = scene.counters().stepsDone;
    // The copy is made here, on the caller's thread; only the steps run on the worker.
    auto copy = std::make_shared<sandcore::Scene>(scene.clone());
    prediction_ = std::async(std::launch::async, [copy] { return runUntilSettled(*copy, 10'000'000); });
    phase_ = Phase::Predicting;
}

void HourglassTimer::start(const sandcore::Scene& scene, double durationSeconds) {
    if (!(durationSeconds > 0.0) || !std::isfinite(durationSeconds))
        throw std::invalid_argument("the timer's duration must be a positive number of seconds");
    duration_ = durationSeconds;
    startStep_ = scene.counters().stepsDone;
    turnedSinceStart_ = false;
    stepsPerSecond_ = 0.0;
    predict(scene);
}

void HourglassTimer::sceneTurned(const sandcore::Scene& scene) {
    if (phase_ == Phase::Off) return;
    turnedSinceStart_ = true;
    predict(scene);
}

void HourglassTimer::stop() {
    if (prediction_.valid()) prediction_.wait();
    prediction_ = {};
    phase_ = Phase::Off;
}

std::optional<double> HourglassTimer::update(const sandcore::Scene& scene) {
    if (phase_ == Phase::Predicting && prediction_.valid() &&
        prediction_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        const std::int64_t steps = prediction_.get();
        endStep_ = predictedFrom_ + std::uint64_t(steps);
        if (!turnedSinceStart_) {
            // The first prediction sets the rate; after a turn the rate stays and the end moves.
            drainSteps_ = steps;
            stepsPerSecond_ = double(steps) / duration_;
        }
        phase_ = Phase::Running;
        return stepsPerSecond_;
    }
    if (phase_ == Phase::Running && scene.counters().stepsDone >= endStep_) phase_ = Phase::Finished;
    return std::nullopt;
}

double HourglassTimer::elapsedSeconds(const sandcore::Scene& scene) const {
    if (stepsPerSecond_ <= 0.0) return 0.0;
    return double(scene.counters().stepsDone - startStep_) / stepsPerSecond_;
}

double HourglassTimer::remainingSeconds(const sandcore::Scene& scene) const {
    if (phase_ == Phase::Predicting) return duration_;
    if (stepsPerSecond_ <= 0.0 || scene.counters().stepsDone >= endStep_) return 0.0;
    return double(endStep_ - scene.counters().stepsDone) / stepsPerSecond_;
}

} // namespace sandglass
