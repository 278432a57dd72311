#pragma once
// The steps of triangle_mesh.hpp for a mesh that weldVertices already welded, so a caller that
// runs several of them (the voxelizer) welds once and walks the edges as few times as it can.
// Private to sandcore.

#include "sandcore/triangle_mesh.hpp"

#include <cstdint>
#include <vector>

namespace sandcore {

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
/// orientedOutward, without the weld.
OrientedMesh orientedOutwardWelded(TriangleMesh welded);

} // namespace sandcore
