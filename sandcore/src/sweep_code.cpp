// SPDX-License-Identifier: MIT
#include "sandcore/sweep_code.hpp"

#include "grid_sweep.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>

namespace sandcore {

bool bmi2SweepBuilt() {
#ifdef SANDCORE_SWEEP_BMI2
    return true;
#else
    return false;
#endif
}

bool bmi2SweepAvailable() {
#ifdef SANDCORE_SWEEP_BMI2
    static const bool available = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
    }();
    return available;
#else
    return false;
#endif
}

namespace {
std::atomic<std::uint64_t> bmi2Sweeps{0};
} // namespace

void countBmi2Sweep() { bmi2Sweeps.fetch_add(1, std::memory_order_relaxed); }

std::uint64_t bmi2SweepsRun() { return bmi2Sweeps.load(std::memory_order_relaxed); }

bool runsBmi2Sweep(PhysicsLevel level, SweepCode code) {
    if (!bmi2SweepAvailable()) return false;
    switch (code) {
    case SweepCode::Fastest: return level == PhysicsLevel::Granular;
    case SweepCode::Portable: return false;
    case SweepCode::Bmi2: return true;
    }
    return false;
}

std::string_view sweepCodeName(PhysicsLevel level, SweepCode code) {
    return runsBmi2Sweep(level, code) ? "bmi2" : "portable";
}

std::string_view sweepCodeChoiceName(SweepCode code) {
    switch (code) {
    case SweepCode::Fastest: return "fastest";
    case SweepCode::Portable: return "portable";
    case SweepCode::Bmi2: return "bmi2";
    }
    return "fastest";
}

std::optional<SweepCode> parseSweepCode(std::string_view name) {
    for (SweepCode code : {SweepCode::Fastest, SweepCode::Portable, SweepCode::Bmi2}) {
        const std::string_view known = sweepCodeChoiceName(code);
        if (name.size() == known.size() &&
            std::equal(name.begin(), name.end(), known.begin(), [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; }))
            return code;
    }
    return std::nullopt;
}

} // namespace sandcore
