// SPDX-License-Identifier: MIT
#include "scene/canvas_surface.hpp"

namespace sandglass {

CanvasSurface canvasSurface(const sandcore::Scene& scene, PaintTarget target, float cellSize) {
    const sandcore::GridLevel level = target == PaintTarget::Top ? sandcore::GridLevel::Upper : sandcore::GridLevel::Lower;
    const sandcore::Int3 origin = scene.gridOrigin(level), size = scene.grid(level).size();
    CanvasSurface surface;
    surface.columnsX = size.x;
    surface.columnsZ = size.z;
    surface.originX = float(origin.x) * cellSize;
    surface.originZ = float(origin.z) * cellSize;
    // The release row's top face, so the draft never hides grains waiting in that row.
    surface.y = float(target == PaintTarget::Top ? origin.y + size.y : origin.y) * cellSize;
    surface.cellSize = cellSize;
    return surface;
}

} // namespace sandglass
