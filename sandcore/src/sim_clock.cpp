// SPDX-License-Identifier: MIT
#include "sandcore/sim_clock.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sandcore {

int SimClock::advance(double elapsedSeconds) {
    int steps = 0;
    capped_ = false;
    if (singleStepPending_) {
        singleStepPending_ = false;
        steps = 1;
    }
    if (!running_ || !(elapsedSeconds > 0.0) || !std::isfinite(elapsedSeconds)) return steps;
    const double period = 1.0 / settings_.stepsPerSecond;
    accumulated_ += elapsedSeconds;
    const auto due = std::int64_t(accumulated_ / period);
    accumulated_ -= double(due) * period;
    // A frame that took too long drops steps instead of trying to catch up (no spiral of death).
    capped_ = due > settings_.maxStepsPerFrame;
    return steps + int(std::min<std::int64_t>(due, settings_.maxStepsPerFrame));
}

double SimClock::stepFraction() const {
    return std::clamp(accumulated_ * settings_.stepsPerSecond, 0.0, std::nextafter(1.0, 0.0));
}

void SimClock::setStepsPerSecond(double stepsPerSecond) {
    if (!(stepsPerSecond > 0.0) || !std::isfinite(stepsPerSecond)) return;
    const double fraction = stepFraction();
    settings_.stepsPerSecond = stepsPerSecond;
    accumulated_ = fraction / stepsPerSecond; // keep the glide where it is
}

} // namespace sandcore
