// SPDX-License-Identifier: MIT
#pragma once
// Speed against error of the voxelizer (SPEC B2 "Voxelization"): time and volume error against
// resolution for a sphere, the bundled hourglass and a torus; a dense mesh; what binning saves.

#include "bench/report_files.hpp"

#include <vector>

namespace sandbench {

/// One voxelization of one mesh at one resolution.
struct VoxelRun {
    std::string mesh;            ///< "sphere", "hourglass" or "torus"
    std::size_t triangles = 0;   ///< triangles in the mesh
    int resolution = 0;          ///< cells along the largest extent
    double milliseconds = 0.0;   ///< best of the repeats
    double meshError = 0.0;      ///< (voxel - mesh volume) / mesh volume
    double analyticError = 0.0;  ///< against the exact solid (sphere 4/3 pi r^3, torus 2 pi^2 R r^2); 0 for the hourglass
    bool hasAnalytic = false;    ///< whether analyticError applies
};

/// Voxelizes the three meshes at each resolution with `threads` threads, best of `repeat`.
std::vector<VoxelRun> measureVoxelization(const std::vector<int>& resolutions, int threads, int repeat);
/// The runs as a table.
Table voxelTable(const std::vector<VoxelRun>& runs);

/// A closed torus of about 200,000 triangles at `resolution` cells with 1 and `threads` threads.
Table denseMeshTable(int resolution, int threads, int repeat);

/// Binned rows against every row tested with every triangle, at `resolution` cells.
Table binningTable(int resolution, int threads, int repeat);

} // namespace sandbench
