// SPDX-License-Identifier: MIT
#pragma once
// SPEC S2, S5, S6 (thesis §3.4 "Zellen innerhalb der Form"): which cells of a grid lie inside a
// triangle mesh. A cell is inside when its centre is; rays along the axes through rows of cell
// centres are crossed with the triangles, decided by exact integer predicates with a symbolic
// perturbation of the ray, so a ray through an edge or vertex is counted exactly once.

#include "sandcore/inside_mask.hpp"
#include "sandcore/triangle_mesh.hpp"

#include <array>
#include <cstdint>

namespace sandcore {

/// Largest accepted resolution, cells: keeps the exact predicates within 64-bit integers.
inline constexpr int kMaxVoxelResolution = 8192;

/// How a mesh becomes an inside mask.
struct VoxelizeSettings {
    int resolution = 64;  ///< cells along the model's largest extent, 1..kMaxVoxelResolution
    bool stretch = false; ///< thesis's per-axis scaling: every axis gets `resolution` cells (aspect not kept)
    /// S5: majority vote of the winding number along x, y and z, counted from both ends of each
    /// ray, with faces oriented outward first: open meshes get a sensible solid and overlapping
    /// closed parts their union.
    bool robust = false;
    int threads = 1;      ///< threads that share the rows; the result does not depend on it
    bool binning = true;  ///< false tests every row against every triangle (only to measure what binning saves)
};

/// Where the model sits in the grid: grid = (model - modelMin) * scale + padding, in cells.
struct VoxelPlacement {
    Int3 size;                         ///< grid cells per axis
    std::array<double, 3> modelMin{};  ///< the model's bounds minimum, model units
    std::array<double, 3> scale{};     ///< cells per model unit, per axis
    std::array<double, 3> padding{};   ///< cells between the grid's low face and the model, per axis
};

/// A voxelized model with what the CLI and GUI report about it (C2).
struct VoxelizeResult {
    InsideMask mask;                ///< inside cells
    VoxelPlacement placement;       ///< how the model was scaled and shifted
    MeshClosedness closedness;      ///< boundary edges after welding (S5)
    double meshVolume = 0.0;        ///< |sum of signed tetrahedra| of the outward-oriented mesh, cell volumes
    /// The mesh volume means something: the mesh is closed and its faces could be oriented
    /// consistently (a surface with inconsistent orientation has no signed volume to compare).
    bool volumeMeaningful = false;
    std::int64_t cellsInside = 0;   ///< inside cells = voxel volume, cell volumes
    /// (cellsInside - meshVolume) / meshVolume; 0 when the mesh volume is 0 or not meaningful.
    double relativeError() const;
};

/// The grid size and placement voxelize() would use; allocates nothing large, so callers can
/// check memory first. Throws std::invalid_argument for a resolution out of range, a mesh
/// without triangles, a non-finite coordinate, zero extent on an axis, or a grid over 2^31 cells.
VoxelPlacement placeInGrid(const TriangleMesh& mesh, const VoxelizeSettings& settings);

/// Scales the mesh into a grid (placeInGrid) and marks the cells whose centres lie inside it.
VoxelizeResult voxelize(const TriangleMesh& mesh, const VoxelizeSettings& settings);

/// The inside test alone, for a mesh already in grid coordinates (cell (i,j,k) spans [i, i+1)
/// and so on); resolution and stretch are ignored. Coordinates must lie within
/// +-2 * kMaxVoxelResolution cells. A centre exactly on the surface counts as inside when moving
/// it by an infinitesimal step towards +x (then +y, then +z) enters the solid.
InsideMask voxelizeGridSpace(const TriangleMesh& gridMesh, Int3 size, const VoxelizeSettings& settings);

} // namespace sandcore
