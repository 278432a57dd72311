#pragma once
// assimp in a child process: what comes back is a plain triangle list in double precision, or
// one line saying why there is none. A crash or hang of the importer ends only the child.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sandglass {

/// The raw result of importing a model file.
struct ImportedTriangles {
    std::vector<std::array<double, 3>> vertices;         ///< positions after node transforms, model units
    std::vector<std::array<std::uint32_t, 3>> triangles; ///< indices into vertices, checked < vertices.size()
    std::string error;                                   ///< one line, empty on success
};

/// Imports `path` with assimp in a forked child that must finish within timeLimitSeconds.
/// Never throws for a bad file: a crash, a hang, an importer error or a malformed reply from
/// the child all come back as `error`.
ImportedTriangles importInChildProcess(const std::string& path, double timeLimitSeconds);

/// Imports `path` with assimp in this process (used by the child, and by the libFuzzer target,
/// which wants crashes to surface). Errors come back as `error`.
ImportedTriangles importInThisProcess(const std::string& path);

/// The wire format between child and parent; decodeImport checks every count and index
/// against the bytes it was given, so a truncated or garbled reply is an error, not a crash.
std::vector<std::uint8_t> encodeImport(const ImportedTriangles& imported);
ImportedTriangles decodeImport(const std::vector<std::uint8_t>& bytes);

} // namespace sandglass
