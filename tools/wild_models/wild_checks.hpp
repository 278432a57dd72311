// SPDX-License-Identifier: MIT
#pragma once
// SPEC W1-W5: what a model from the wild must give when loaded with no options, checked against
// the generator's ground truth. Shared by the property tests and the corpus report (wild_report).

#include "wild_models/wild_models.hpp"

#include "sandcore/physics_settings.hpp"

#include <cstdint>
#include <filesystem>
#include <string>

namespace sandglass::wild {

/// How one model fared.
struct ModelCheck {
    bool loaded = false;            ///< the file built a scene
    std::string failure;            ///< the first property that failed, one line; empty when all held
    bool grainOutside = false;      ///< W3 broken: a grain was found outside the glass (or body) at some check
    std::int64_t grainsLeftAbove = -1; ///< after the drain, grains that stayed above the neck; -1: not drained
    std::string note;               ///< the program's note (W5: no hourglass; W4: parts too thin), if it gave one
    std::int64_t grains = 0;        ///< grains at the start
    double upperFillShare = 0.0;    ///< grains in the upper bulb / the upper bulb's volume in cells
    double loadMilliseconds = 0.0;  ///< whole build of the scene from the file, ms
    bool passed() const { return loaded && failure.empty(); } ///< every property held
};

/// What to check.
struct CheckSettings {
    int resolution = 64;   ///< cells along the model's largest extent
    bool drain = true;     ///< step until the sand has run through (hourglass) or collapsed (sculpture)
    /// Give up draining after this many steps, or after twice the steps the granular neck's
    /// Beverloo rate needs for all the sand if that is more (a one-cell neck passes 0.065 grains
    /// a step).
    int maxSteps = 200000;
    int checkEvery = 10;   ///< look at every grain after this many steps
    sandcore::PhysicsLevel physics = sandcore::PhysicsSettings{}.level; ///< the rules that drain it
};

/// Writes the model to `file` (.obj or .stl), builds it as the kind of scene its class is (an
/// hourglass; a funnel as an hourglass that should say it is none; a character or keyboard as a
/// sculpture) with no options but the resolution, and checks it:
/// - hourglasses: the up axis found (its sign too with modelled sand), every grain inside the
///   glass at the start and after every checkEvery steps, at least 40% of the upper bulb's volume
///   as sand in the upper bulb, and every grain in the lower bulb at the end;
/// - a funnel: a note, and every grain inside the funnel at the start;
/// - a character: stood up along its true up axis, every sand cell inside its body;
/// - a keyboard: where its keys are thinner than a cell, a clear refusal that names a resolution,
///   or sand in the keys that hold cell centres with a note that names one; at that resolution
///   (or the one asked for) every sand cell in a key.
ModelCheck checkModel(const WildModel& model, const std::filesystem::path& file, const CheckSettings& settings);

} // namespace sandglass::wild
