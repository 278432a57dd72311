#pragma once
// What voxelize needs of a loaded mesh before casting rays, computed in parallel with little
// fresh memory: the same welded vertices, kept triangles, outward orientation, closedness and
// inconsistency counts as weldVertices -> trianglesToKeep -> orientedOutwardWelded
// (welded_mesh.hpp), bit for bit and for any thread count. Private to sandcore.

#include "sandcore/large_pages.hpp"
#include "sandcore/triangle_mesh.hpp"
#include "sandcore/worker_pool.hpp"

#include <cstdint>
#include <vector>

namespace sandcore {

/// A welded mesh, its repeated faces dropped, with the links between faces that one walk over
/// its edges found; orientFaces then turns it outward.
struct WalkedMesh {
    TriangleMesh mesh;           ///< welded vertices, kept triangles (as given until orientFaces)
    MeshClosedness closedness;   ///< closednessOf the mesh as given (before dropping repeated faces)
    /// Per triangle edge slot 3t + e (edge from corner e to e + 1): the neighbour across an edge
    /// used by exactly two triangles, other << 1 | (1 when the two run along it the same way).
    std::vector<std::uint32_t, LargePageAllocator<std::uint32_t>> neighbours;
};

/// Welds the vertices at bit-identical positions, drops repeated faces and links neighbours.
/// Throws std::invalid_argument for an index out of range or 2^29 triangles and more.
WalkedMesh weldAndWalk(const TriangleMesh& mesh, WorkerPool& pool);

/// Flips faces as orientedOutward does; returns closednessOf(result).inconsistentEdges.
std::int64_t orientFaces(WalkedMesh& walked);

} // namespace sandcore
