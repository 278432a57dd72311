// SPDX-License-Identifier: MIT
#pragma once
// The hourglass as a timer (T2): the steps a full drain takes are predicted by running a copy
// of the same scene (same seed, so the same steps) until it settles, on a worker thread; the
// step rate is then set so that the drain takes the chosen duration. After a turn the remaining
// time is that of the sand now on top, predicted again the same way.

#include "sandcore/scene.hpp"

#include <cstdint>
#include <future>
#include <optional>

namespace sandglass {

/// Steps until a copy of `scene` settles (a step moves nothing), at most maxSteps; the scene
/// itself is not touched. Deterministic: the same scene and seed always give the same count.
std::int64_t predictDrainSteps(const sandcore::Scene& scene, std::int64_t maxSteps = 10'000'000);

class HourglassTimer {
public:
    enum class Phase {
        Off,        ///< no timer set
        Predicting, ///< the drain is being measured on a worker thread
        Running,    ///< the rate is set; the sand runs
        Finished,   ///< the sand has run out: the end is signalled
    };

    HourglassTimer() = default;
    ~HourglassTimer();
    HourglassTimer(const HourglassTimer&) = delete;
    HourglassTimer& operator=(const HourglassTimer&) = delete;

    /// Sets a timer of `durationSeconds` (> 0) on the scene as it is now: the drain from here is
    /// predicted on a worker thread. Throws std::invalid_argument for a non-positive duration.
    void start(const sandcore::Scene& scene, double durationSeconds);
    /// The hourglass was turned: the remaining time becomes that of the sand now on top.
    void sceneTurned(const sandcore::Scene& scene);
    /// Stops the timer (the rate stays as it is).
    void stop();

    /// Once per frame: takes a finished prediction and notices the end. Returns the step rate
    /// to set when a new prediction arrived (steps per second), else nothing.
    std::optional<double> update(const sandcore::Scene& scene);

    Phase phase() const { return phase_; }                      ///< where the timer stands
    double durationSeconds() const { return duration_; }        ///< the duration asked for, s
    double stepsPerSecond() const { return stepsPerSecond_; }   ///< the rate the timer set (0 before)
    std::int64_t drainSteps() const { return drainSteps_; }     ///< steps of the drain predicted at start
    /// Seconds of sand run since the start, at the set rate (simulated time, so a slow frame
    /// does not make the timer lie).
    double elapsedSeconds(const sandcore::Scene& scene) const;
    /// Seconds until the sand on top has run out, at the set rate.
    double remainingSeconds(const sandcore::Scene& scene) const;

private:
    void predict(const sandcore::Scene& scene);

    Phase phase_ = Phase::Off;
    double duration_ = 0.0;
    double stepsPerSecond_ = 0.0;
    std::int64_t drainSteps_ = 0;
    std::uint64_t startStep_ = 0;   // the scene's step counter when the timer started
    std::uint64_t predictedFrom_ = 0; // the step counter the running prediction started from
    std::uint64_t endStep_ = 0;     // the step at which the sand on top has run out
    bool turnedSinceStart_ = false;
    std::future<std::int64_t> prediction_;
};

} // namespace sandglass
