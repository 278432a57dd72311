// SPDX-License-Identifier: MIT
#pragma once
// A plain triangle list: what a model loader hands to the voxelizer (SPEC S1, S2). sandcore
// never reads model files itself; the application's loader fills this struct.

#include "sandcore/vec3.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace sandcore {

/// Triangles as indices into a vertex list. Orientation may be mixed: nothing here relies on it
/// except signedVolume.
struct TriangleMesh {
    std::vector<Vec3> vertices;                          ///< positions, model units
    std::vector<std::array<std::uint32_t, 3>> triangles; ///< three vertex indices each

    /// Appends another mesh's vertices and triangles.
    void append(const TriangleMesh& other);
};

/// Axis-aligned bounds of the vertices that triangles use.
struct MeshBounds {
    std::array<double, 3> min{}; ///< smallest x, y, z, model units
    std::array<double, 3> max{}; ///< largest x, y, z, model units
    /// Extent along axis (0 = x, 1 = y, 2 = z), model units.
    double extent(int axis) const { return max[std::size_t(axis)] - min[std::size_t(axis)]; }
};

/// Whether a mesh encloses a volume (SPEC S5).
struct MeshClosedness {
    std::int64_t boundaryEdges = 0;    ///< edges used by an odd number of triangles, after welding
    std::int64_t nonManifoldEdges = 0; ///< edges used by more than two triangles, after welding
    /// Edges whose two triangles run along them in the same direction: the faces' orientation is
    /// inconsistent there, so a signed volume of the mesh as it is means nothing.
    std::int64_t inconsistentEdges = 0;
    bool closed = false;               ///< no boundary edges: ray parity is well defined everywhere
};

/// Bounds of the vertices referenced by triangles; throws std::invalid_argument for a mesh
/// without triangles or with an index out of range.
MeshBounds boundsOf(const TriangleMesh& mesh);

/// The mesh with vertices at bit-identical positions merged into one (indices remapped).
TriangleMesh weldVertices(const TriangleMesh& mesh);

/// Boundary and non-manifold edge counts after welding. Triangles that repeat a vertex are
/// skipped: they enclose nothing.
MeshClosedness closednessOf(const TriangleMesh& mesh);

/// The welded mesh without triangles that repeat another with the same orientation (a face
/// written twice). A pair with opposite orientations is kept: two closed parts touching along a
/// face share it that way, and the pair cancels as it should.
TriangleMesh withoutRepeatedTriangles(const TriangleMesh& mesh);

/// The mesh with triangles flipped so that neighbours across every edge used by exactly two
/// triangles agree, and each connected part winds counter-clockwise seen from outside (its
/// signed volume about its own bounds' centre is positive). Parity never depends on this; the
/// winding number and the signed volume do.
TriangleMesh orientedOutward(const TriangleMesh& mesh);

/// Sum of signed tetrahedra over all triangles (model units cubed); positive for a closed mesh
/// whose faces wind counter-clockwise seen from outside. Computed about the bounds' centre so
/// models far from the origin lose no precision.
double signedVolume(const TriangleMesh& mesh);

} // namespace sandcore
