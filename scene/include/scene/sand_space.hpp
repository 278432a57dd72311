#pragma once
// SPEC S7-S9: a model file's parts, up axis and sand space. For the hourglass the sand space is
// the largest cavity that the vessel and frame parts enclose together (a glass with thickness);
// a model made as one surface of the sand space keeps its inside (S2). Sculptures keep +y.

#include "scene/model_parts.hpp"
#include "scene/model_voxelizer.hpp"

#include "sandcore/inside_mask.hpp"
#include "sandcore/up_axis.hpp"

#include <optional>
#include <string>
#include <vector>

namespace sandglass {

/// Where the sand of an hourglass lives.
enum class VesselKind : std::uint8_t {
    Solid,  ///< the model is the sand space's surface: its inside cells
    Cavity, ///< the largest cavity enclosed by the vessel and frame parts
};
/// "solid" or "cavity".
const char* vesselKindName(VesselKind kind);

/// Fewest cells a cavity needs to count as the sand space (a 3x3x3 room); smaller ones are gaps
/// between touching parts.
inline constexpr std::int64_t kMinCavityCells = 27;

/// What the user asks of a model beyond the voxelization settings.
struct ModelShapeRequest {
    sandcore::SceneKind kind = sandcore::SceneKind::Hourglass; ///< hourglass looks for a cavity and the up axis
    std::vector<PartRoleChoice> roles;  ///< --part NAME=ROLE, applied after the automatic roles
    std::optional<sandcore::UpAxis> up; ///< --up; none = found (hourglass) or +y (sculpture)
};

/// A model file turned into the cells a scene is built from.
struct SandSpace {
    ModelVoxelization model;            ///< the whole model's voxelization (S2, S6), turned to the up axis
    std::vector<ModelPart> parts;       ///< the parts with their roles (model units, not turned)
    sandcore::InsideMask space;         ///< sand space (hourglass) or sand cells (sculpture), turned
    sandcore::InsideMask obstacles;     ///< sculpture: cells of static parts, turned; empty size otherwise
    VesselKind vessel = VesselKind::Solid; ///< hourglass: where the sand lives
    sandcore::UpAxis up = sandcore::UpAxis::PlusY; ///< the model axis that points up
    bool upFound = false;               ///< the up axis was found, not given
    int cavities = 0;                   ///< cavities the walls enclose (hourglass)
    double cavityMilliseconds = 0.0;    ///< time of the walls' voxelization and the cavity search, ms
};

/// Loads the parts of `path`, chooses their roles, voxelizes the model (memory checked first,
/// as voxelizeModelFile) and finds the sand space and up axis. Throws ModelError ("FILE: cause")
/// for bad input and std::invalid_argument for an unknown part name.
SandSpace loadSandSpace(const std::string& path, const sandcore::VoxelizeSettings& settings, ModelUse use,
                        const ModelShapeRequest& request, std::uint64_t memoryLimit = 0);

} // namespace sandglass
