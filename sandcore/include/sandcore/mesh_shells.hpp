// SPDX-License-Identifier: MIT
#pragma once
// SPEC W1: a model's object often holds several separate surfaces (a glass, its posts and plates,
// modelled sand). Each connected shell gets a role of its own.

#include "sandcore/triangle_mesh.hpp"

#include <vector>

namespace sandcore {

/// The mesh's connected shells: triangles joined through shared vertices (weld first, see
/// weldVertices), each shell with its own vertex list, in the order of each shell's first triangle.
std::vector<TriangleMesh> splitIntoShells(const TriangleMesh& mesh);

/// The mesh with every face that another face repeats dropped, whatever the two windings: a face
/// modelled twice (often once per side) is drawn once. The first of each set is kept.
TriangleMesh withoutDoubledFaces(const TriangleMesh& mesh);

} // namespace sandcore
