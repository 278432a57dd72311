// SPDX-License-Identifier: MIT
#pragma once
// Meshes in the canonical frame (y up, axis at x = z = 0, canonical units) that the model
// classes are made of, and the damage a downloaded file carries.

#include "seeded_random.hpp"
#include "wild_models/wild_models.hpp"

#include "sandcore/triangle_mesh.hpp"

#include <functional>
#include <string>
#include <vector>

namespace sandglass::wild {

using sandcore::TriangleMesh;

/// A named part of a canonical model, before the turn to its up axis.
struct Part {
    std::string name;  ///< object name
    TriangleMesh mesh; ///< canonical units
};

/// A model of one class in the canonical frame, with its ground truth.
struct CanonicalModel {
    std::vector<Part> parts; ///< the file's objects
    GroundTruth truth;       ///< canonical units
    std::int64_t removedFaces = 0; ///< faces cut away to open holes
};

/// A surface of revolution through (radius, y) points listed bottom to top; a point of radius 0
/// is a pole. Without poles at the ends the surface is open there. Faces point away from the axis.
TriangleMesh lathe(const std::vector<ProfileSample>& radiusAtY, int segments);
/// As lathe, closed at both ends by flat discs (or poles where the profile already meets the axis).
TriangleMesh closedLathe(std::vector<ProfileSample> radiusAtY, int segments);
/// A closed surface of revolution from a closed loop of (radius, y) points off the axis: a tube
/// wall with rims, the loop running up the outside and down the inside.
TriangleMesh revolveLoop(const std::vector<ProfileSample>& loop, int segments);
/// A closed cylinder about a vertical axis through (x, z), from y0 to y1.
TriangleMesh cylinderMesh(double radius, double y0, double y1, double x, double z, int segments);
/// A closed axis-aligned box.
TriangleMesh boxMesh(Point min, Point max);
/// A closed ellipsoid, or open where cutTop / cutBottom leave out the rings around its poles.
TriangleMesh ellipsoidMesh(const Ellipsoid& solid, int rings, int segments, bool cutTop, bool cutBottom);
/// A capsule; an end that is not round is left open (a sleeve).
TriangleMesh capsuleMesh(const Capsule& solid, int rings, int segments);

/// The mesh with every triangle's winding reversed.
TriangleMesh reversed(TriangleMesh mesh);
/// Removes the triangles whose centroid satisfies `cut`; returns how many went.
std::int64_t removeFaces(TriangleMesh& mesh, const std::function<bool(Point)>& cut);

/// Flips, duplicates and unwelds faces at random, as files from the wild have them; records it.
void damageParts(Rng& rng, std::vector<Part>& parts, Damage& damage);

} // namespace sandglass::wild
