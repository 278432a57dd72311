// SPDX-License-Identifier: MIT
#pragma once
// Small hand-built scenes for rule tests: a lower box under a thin upper grid, both EMPTY, run by
// the classic rules (R2) unless a test switches them.

#include "sandcore/scene.hpp"

#include <vector>

namespace fixtures {

/// A scene whose lower grid is `lower` and whose upper grid is `upperHeight` layers of the same
/// footprint, both EMPTY; cells listed in invalidLower are INVALID.
inline sandcore::Scene boxScene(sandcore::Int3 lower, int upperHeight = 1,
                                const std::vector<sandcore::Int3>& invalidLower = {}, std::uint64_t seed = 1) {
    sandcore::CellGrid lowerLayout(lower);
    for (const sandcore::Int3& c : invalidLower) lowerLayout[lowerLayout.index(c)] = sandcore::kInvalid;
    sandcore::StepSettings step;
    step.seed = seed;
    step.physics.level = sandcore::PhysicsLevel::Classic;
    return sandcore::Scene(sandcore::SceneShape{}, sandcore::CellGrid({lower.x, upperHeight, lower.z}),
                           std::move(lowerLayout), {}, step);
}

/// The ids of the grains the last step moved, in the scene's order.
inline std::vector<std::uint32_t> movedIds(const sandcore::Scene& scene) {
    std::vector<std::uint32_t> ids;
    for (const sandcore::GrainMove& move : scene.movedGrains()) ids.push_back(move.grain);
    return ids;
}

/// Places a grain at (x, y, z) of the lower grid; returns its id.
inline std::int64_t putLower(sandcore::Scene& scene, int x, int y, int z) {
    const auto& grid = scene.grid(sandcore::GridLevel::Lower);
    return scene.addGrain(sandcore::GridLevel::Lower, grid.index(x, y, z));
}

/// The content of lower-grid cell (x, y, z).
inline sandcore::CellValue lowerAt(const sandcore::Scene& scene, int x, int y, int z) {
    return scene.grid(sandcore::GridLevel::Lower).at(x, y, z);
}

} // namespace fixtures
