// SPDX-License-Identifier: MIT
#pragma once
// SPEC PH1: which rules move the sand. `classic` is the thesis's (R2: fall one cell, else slip to
// a random empty successor); `granular` adds a tunable, round angle of repose (PH2), gravity
// with multi-cell falls (PH3) and, in an hourglass, a discharge at Beverloo's rate (PH4).

#include <cstdint>
#include <optional>
#include <string_view>

namespace sandcore {

/// The two physics levels of PH1.
enum class PhysicsLevel : std::uint8_t {
    Classic = 0,  ///< the thesis's rules; results and recorded hashes as in the first release
    Granular = 1, ///< repose angle, gravity and the neck-flow discharge
};

/// Smallest and largest repose angle the granular rules accept, degrees (PH2).
inline constexpr float kMinReposeDegrees = 20.0f;
inline constexpr float kMaxReposeDegrees = 45.0f; ///< see kMinReposeDegrees
/// Smallest and largest gravity, cells per step squared (PH3): below the smallest, 16.16 fixed
/// point would round a grain's speed gain towards nothing.
inline constexpr float kMinGravity = 0.001f;
inline constexpr float kMaxGravity = 64.0f; ///< see kMinGravity

/// Settings of the granular level; classic ignores everything but `level`.
struct PhysicsSettings {
    PhysicsLevel level = PhysicsLevel::Granular; ///< which rules run; granular looks like sand (PH1)
    float reposeDegrees = 33.0f; ///< granular: angle of repose of a poured cone, degrees in [20, 45]
    /// granular: gravity in cells per step squared, in [0.001, 64]. The default is slow motion
    /// (1 mm cells at 700 steps/s; a fall of 100 cells takes 100 steps, as in classic) so that the
    /// sand around the neck, one grain per cell and step, keeps up with Beverloo's rate for the
    /// default necks; see gravityFromCellSize.
    float gravity = 0.02f;
    friend bool operator==(const PhysicsSettings&, const PhysicsSettings&) = default; ///< same level and values
};

/// g in cells per step squared for cells of `cellMetres` metres at `stepsPerSecond`:
/// 9.81 / (cellMetres * stepsPerSecond^2) (1 mm cells at 60 steps/s give about 2.7).
double gravityFromCellSize(double cellMetres, double stepsPerSecond);

/// Throws std::invalid_argument with a one-line message unless the settings are usable.
void validatePhysics(const PhysicsSettings& physics);

/// "classic" or "granular".
std::string_view physicsLevelName(PhysicsLevel level);
/// The level named "classic" or "granular"; nothing for any other text.
std::optional<PhysicsLevel> parsePhysicsLevel(std::string_view name);

} // namespace sandcore
