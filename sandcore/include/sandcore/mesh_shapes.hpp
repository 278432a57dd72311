// SPDX-License-Identifier: MIT
#pragma once
// Closed triangle meshes built in code: shared by the voxelizer's tests, the benchmark and the
// generator of the bundled models (tools/make_models.cpp). All wind counter-clockwise seen
// from outside, so signedVolume() is positive.

#include "sandcore/triangle_mesh.hpp"

#include <vector>

namespace sandcore {

/// An axis-aligned box from min to max corner, 12 triangles.
TriangleMesh makeBoxMesh(Vec3 min, Vec3 max);

/// A sphere of `radius` about the origin: an icosahedron subdivided `subdivisions` times
/// (20 * 4^subdivisions triangles).
TriangleMesh makeIcosphereMesh(int subdivisions, float radius);

/// A torus about the y axis: ring radius `major`, tube radius `minor`, `rings` segments around
/// the axis and `sides` around the tube (2 * rings * sides triangles).
TriangleMesh makeTorusMesh(float major, float minor, int rings, int sides);

/// One point of a lathe profile: radius from the y axis and height, model units.
struct ProfilePoint {
    float radius; ///< distance from the y axis; 0 only at the first and last point (a pole)
    float y;      ///< height
};

/// A surface of revolution about the y axis from a profile listed bottom to top, with
/// `segments` around the axis. A profile that starts and ends at radius 0 gives a closed mesh.
TriangleMesh makeLatheMesh(const std::vector<ProfilePoint>& profile, int segments);

/// A closed tube of `radius` with `sides` around it along a closed polyline (the last point
/// joins the first).
TriangleMesh makeTubeMesh(const std::vector<Vec3>& loop, float radius, int sides);

} // namespace sandcore
