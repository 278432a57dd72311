// SPDX-License-Identifier: MIT
#pragma once
// Which build of the sweep's code runs a step. On x86-64 Linux with GCC or Clang and GNU ld
// (sandcore/CMakeLists.txt, SANDCORE_SWEEP_BMI2), sandcore holds the sweep (grid_sweep.cpp,
// granular_rules.cpp) twice: built for every x86-64 CPU, and built for CPUs with BMI1 and BMI2
// (Intel since 2013, AMD since 2015), whose shifts by a variable count and and-not are one
// instruction each where the portable code needs several. The granular rules read 7-cell
// windows of bit rows with such shifts in every wake and slide, and their steps run a few
// percent faster in that build; the classic rules' steps ran a little slower in it, so they keep
// the portable code. Both builds give the same result (docs/performance.md, "The sweep built
// twice").

#include "sandcore/physics_settings.hpp"

#include <cstdint>
#include <optional>
#include <string_view>

namespace sandcore {

/// Which build of the sweep a step runs (StepSettings::sweepCode). Never changes the result.
enum class SweepCode : std::uint8_t {
    Fastest,  ///< the one measured faster for the rules: BMI2 for granular steps where possible, portable for classic
    Portable, ///< the build for every x86-64 CPU
    Bmi2,     ///< the BMI1 and BMI2 build, where this build holds it and the CPU has both; else the portable one
};

/// True when this build holds the sweep built for BMI1 and BMI2 (sandcore/CMakeLists.txt).
bool bmi2SweepBuilt();
/// True when that build is here and this CPU has BMI1 and BMI2.
bool bmi2SweepAvailable();
/// True when a step of these rules, asking for `code`, runs the BMI2 build here.
bool runsBmi2Sweep(PhysicsLevel level, SweepCode code);
/// "bmi2" or "portable": the build a step of these rules, asking for `code`, runs here.
std::string_view sweepCodeName(PhysicsLevel level, SweepCode code);
/// Sweeps the BMI2 build has run in this process (a step sweeps each grid once): shows that
/// the choice above is the one made.
std::uint64_t bmi2SweepsRun();
/// "fastest", "portable" or "bmi2": the choice itself, as the command line spells it.
std::string_view sweepCodeChoiceName(SweepCode code);
/// The choice spelt so (any case), or nothing.
std::optional<SweepCode> parseSweepCode(std::string_view name);

} // namespace sandcore
