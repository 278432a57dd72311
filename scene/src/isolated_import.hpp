// SPDX-License-Identifier: MIT
#pragma once
// assimp in a child process: what comes back is a plain triangle list in double precision, cut
// into the file's parts (S7: named objects with their material colours), or one line saying why
// there is none. A crash or hang of the importer ends only the child.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sandglass {

/// One object of the file (an assimp node with meshes): a run of consecutive triangles.
struct ImportedPart {
    std::string name;                 ///< the node's name, else its first mesh's; may be empty
    std::uint64_t triangleCount = 0;  ///< its triangles follow the previous part's, in order
    bool hasColour = false;           ///< a material gave a diffuse (or base) colour
    std::array<float, 3> colour{0.8f, 0.8f, 0.8f}; ///< that colour, linear 0..1
};

/// The raw result of importing a model file.
struct ImportedTriangles {
    std::vector<std::array<double, 3>> vertices;         ///< positions after node transforms, model units
    std::vector<std::array<std::uint32_t, 3>> triangles; ///< indices into vertices, checked < vertices.size()
    std::vector<ImportedPart> parts; ///< the triangles cut into objects; the counts add up to triangles.size()
    std::string error;                                   ///< one line, empty on success
};

/// Imports `path` with assimp in a child process (the sandglass-import executable) that must
/// finish within timeLimitSeconds.
/// Never throws for a bad file: a crash, a hang, an importer error or a malformed reply from
/// the child all come back as `error`.
ImportedTriangles importInChildProcess(const std::string& path, double timeLimitSeconds);

/// Imports `path` with assimp in this process (used by the child, and by the libFuzzer target,
/// which wants crashes to surface). Errors come back as `error`.
ImportedTriangles importInThisProcess(const std::string& path);

/// The wire format between child and parent; decodeImport checks every count and index
/// against the bytes it was given, so a truncated or garbled reply is an error, not a crash.
std::vector<std::uint8_t> encodeImport(const ImportedTriangles& imported);
ImportedTriangles decodeImport(std::span<const std::uint8_t> bytes);

} // namespace sandglass
