// SPDX-License-Identifier: MIT
#pragma once
// SPEC S7: a model file as artists make it, several named objects (assimp nodes), each a part
// with a role in the scene. A file without objects (a binary STL) is one part.

#include "scene/mesh_loader.hpp"

#include "sandcore/scene.hpp"
#include "sandcore/scene_geometry.hpp"
#include "sandcore/triangle_mesh.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sandglass {

/// What a part of a model is in the scene.
enum class PartRole : std::uint8_t {
    Vessel, ///< hourglass glass: its walls enclose the sand space, drawn transparent
    Frame,  ///< hourglass frame (plates, pillars, caps): walls too, drawn opaque
    Sand,   ///< sculpture: becomes sand
    Static, ///< sculpture: stays as an obstacle (a pedestal)
};

/// "vessel", "frame", "sand" or "static".
const char* partRoleName(PartRole role);
/// The role named; throws std::invalid_argument listing the four names otherwise.
PartRole parsePartRole(std::string_view name);

/// A role the user set for the part of that name (`--part NAME=ROLE`).
struct PartRoleChoice {
    std::string name; ///< the part's name as listed
    PartRole role = PartRole::Vessel; ///< its role
    friend bool operator==(const PartRoleChoice&, const PartRoleChoice&) = default;
};
/// "NAME=ROLE" to a choice; throws std::invalid_argument with one line otherwise.
PartRoleChoice parsePartRoleChoice(std::string_view text);

/// One connected shell of an object of a model file (W1): an object of several shells (a glass
/// with its posts and plates, modelled sand) gives a part for each.
struct ModelPart {
    std::string name;            ///< the object's name, with " #K" for its K-th shell when it has several; made unique
    std::string object;          ///< the name of the object (node or mesh) the shell belongs to
    sandcore::TriangleMesh mesh; ///< its triangles with the node transforms applied, model units
    bool closed = false;         ///< no boundary edges (S5)
    PartRole role = PartRole::Vessel; ///< chosen by chooseRoles
    /// The role came from the part's name or from the user; otherwise the hourglass's sand-space
    /// search decides between vessel, frame and modelled sand (sandcore::ModelShell::roleFixed).
    bool roleFixed = false;
    bool hasColour = false;      ///< the material gave a diffuse colour
    std::array<float, 3> colour{0.8f, 0.8f, 0.8f}; ///< diffuse colour, linear 0..1
    /// The file's bounding-box centre, which the loader subtracted from every vertex: the file's
    /// own coordinates are mesh + fileCentre (W6), model units.
    std::array<double, 3> fileCentre{};
};

/// What is reported of a part (`parts` in the JSON).
struct PartSummary {
    std::string name;         ///< as ModelPart::name
    std::int64_t triangles = 0; ///< triangles of the part
    bool closed = false;      ///< no boundary edges
    PartRole role = PartRole::Vessel; ///< role in the scene
};

/// Reads every object of a model file, split into its connected shells, as parts, in the order of
/// assimp's node tree (the order loadMesh merges them), through the same importer child process and checks as loadMesh (a
/// corrupt file that crashes or hangs assimp, or a FIFO, costs one line of error, never the
/// process). Vertices are moved as loadMesh moves them (bounding-box centre at the origin) and
/// joined within each part. Throws ModelError ("FILE: cause") for every S1 bad input.
std::vector<ModelPart> loadModelParts(const std::string& path, const MeshLoadOptions& options = {});

/// All parts as one mesh, in order: loadMesh's triangles at loadMesh's positions (vertices shared
/// by two parts are not joined).
sandcore::TriangleMesh mergedMesh(const std::vector<ModelPart>& parts);

/// Gives every part its role. Automatic for the hourglass: names with glass/vessel/bulb are the
/// vessel, frame/base/cap/plate/pillar/post/stand/rod/wood the frame, sand the modelled sand
/// (all fixed); others are the vessel until the sand-space search decides. For the sculpture,
/// object by object (a shell takes its object's role): the largest closed object is sand; one
/// named base/pedestal/plinth/stand, or one that rests on the floor and reaches no higher than
/// the bottom quarter of the sand object, is static; others are sand. Then the user's choices,
/// by part or by object name; throws std::invalid_argument naming an unknown part and listing the parts.
void chooseRoles(std::vector<ModelPart>& parts, sandcore::SceneKind kind, const std::vector<PartRoleChoice>& choices);

/// The reported view of the parts.
std::vector<PartSummary> summarize(const std::vector<ModelPart>& parts);

} // namespace sandglass
