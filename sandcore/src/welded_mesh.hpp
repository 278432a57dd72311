// SPDX-License-Identifier: MIT
#pragma once
// The steps of triangle_mesh.hpp for a mesh that weldVertices already welded, so a caller that
// runs several of them (the voxelizer) welds once and walks the edges as few times as it can.
// Private to sandcore.

#include "sandcore/triangle_mesh.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace sandcore {

/// Widens `bounds` by the corners of triangles [first, end), in order (a tie of -0.0 and +0.0
/// keeps the one met first). Returns the first error met (a missing vertex, a non-finite
/// coordinate), with `bounds` then incomplete, or nullptr. boundsOf over one range; the
/// voxelizer's over several in parallel.
const char* widenBoundsByCorners(const TriangleMesh& mesh, std::size_t first, std::size_t end, MeshBounds& bounds);

/// closednessOf, without the weld.
MeshClosedness closednessOfWelded(const TriangleMesh& welded);
/// Per triangle, 1 when withoutRepeatedTriangles keeps it; empty when it keeps every one.
std::vector<char> trianglesToKeep(const TriangleMesh& welded);
/// welded with the triangles trianglesToKeep flagged (all of them for an empty keep).
TriangleMesh keptTriangles(TriangleMesh welded, const std::vector<char>& keep);

/// orientedOutward's result, and what the one walk over its edges measured on the way.
struct OrientedMesh {
    TriangleMesh mesh;              ///< the mesh oriented outward
    MeshClosedness closedness;      ///< closednessOf the mesh as it was given
    std::int64_t inconsistentAfter = 0; ///< closednessOf(mesh).inconsistentEdges, after the flips
};
/// Flips every triangle of `part` (flipped[t] ^= 1) when the part, with its current flips,
/// encloses a negative signed volume about its own centre. Shared by both orientation walks.
void orientPartByVolume(std::span<const Vec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
                        std::span<const std::uint32_t> part, std::span<std::int8_t> flipped);

/// orientedOutward, without the weld.
OrientedMesh orientedOutwardWelded(TriangleMesh welded);

} // namespace sandcore
