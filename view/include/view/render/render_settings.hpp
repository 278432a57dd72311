// SPDX-License-Identifier: MIT
#pragma once
// How grains are drawn (SPEC V1-V6): the display half of the application state. The panels
// change it; the renderer reads it every frame.

#include "scene/sand_palette.hpp"

#include "sandcore/normals.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string_view>

namespace sandglass {

/// The four looks of thesis §3.8 (SPEC V1).
enum class RenderMode : std::uint8_t {
    Points,          ///< GL points of a fixed pixel size (the thesis's default)
    Sprites,         ///< round shaded point sprites of a fixed pixel size ("ungerichtete Sprites")
    Billboards,      ///< a shaded quad per grain, turned to face the camera exactly
    PseudoBillboards ///< quads sharing one orientation from the camera's rotation, set once per frame
};

/// True for the modes that draw each sub-grain as a quad (4 corners, 2 triangles).
constexpr bool drawsQuads(RenderMode mode) { return mode == RenderMode::Billboards || mode == RenderMode::PseudoBillboards; }

/// Every render mode in panel order.
inline constexpr RenderMode kRenderModes[] = {RenderMode::Points, RenderMode::Sprites, RenderMode::Billboards,
                                              RenderMode::PseudoBillboards};

/// Command-line name: "points", "sprites", "billboards" or "pseudo".
const char* renderModeName(RenderMode mode);
/// The thesis's short table name: "P", "S", "BB" or "PBB".
const char* renderModeShortName(RenderMode mode);
/// Panel label: "Points", "Sprites", "Billboards", "Pseudo-billboards".
const char* renderModeLabel(RenderMode mode);
/// The mode named by renderModeName, or nothing.
std::optional<RenderMode> parseRenderMode(std::string_view name);

/// Command-line name of an R12 normal estimate: "columns" or "gradient".
const char* normalMethodName(sandcore::NormalMethod method);
/// The estimate named by normalMethodName, or nothing.
std::optional<sandcore::NormalMethod> parseNormalMethod(std::string_view name);

/// Grains per cell of SPEC V2 (the thesis's mInnerCountMax).
inline constexpr int kMaxGrainsPerCell = 32;

/// How grains reach the GPU (V8).
enum class GrainPath : std::uint8_t {
    GpuInterpolated, ///< kept on the GPU, only what changed uploaded, positions worked out by the vertex shader
    CpuFullUpload,   ///< every grain packed on the CPU and uploaded whenever any moved (the earlier path, kept as reference)
};

/// The lights of a lit scene (docs/rendering.md, Lighting).
enum class LightRig : std::uint8_t {
    Studio, ///< a warm key light from above, a cool fill and a sky; with the look's elements below
    Thesis, ///< the thesis's white point light a little below the camera, nothing else (§3.8)
};

/// Command-line name: "studio" or "thesis".
const char* lightRigName(LightRig rig);
/// The rig named by lightRigName, or nothing.
std::optional<LightRig> parseLightRig(std::string_view name);

/// Display settings. The defaults are the best look that holds real time on an ordinary GPU
/// (docs/rendering.md, "The default look"): lit pseudo-billboards under the studio lights with
/// ambient occlusion, shadows, tone mapping and a glass that reflects a sky. thesisLook() gives
/// the thesis's choices (§3.7): unlit points. Beyond the thesis are also the glass hull (on) and
/// the normal estimate (the occupancy gradient, not the thesis's column heights, which are wrong
/// on walls and overhangs).
struct RenderSettings {
    RenderMode mode = RenderMode::PseudoBillboards; ///< round lit grains; the thesis drew points
    int grainsPerCell = 4;                ///< sub-grains drawn per cell, 1..32 (V2)
    bool lighting = true;                 ///< V3: grains lit from estimated normals; the thesis's default was off
    LightRig light = LightRig::Studio;    ///< which lights; Thesis draws exactly as the thesis did
    bool ambientOcclusion = true;         ///< studio: a grain darkens with its occupied neighbours (from the cells)
    bool shadows = true;                  ///< studio: the key light's shadow map (sand, frame, base)
    bool toneMapping = true;              ///< studio: a filmic curve from linear light to the screen; off: clamped
    bool glassEnvironment = true;         ///< studio: glass reflects a soft sky and ground
    bool innerGrains = true;              ///< V4: draw grains hidden by their 6 neighbours; default on
    bool blackBackground = false;         ///< V5: thesis default white
    bool hull = true;                     ///< V6: translucent vessel hull (beyond the thesis)
    bool voxelHull = false;               ///< S10: a model's vessel as the voxel hull, not as modelled
    float pointSize = 3.0f;               ///< points and sprites: diameter in pixels at content scale 1
    float quadSize = 1.15f;               ///< billboards: quad edge in cells at 1 grain per cell (shrinks with k); large enough that a pile shows no background
    float jitter = 0.5f;                  ///< R8 jitter 0..1 of a grain inside its cell
    float cellSize = 1.0f;                ///< world units per cell (the thesis's mSize)
    SandPalette palette = SandPalette::Desert; ///< S12: the sand's colours; default warm desert sand
    sandcore::NormalMethod normals = sandcore::NormalMethod::OccupancyGradient; ///< R12 estimate used by V3; beyond the thesis (its method is ColumnHeights)
    GrainPath grainPath = GrainPath::GpuInterpolated; ///< V8 upload path; both draw the same picture
};
/// The thesis's own choices (§3.7): unlit points, its light when lit, none of the studio's elements.
RenderSettings thesisLook();

/// True when the studio lights shade (the frame and glass always with them, the grains when lit).
inline bool studioLights(const RenderSettings& settings) { return settings.light == LightRig::Studio; }
/// True when grains are darkened by their occupied neighbours.
inline bool grainOcclusion(const RenderSettings& settings) {
    return settings.lighting && studioLights(settings) && settings.ambientOcclusion;
}
/// True when the key light's shadow map is drawn and read.
inline bool keyShadows(const RenderSettings& settings) { return studioLights(settings) && settings.shadows; }

/// The sub-grains drawn per cell: grainsPerCell kept to 1..kMaxGrainsPerCell.
inline int drawnGrainsPerCell(const RenderSettings& settings) {
    return std::clamp(settings.grainsPerCell, 1, kMaxGrainsPerCell);
}

} // namespace sandglass
