#pragma once
// The steps of triangle_mesh.hpp for a mesh that weldVertices already welded, so a caller that
// runs several of them (the voxelizer) welds once. Private to sandcore.

#include "sandcore/triangle_mesh.hpp"

namespace sandcore {

MeshClosedness closednessOfWelded(const TriangleMesh& welded);        ///< closednessOf, without the weld
TriangleMesh withoutRepeatedTrianglesWelded(TriangleMesh welded);     ///< withoutRepeatedTriangles, without the weld
TriangleMesh orientedOutwardWelded(TriangleMesh welded);              ///< orientedOutward, without the weld

} // namespace sandcore
