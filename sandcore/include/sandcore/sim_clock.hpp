// SPDX-License-Identifier: MIT
#pragma once
// R9: the fixed-rate simulation clock, driven by an accumulator on the wall clock so the flow
// speed does not depend on the frame rate (the thesis's eventSteps, in steps per second).

namespace sandcore {

/// How fast the simulation runs against the wall clock.
struct ClockSettings {
    double stepsPerSecond = 30.0; ///< flow speed, steps per second of wall time (> 0)
    int maxStepsPerFrame = 4;     ///< at most this many steps per frame; a slow frame drops the rest
};

/// Turns wall time into simulation steps at a fixed rate (R9); paused at first.
class SimClock {
public:
    /// A paused clock with these settings.
    explicit SimClock(ClockSettings settings = {}) : settings_(settings) {}

    /// Adds elapsed wall time (seconds) and returns how many steps are due now.
    int advance(double elapsedSeconds);
    /// Fraction of the current step interval that has passed, in [0, 1): drives smooth motion.
    double stepFraction() const;

    bool running() const { return running_; }        ///< true while steps are produced
    void setRunning(bool running) { running_ = running; } ///< pause (false) or resume (true)
    void requestSingleStep() { singleStepPending_ = true; } ///< one step at the next advance, even when paused
    double stepsPerSecond() const { return settings_.stepsPerSecond; } ///< current rate
    /// Changes the rate; non-positive or non-finite rates are ignored.
    void setStepsPerSecond(double stepsPerSecond);
    int maxStepsPerFrame() const { return settings_.maxStepsPerFrame; } ///< the cap of steps per advance
    /// Changes the cap of steps per advance (at least 1).
    void setMaxStepsPerFrame(int steps) { settings_.maxStepsPerFrame = steps < 1 ? 1 : steps; }
    /// True when the last advance had more steps due than the cap and dropped the rest, so the
    /// simulation ran slower than its rate.
    bool capped() const { return capped_; }

private:
    ClockSettings settings_;
    double accumulated_ = 0.0; // seconds not yet turned into steps
    bool running_ = false;
    bool singleStepPending_ = false;
    bool capped_ = false;
};

} // namespace sandcore
