// SPDX-License-Identifier: MIT
#pragma once
// Welding, dropping repeated faces, closedness and the outward orientation of a mesh: the one
// implementation behind the public functions of triangle_mesh.hpp (on one thread) and what
// voxelize needs of a loaded mesh before casting rays (on all of its threads). Computed in
// parallel with little fresh memory; the results are the same for any thread count. Private to
// sandcore. The orientation's search and sums: mesh_orientation.cpp.

#include "sandcore/large_pages.hpp"
#include "sandcore/triangle_mesh.hpp"
#include "worker_pool.hpp"

#include <array>
#include <cstdint>
#include <new>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace sandcore {

template <class T> using LargePageVector = std::vector<T, FillLaterAllocator<T>>;
using MeshTriangle = std::array<std::uint32_t, 3>;
/// WalkedMesh::neighbours of an edge that links no two faces.
inline constexpr std::uint32_t kNoNeighbour = ~std::uint32_t{0};

/// A welded mesh, its repeated faces dropped, with the links between faces that one walk over
/// its edges found. Kept in huge pages: fresh memory costs a page fault per 4 KiB otherwise.
/// A mesh loaded through a library that welds (assimp) has nothing to weld: then the spans are
/// the given mesh's own arrays, and nothing is copied until a step must change the triangles.
struct WalkedMesh {
    std::span<const Vec3> vertices;           ///< welded positions, in the order of first use
    std::span<const MeshTriangle> triangles;  ///< kept triangles, as given
    LargePageVector<Vec3> weldedVertices;     ///< the vertices' storage where welding changed them
    LargePageVector<MeshTriangle> ownTriangles; ///< the triangles' storage once they are changed
    MeshClosedness closedness;                ///< closednessOf the mesh as given (before dropping repeated faces)
    /// Per triangle edge slot 3t + e (edge from corner e to e + 1): the neighbour across an edge
    /// used by exactly two triangles, other << 1 | (1 when the two run along it the same way);
    /// kNoNeighbour for any other edge.
    LargePageVector<std::uint32_t> neighbours;

    WalkedMesh() = default;
    WalkedMesh(const WalkedMesh&) = delete; // the spans may point into its own storage
    WalkedMesh& operator=(const WalkedMesh&) = delete;
    WalkedMesh(WalkedMesh&&) = default;     // a moved vector keeps its buffer, so the spans stay valid

    /// The triangles, in storage of its own (copied from the given mesh the first time).
    std::span<MeshTriangle> changeableTriangles();
    /// Keeps the first `count` triangles.
    void keepFirstTriangles(std::size_t count);
    /// The vertices and triangles as a plain mesh of their own.
    TriangleMesh copy() const;
};

/// Widens `bounds` by the corners of triangles [first, end), in order (a tie of -0.0 and +0.0
/// keeps the one met first). Returns the first error met (a missing vertex, a non-finite
/// coordinate), with `bounds` then incomplete, or nullptr. boundsOf over one range;
/// boundsInParallel over several.
const char* widenBoundsByCorners(std::span<const Vec3> vertices, std::span<const MeshTriangle> triangles, std::size_t first,
                                 std::size_t end, MeshBounds& bounds);

/// boundsOf, in parallel: the same bounds, and the same error for the first bad triangle.
MeshBounds boundsInParallel(const TriangleMesh& mesh, WorkerPool& pool);

/// Welds the vertices at bit-identical positions: the positions in the order of their first use,
/// the triangles renumbered (no copy where nothing welds). Only the triangles that were
/// renumbered have their indices checked; nothing is linked.
WalkedMesh weldedVertices(const TriangleMesh& mesh, WorkerPool& pool);

/// Whether weldAndWalk drops the faces that repeat another with the same orientation.
enum class RepeatedFaces { Drop, Keep };
/// Welds the vertices at bit-identical positions, drops repeated faces (unless told to keep
/// them) and links neighbours. Throws std::invalid_argument for an index out of range or 2^29
/// triangles and more.
WalkedMesh weldAndWalk(const TriangleMesh& mesh, WorkerPool& pool, RepeatedFaces repeated = RepeatedFaces::Drop);

/// Which triangles orientedOutward flips (1) and closednessOf(its result).inconsistentEdges:
/// neighbours across every edge used by exactly two faces agree where they can, and each part
/// (faces linked through such edges) is turned over as a whole when its signed volume about its
/// own bounds' centre is negative.
/// Reads the mesh only, so rays can be cast through it meanwhile.
struct Orientation {
    LargePageVector<std::uint8_t> flipped;
    std::int64_t inconsistentAfter = 0;
    /// signedVolumeOf(walked, flipped, bounds), where the orientation summed it on the way (a mesh
    /// of one part, whose centre is the bounds' centre); otherwise empty.
    std::optional<double> signedVolume;
};
/// `bounds`: the bounds of the corners the walked mesh's triangles use (boundsInParallel of the
/// mesh as loaded has them).
Orientation orientationOf(const WalkedMesh& walked, const MeshBounds& bounds);

/// Sum of signed tetrahedra about the bounds' centre (signedVolume), the triangles whose
/// `flipped` entry is nonzero turned over (none when `flipped` is empty).
double signedVolumeAbout(std::span<const Vec3> vertices, std::span<const MeshTriangle> triangles,
                         std::span<const std::uint8_t> flipped, const MeshBounds& bounds);

/// signedVolume of the mesh with the flipped triangles turned over, bit for bit, given the
/// bounds of the mesh as loaded (boundsInParallel). Its triangles' corners are the welded mesh's
/// at the same positions: welding and dropping repeated faces keep every position a kept
/// triangle uses, and where they swap a -0.0 for a +0.0 the centre, and so each term, keeps its value.
double signedVolumeOf(const WalkedMesh& walked, const LargePageVector<std::uint8_t>& flipped, const MeshBounds& bounds);

/// Turns the flipped triangles over.
void applyOrientation(WalkedMesh& walked, const Orientation& orientation, WorkerPool& pool);

/// The walked mesh oriented outward (orientationOf, then applyOrientation), as a plain mesh.
TriangleMesh turnedOutward(WalkedMesh walked, WorkerPool& pool);

} // namespace sandcore
