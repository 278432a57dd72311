// SPDX-License-Identifier: MIT
#include "sandcore/physics_settings.hpp"

#include <stdexcept>

namespace sandcore {

double gravityFromCellSize(double cellMetres, double stepsPerSecond) {
    if (!(cellMetres > 0) || !(stepsPerSecond > 0))
        throw std::invalid_argument("cell size and step rate must be positive");
    return 9.81 / (cellMetres * stepsPerSecond * stepsPerSecond);
}

void validatePhysics(const PhysicsSettings& physics) {
    if (!(physics.reposeDegrees >= kMinReposeDegrees && physics.reposeDegrees <= kMaxReposeDegrees))
        throw std::invalid_argument("repose angle must lie in [20, 45] degrees");
    if (!(physics.gravity >= kMinGravity && physics.gravity <= kMaxGravity))
        throw std::invalid_argument("gravity must lie in [0.001, 64] cells per step squared");
}

std::string_view physicsLevelName(PhysicsLevel level) { return level == PhysicsLevel::Granular ? "granular" : "classic"; }

std::optional<PhysicsLevel> parsePhysicsLevel(std::string_view name) {
    if (name == "classic") return PhysicsLevel::Classic;
    if (name == "granular") return PhysicsLevel::Granular;
    return std::nullopt;
}

} // namespace sandcore
