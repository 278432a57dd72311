// SPDX-License-Identifier: MIT
#pragma once
// Scene geometry (R10, S1): the sizes of each scene's two grids and the memory a scene will
// need, computed before anything is allocated. The scenes in scenes.hpp are built from these
// sizes, so an application's memory check and the library agree by construction.

#include "sandcore/scene.hpp"
#include "sandcore/vec3.hpp"

#include <cstdint>

namespace sandcore {

/// The three scenes of R10: what the recipes in scenes.hpp build. A Scene itself needs none of
/// them, only the SceneShape its recipe gives it.
enum class SceneKind : std::uint8_t {
    Hourglass, ///< MODE_SHAPE + SHAPE_FIX: sand drains from the upper bulb into the lower
    Sculpture, ///< MODE_SHAPE + SHAPE_LOSE: a model filled with sand collapses into a heap
    Canvas,    ///< MODE_PAINT: the user pours sand into an empty box
};

/// Height of the canvas's release grid for a canvas `width` cells wide: width / 6, at least 2 cells.
constexpr int canvasReleaseHeight(int width) { return width / 6 > 2 ? width / 6 : 2; }
/// Height of the canvas's painting box for a canvas `width` cells wide: 2/3 of width, at least 2 cells.
constexpr int canvasBoxHeight(int width) {
    const auto height = int(std::int64_t(width) * 2 / 3); // 64 bits: no overflow for any int width
    return height > 2 ? height : 2;
}

/// R10 canvas sizes; the defaults are the canvas 60 cells wide (canvasSettingsForWidth(60)).
struct CanvasSettings {
    Int3 upperSize{60, canvasReleaseHeight(60), 60}; ///< the thin release grid, cells
    Int3 lowerSize{60, canvasBoxHeight(60), 60};     ///< the painting box, cells
};

/// The canvas `width` cells wide and deep: a release grid canvasReleaseHeight(width) high over a
/// painting box canvasBoxHeight(width) high. A width below 1 gives sizes makeCanvasScene rejects.
CanvasSettings canvasSettingsForWidth(int width);

/// The two grids of a scene, cells per axis.
struct SceneGridSizes {
    Int3 upper; ///< the upper grid (upper bulb, sculpture, release layer), cells
    Int3 lower; ///< the lower grid (lower bulb, floor box, painting box), cells
};

/// Grid sizes of a scene of `kind` built from a mask of maskSize cells (R10):
/// Hourglass: an upper bound, maskSize for each grid (the split at the neck makes the two
/// grids together one mask height plus the shared row; a vessel without a neck, or empty
/// layers trimmed away, give at most maskSize each). Sculpture: exact, upper {2x, y, 2z} and
/// lower {2x, 2y, 2z}. Canvas: exact, canvasSettingsForWidth(maskSize.x); y and z are unused.
SceneGridSizes sceneGridSizes(SceneKind kind, Int3 maskSize);

/// Throws std::invalid_argument with a one-line message unless both grids of
/// sceneGridSizes(kind, maskSize) are valid grid sizes (validateGridSize); allocates nothing.
void validateSceneGridSizes(SceneKind kind, Int3 maskSize);

/// Memory a scene of `kind` built from a mask of maskSize cells will need, bytes: a generous
/// estimate of its grids, masks and grains, for refusing a scene before allocating it (S1).
/// 0 when an axis of maskSize is not positive.
std::uint64_t estimateSceneBytes(SceneKind kind, Int3 maskSize);

/// Memory the voxelizer needs for a mask of maskSize cells alone (no scene), bytes: the inside
/// flags and the robust mode's votes. 0 when an axis of maskSize is not positive.
std::uint64_t estimateMaskBytes(Int3 maskSize);

} // namespace sandcore
