// SPDX-License-Identifier: MIT
#pragma once
// SPEC S8, S9, W1-W5: the recipe that turns a model's triangles into an hourglass: which shells
// are glass, frame and modelled sand, where the sand lives (the space the glass encloses, with
// or without wall thickness, open ends closed by plates with small gaps, a neck under a cell
// opened), which way is up, and the initial sand. Geometry only: the application and an
// embedder call the same function.

#include "sandcore/inside_mask.hpp"
#include "sandcore/scene.hpp"
#include "sandcore/scenes.hpp"
#include "sandcore/triangle_mesh.hpp"
#include "sandcore/up_axis.hpp"
#include "sandcore/voxelizer.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sandcore {

/// What a shell of a model is in an hourglass (S7).
enum class ShellRole : std::uint8_t {
    Glass, ///< its walls enclose the sand space
    Frame, ///< plates, posts, caps: walls too, never sand space
    Sand,  ///< modelled sand inside the glass: the initial sand
};

/// One connected surface of a model (W1).
struct ModelShell {
    TriangleMesh mesh;                ///< model units
    ShellRole role = ShellRole::Glass; ///< what it is; see roleFixed
    /// The role came from a name or from the user and is kept; otherwise the search decides
    /// between glass, frame and modelled sand from the shell's place in the model.
    bool roleFixed = false;
    /// Whether the mesh is closed, when the caller already knows (closednessOf()); found otherwise.
    std::optional<bool> closed = std::nullopt;
};

/// Where the sand of a model hourglass lives.
enum class SandSpaceKind : std::uint8_t {
    Solid,      ///< the inside of a closed glass surface (a model made as one surface of its sand)
    Cavity,     ///< the space the walls enclose (glass with thickness, or glass closed by plates)
    OpenVessel, ///< no hourglass: the inside of a vessel open at its ends (a funnel); it runs out onto the floor
    Model,      ///< no hourglass and no vessel: the model's own inside, used as a solid
};
/// "solid", "cavity", "open" or "model".
const char* sandSpaceKindName(SandSpaceKind kind);

/// How the sand space is searched for.
struct HourglassSpaceSettings {
    VoxelizeSettings voxelize;   ///< resolution, stretch and threads of the model's grid
    std::optional<UpAxis> up;    ///< the model axis that points up; none = found along the neck
    int maxClosingCells = 2;     ///< gaps in the walls up to twice this many cells wide are closed
};

/// The sand space of a model hourglass, in the model's grid turned so that up is +y.
struct HourglassSpace {
    VoxelPlacement placement;          ///< model units to the model's grid (before the turn)
    InsideMask space;                  ///< cells sand may take, turned
    /// The insides of the shells of role Sand, turned; all outside when none. Cells outside the
    /// space may be marked (sand modelled into the glass's wall): the scene never fills those.
    InsideMask modelledSand;
    UpAxis up = UpAxis::PlusY;         ///< the model axis turned to +y
    bool upFound = false;              ///< found along the neck, not given
    SandSpaceKind kind = SandSpaceKind::Cavity; ///< where the sand lives
    bool isHourglass = false;          ///< the space has two bulbs and a neck
    int closingCells = 0;              ///< the walls' gaps that had to be closed, cells (0 = none)
    bool neckOpened = false;           ///< a neck narrower than a cell was opened to one cell
    int enclosedSpaces = 0;            ///< spaces the walls enclose with no gap closed (cavities of 27 cells or more)
    std::vector<ShellRole> roles;      ///< each shell's role as used, in the order given
    /// W5: empty when an hourglass was found; otherwise one line saying why not and what the
    /// space is instead.
    std::string note;
};

/// Finds the sand space of an hourglass made of `shells` (S8, W2): the space enclosed by the
/// glass and frame shells, closing gaps of up to 2 * maxClosingCells cells and opening a neck
/// under a cell; of all such spaces the largest with two bulbs and a neck, stood up along its
/// neck (the bulb holding more modelled sand on top). Shells not fixed become modelled sand when
/// walls enclose them and they fill part of one bulb, and frame when the sand space does not
/// border on them. Without an hourglass, the inside of an open vessel or the model's own inside
/// is used, with a note. Shells without triangles are skipped; throws std::invalid_argument when
/// there is no shell or placeInGrid refuses the grid.
HourglassSpace findHourglassSpace(const std::vector<ModelShell>& shells, const HourglassSpaceSettings& settings);

/// An hourglass scene from a sand space: makeHourglassScene, with the modelled sand as the
/// upper bulb's initial sand when there is any in it, filled to fit the lower bulb (fitLowerBulb).
Scene makeHourglassScene(const HourglassSpace& space, HourglassSettings hourglass = {}, const StepSettings& step = {});

/// The whole recipe in one call, for an embedder: a triangle soup (any number of shells, glass
/// with or without thickness, frame, modelled sand) to a ready hourglass scene of `resolution`
/// cells along its largest extent.
Scene makeHourglassFromMesh(const TriangleMesh& mesh, int resolution = 64, const HourglassSettings& hourglass = {},
                            const StepSettings& step = {});

} // namespace sandcore
