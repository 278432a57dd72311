// SPDX-License-Identifier: MIT
#pragma once
// SPEC S7-S9, W1-W5: a model file's parts, up axis and sand space. The hourglass's recipe is
// sandcore's (findHourglassSpace); this layer loads the file, names the parts and reports.
// Sculptures fill open meshes robustly and stand a model up along +y, or +z when it is clearly
// taller that way.

#include "scene/build_progress.hpp"
#include "scene/model_parts.hpp"
#include "scene/model_voxelizer.hpp"

#include "sandcore/hourglass_space.hpp"
#include "sandcore/inside_mask.hpp"
#include "sandcore/up_axis.hpp"

#include <optional>
#include <string>
#include <vector>

namespace sandglass {

/// Where the sand of an hourglass lives (sandcore::SandSpaceKind).
using VesselKind = sandcore::SandSpaceKind;
/// "solid", "cavity", "open" or "model".
inline const char* vesselKindName(VesselKind kind) { return sandcore::sandSpaceKindName(kind); }

/// What the user asks of a model beyond the voxelization settings.
struct ModelShapeRequest {
    sandcore::SceneKind kind = sandcore::SceneKind::Hourglass; ///< hourglass looks for a cavity and the up axis
    std::vector<PartRoleChoice> roles;  ///< --part NAME=ROLE, applied after the automatic roles
    std::optional<sandcore::UpAxis> up; ///< --up; none = found (hourglass) or by the sculpture's rule
};

/// A model file turned into the cells a scene is built from.
struct SandSpace {
    ModelVoxelization model;            ///< the whole model's voxelization (S2, S6), turned to the up axis
    std::vector<ModelPart> parts;       ///< the parts (shells) with their roles (model units, not turned)
    sandcore::InsideMask space;         ///< sand space (hourglass) or sand cells (sculpture), turned
    sandcore::InsideMask obstacles;     ///< sculpture: cells of static parts, turned; empty size otherwise
    sandcore::InsideMask modelledSand;  ///< hourglass: the modelled sand's cells, turned; empty size when none
    VesselKind vessel = VesselKind::Solid; ///< hourglass: where the sand lives
    sandcore::UpAxis up = sandcore::UpAxis::PlusY; ///< the model axis that points up
    bool upFound = false;               ///< the up axis was found, not given
    int cavities = 0;                   ///< spaces the walls enclose (hourglass)
    int closingCells = 0;               ///< hourglass: gaps in the walls closed, cells (0 = none)
    bool neckOpened = false;            ///< hourglass: a neck under a cell was opened to one cell
    std::string note;                   ///< W5: why no hourglass was found and what was done instead; W4: parts too thin for the grid; empty otherwise
    double cavityMilliseconds = 0.0;    ///< time of the sand-space search (hourglass), ms
    double loadMilliseconds = 0.0;      ///< time of reading the file and splitting it into parts, ms
};

/// Loads the parts of `path`, chooses their roles, voxelizes the model (memory checked first,
/// as voxelizeModelFile) and finds the sand space and up axis. Throws ModelError ("FILE: cause")
/// for bad input and std::invalid_argument for an unknown part name. `progress` (when given)
/// passes Loading, Voxelizing and FindingSandSpace, and may throw BuildCancelled there.
SandSpace loadSandSpace(const std::string& path, const sandcore::VoxelizeSettings& settings, ModelUse use,
                        const ModelShapeRequest& request, std::uint64_t memoryLimit = 0,
                        BuildProgress* progress = nullptr);

/// The sculpture's up axis when none is given: +z when the model is clearly longer along z than
/// along x and y (a figure modelled Z-up would lie on its back otherwise), else +y. A sculpture
/// is made to stand, so its longest extent is taken as its height only when it is clearly so.
sandcore::UpAxis sculptureUpAxis(const sandcore::MeshBounds& bounds);

/// When the model's median part is thinner than `thinnerThanCells` cells at `resolution`: "its N
/// parts are about X cells thin; --res R would give them two cells across"; else "".
std::string thinPartsHint(const std::vector<ModelPart>& parts, const sandcore::VoxelPlacement& placement, int resolution,
                          double thinnerThanCells);

/// S1: why no cell lies inside the model at `resolution`, with the resolution that would give
/// most of its parts two cells across when they are thinner than that (one line).
std::string noCellInsideMessage(const std::vector<ModelPart>& parts, const sandcore::VoxelPlacement& placement,
                                int resolution, bool closed);

} // namespace sandglass
