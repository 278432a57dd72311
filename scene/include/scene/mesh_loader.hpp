#pragma once
// SPEC S1: any model file assimp reads becomes a plain sandcore::TriangleMesh. Every bad input
// throws ModelError with a one-line message "FILE: cause".

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

/// Reads every mesh of the file, triangulated, with identical vertices joined and node
/// transforms applied, merged into one mesh. Throws ModelError for a missing or unreadable file,
/// a format assimp cannot read, no triangles (points or lines only), a NaN or infinite
/// coordinate, or zero extent on an axis.
sandcore::TriangleMesh loadMesh(const std::string& path);

} // namespace sandglass
