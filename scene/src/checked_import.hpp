// SPDX-License-Identifier: MIT
#pragma once
// The one way a model file is read (loadMesh and loadModelParts): the importer child process
// (isolated_import.hpp) and every S1/H2 check of what it returns, so no file reaches assimp in
// the application's own process and both loaders refuse the same bad inputs the same way.

#include "isolated_import.hpp"
#include "scene/mesh_loader.hpp"

#include "sandcore/triangle_mesh.hpp"

#include <array>
#include <string>

namespace sandglass {

/// An imported model that passed every check, and the centre of its bounding box.
struct CheckedImport {
    ImportedTriangles imported;      ///< vertices, triangles and parts (never empty)
    std::array<double, 3> centre{};  ///< bounding-box centre of the used vertices, model units

    /// Vertex i moved so that the centre is the origin, computed in double, then rounded to float.
    sandcore::Vec3 centred(std::uint32_t i) const;
};

/// Refuses a missing, unreadable or non-regular file (a FIFO would block the importer forever)
/// before any process starts, imports it in the child process with the time limit, and checks
/// the result (no triangles, NaN or infinite coordinates, single precision too coarse, zero
/// extent). Throws ModelError ("FILE: cause") for each.
CheckedImport importChecked(const std::string& path, const MeshLoadOptions& options);

} // namespace sandglass
