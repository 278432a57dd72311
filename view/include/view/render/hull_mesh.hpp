// SPDX-License-Identifier: MIT
#pragma once
// The vessel drawn as faint glass (SPEC V6): every face between a cell sand may fill and a cell
// it may not (INVALID or, for the hourglass, outside the grids), with a smoothed normal so the
// voxel staircase shades like a curved wall. The canvas and the sculpture get box outlines.

#include "sandcore/scene.hpp"
#include "sandcore/scene_geometry.hpp"

#include <vector>

namespace sandglass {

/// One hull vertex: world position and unit normal pointing into the wall.
struct HullVertex {
    float x, y, z;    ///< world units
    float nx, ny, nz; ///< unit normal, pointing from the sand side into the wall
};

struct HullMesh {
    std::vector<HullVertex> triangles;  ///< 6 vertices per cell face
    std::vector<HullVertex> lines;      ///< 2 vertices per outline edge (normal unused)
};

/// The hull of a scene of `kind` at cellSize world units per cell: the vessel's wall for an
/// hourglass, with the outline of the floor box (sculpture) or of both boxes (canvas).
HullMesh buildHullMesh(const sandcore::Scene& scene, sandcore::SceneKind kind, float cellSize);

} // namespace sandglass
