// SPDX-License-Identifier: MIT
#include "sandcore/triangle_mesh.hpp"

#include "mesh_preparation.hpp"

#include <limits>
#include <stdexcept>
#include <utility>

namespace sandcore {

void TriangleMesh::append(const TriangleMesh& other) {
    const auto base = std::uint32_t(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    for (const auto& t : other.triangles) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

MeshBounds boundsOf(const TriangleMesh& mesh) {
    if (mesh.triangles.empty()) throw std::invalid_argument("the mesh has no triangles");
    MeshBounds bounds;
    bounds.min.fill(std::numeric_limits<double>::infinity());
    bounds.max.fill(-std::numeric_limits<double>::infinity());
    if (const char* error = widenBoundsByCorners(mesh.vertices, mesh.triangles, 0, mesh.triangles.size(), bounds))
        throw std::invalid_argument(error);
    return bounds;
}

// The steps below are the voxelizer's preparation (mesh_preparation.hpp) on the calling thread
// alone: its results do not depend on the thread count, and a pool of one starts no thread.

TriangleMesh weldVertices(const TriangleMesh& mesh) {
    WorkerPool pool(1);
    const WalkedMesh welded = weldedVertices(mesh, pool);
    // Renumbered triangles were checked by the weld; a mesh with nothing to weld is checked here.
    for (const auto& t : welded.triangles)
        if (t[0] >= welded.vertices.size() || t[1] >= welded.vertices.size() || t[2] >= welded.vertices.size())
            throw std::invalid_argument("a triangle refers to a missing vertex");
    return welded.copy();
}

MeshClosedness closednessOf(const TriangleMesh& mesh) {
    WorkerPool pool(1);
    return weldAndWalk(mesh, pool, RepeatedFaces::Keep).closedness;
}

TriangleMesh withoutRepeatedTriangles(const TriangleMesh& mesh) {
    WorkerPool pool(1);
    return weldAndWalk(mesh, pool).copy();
}

TriangleMesh orientedOutward(const TriangleMesh& mesh) {
    WorkerPool pool(1);
    return turnedOutward(weldAndWalk(mesh, pool, RepeatedFaces::Keep), pool);
}

double signedVolume(const TriangleMesh& mesh) {
    if (mesh.triangles.empty()) return 0.0;
    return signedVolumeAbout(mesh.vertices, mesh.triangles, {}, boundsOf(mesh));
}

} // namespace sandcore
