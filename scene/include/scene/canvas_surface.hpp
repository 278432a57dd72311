// SPDX-License-Identifier: MIT
#pragma once
// Where the canvas lies in the world (SPEC P2, P5): the rectangle the mouse points at, shared
// by picking (P1) and the draft image, so both use the renderer's cell-to-world transform.

#include "scene/sand_painter.hpp"

#include "sandcore/scene.hpp"

namespace sandglass {

/// A horizontal rectangle of columns x 0..columnsX, z 0..columnsZ at height y.
struct CanvasSurface {
    int columnsX = 0;      ///< columns along +x
    int columnsZ = 0;      ///< columns along +z
    float originX = 0.0f;  ///< world x of column 0's left edge, world units
    float originZ = 0.0f;  ///< world z of column 0's near edge, world units
    float y = 0.0f;        ///< world height of the rectangle, world units
    float cellSize = 1.0f; ///< world units per column
    friend bool operator==(const CanvasSurface&, const CanvasSurface&) = default;
};

/// PAINT_TOP: the top face of the upper grid's top row; PAINT_BOTTOM: the lower grid's floor.
CanvasSurface canvasSurface(const sandcore::Scene& scene, PaintTarget target, float cellSize);

} // namespace sandglass
