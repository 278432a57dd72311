// SPDX-License-Identifier: MIT
#pragma once
// SPEC S1, H2, H4: any model file assimp reads becomes a plain sandcore::TriangleMesh. Every bad
// input throws ModelError with a one-line message "FILE: cause"; no file, however corrupt, may
// crash or hang the process, so assimp runs in a child process with a time limit (see
// mesh_loader.cpp and docs/shapes.md, "Loading untrusted files").

#include "sandcore/triangle_mesh.hpp"

#include <stdexcept>
#include <string>

namespace sandglass {

/// A model that cannot be used; what() is one line naming the file and the cause.
class ModelError : public std::runtime_error {
public:
    /// Message "path: cause".
    ModelError(const std::string& path, const std::string& cause) : std::runtime_error(path + ": " + cause) {}
};

/// How a model file is imported.
struct MeshLoadOptions {
    /// Longest time the import may take, seconds; 0 means 20 s plus 1 s per MiB of the file.
    double timeLimitSeconds = 0.0;
};

/// Fewest steps of single precision the model's largest extent must span at its distance from the
/// origin: below that the file's (or assimp's) float coordinates cannot hold the model's shape.
inline constexpr double kMinSinglePrecisionSteps = 16.0;

/// Reads every mesh of the file, triangulated, node transforms applied in double precision,
/// merged into one mesh, moved so that its bounding-box centre is the origin (the voxel
/// placement never depended on where the model sat; near the origin single precision holds it
/// best) and with vertices at bit-identical positions joined (never assimp's epsilon join, which
/// merges distinct vertices of small models). Throws ModelError for a missing, unreadable or
/// non-regular file (a FIFO), a format assimp cannot read, a file that crashes or hangs the
/// importer, no triangles (points or lines only), a NaN or infinite coordinate, coordinates
/// that single precision cannot resolve at the model's distance from the origin, or zero extent
/// on an axis.
sandcore::TriangleMesh loadMesh(const std::string& path, const MeshLoadOptions& options = {});

} // namespace sandglass
