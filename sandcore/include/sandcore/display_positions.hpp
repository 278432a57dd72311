// SPDX-License-Identifier: MIT
#pragma once
// R8: where a grain is drawn. A grain glides from the cell it left to the cell it entered during
// the step after its move; the position is computed from (from, to, fraction) every time, never
// accumulated, so a resting grain sits exactly on its cell's display point forever.

#include "sandcore/scene.hpp"
#include "sandcore/vec3.hpp"

#include <span>

namespace sandcore {

/// How grains are placed in world space.
struct DisplaySettings {
    float cellSize = 1.0f; ///< world units per cell (the thesis's mSize); scales display only
    float jitter = 0.5f;   ///< 0..1: each grain sits up to +-jitter*cellSize/2 per axis off its cell centre
};

/// A grain's fixed offset inside its cell, in cells (each component in [-jitter/2, jitter/2]).
Vec3 jitterOffset(std::uint32_t identity, float jitter);

/// The display point of a grain at rest in a cell: (origin + cell + 1/2 + jitter) * cellSize.
Vec3 cellDisplayPoint(const Scene& scene, GridLevel level, std::uint32_t cell, std::uint32_t identity,
                      const DisplaySettings& display);

/// Where grain `id` is drawn when `stepFraction` (0..1) of the current step interval has passed:
/// on its way from its previous cell if it moved in the last step, else at its display point.
Vec3 grainDisplayPosition(const Scene& scene, std::uint32_t id, float stepFraction, const DisplaySettings& display);

/// grainDisplayPosition for every grain, written to out (out.size() >= grainCount()).
void writeDisplayPositions(const Scene& scene, float stepFraction, const DisplaySettings& display,
                           std::span<Vec3> out);

/// The world-space box that holds both grids, in world units: min corner and max corner.
void sceneBounds(const Scene& scene, const DisplaySettings& display, Vec3& minCorner, Vec3& maxCorner);

} // namespace sandcore
