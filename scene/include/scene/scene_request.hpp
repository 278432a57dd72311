// SPDX-License-Identifier: MIT
#pragma once
// What the user asked for (scene kind, shape, resolution), turned into a sandcore::Scene. The
// command line, the benchmark and the window all build scenes through here, and every value of a
// request is given its default and checked in one place (applySceneDefaults), with one range each.

#include "scene/build_progress.hpp"
#include "scene/model_drawing.hpp"
#include "scene/model_parts.hpp"
#include "scene/model_voxelizer.hpp"
#include "scene/sand_space.hpp"

#include "sandcore/inside_mask.hpp"
#include "sandcore/scene.hpp"
#include "sandcore/scene_geometry.hpp"

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace sandglass {

/// The range a setting may take, with the command-line option that sets it (for messages).
template <class T> struct SettingRange {
    T min;              ///< smallest allowed value
    T max;              ///< largest allowed value
    const char* option; ///< e.g. "--res"
    bool contains(T value) const { return value >= min && value <= max; } ///< min <= value <= max
};

inline constexpr SettingRange<int> kResolutionRange{8, 4096, "--res"};     ///< cells along the largest extent
inline constexpr SettingRange<int> kThreadsRange{1, 256, "--threads"};      ///< worker threads of a step
inline constexpr SettingRange<double> kNeckRadiusRange{0.0, 1024.0, "--neck"}; ///< cells; 0 = automatic
inline constexpr SettingRange<double> kFillRange{0.001, 1.0, "--fill"};     ///< share of the upper bulb filled
inline constexpr SettingRange<int> kNoiseRange{-1, 5, "--noise"};           ///< noNoise threshold; -1 = off
/// Granular angle of repose, degrees (SPEC PH2).
inline constexpr SettingRange<double> kReposeRange{sandcore::kMinReposeDegrees, sandcore::kMaxReposeDegrees, "--repose"};
/// Granular gravity, cells per step squared (SPEC PH3).
inline constexpr SettingRange<double> kGravityRange{sandcore::kMinGravity, sandcore::kMaxGravity, "--gravity"};

/// A scene as the user describes it.
struct SceneRequest {
    sandcore::SceneKind kind = sandcore::SceneKind::Hourglass; ///< which of the three scenes
    std::string shape;          ///< procedural shape: "sphere", "cube" or "hourglass"; empty = the scene's default
    int resolution = 0;         ///< cells along the shape's largest extent (the canvas: its width); 0 = defaultResolution(kind)
    float neckRadius = 0.0f;    ///< procedural hourglass neck radius in cells; 0 = resolution / 24, at least 1.5
    float fillFraction = 0.85f; ///< share of the upper bulb filled at reset (hourglass)
    std::string modelPath;      ///< model file (any format assimp reads); empty = the procedural shape
    bool stretch = false;       ///< model: scale every axis to `resolution` cells (aspect not kept)
    bool robust = false;        ///< model: majority-vote inside test for open meshes (S5)
    int noiseThreshold = 1;     ///< model: S3 noNoise removes cells with at most this many inside face neighbours; -1 = off
    bool drainCompletely = true; ///< hourglass: S3 noSharpEdges carves the upper bulb so it drains completely
    std::uint64_t memoryLimit = 0; ///< model: bytes a scene may use; 0 = the memory available now
    std::vector<PartRoleChoice> partRoles; ///< model: S7 roles the user set (--part NAME=ROLE); others automatic
    std::string upAxis;         ///< model: S9 "+x" ... "-z" (--up); empty = found (hourglass) or +y (sculpture)
    bool sandbox = false;       ///< canvas: the sandbox, a bed of sand over the floor to dig in (--scene sandbox)
};

/// Everything that decides a scene and its steps: the request and the library's step settings
/// (seed, threads, sleeping), embedded rather than copied field by field.
struct SceneSettings {
    SceneRequest request;        ///< scene kind, model file or procedural shape, resolution, fill
    sandcore::StepSettings step; ///< seed, threads and sleeping of every step
};

/// Gives every unset value of settings its default (resolution, the scene's default model when
/// neither a model nor a shape is named) and checks every value against its range and the
/// combinations (a canvas takes no model or shape; a model excludes a shape). Throws
/// std::invalid_argument with one line naming the option, e.g. "--res must lie in 8..4096, got 4".
/// The command line, the panel and the benchmark all call it before building.
void applySceneDefaults(SceneSettings& settings);

/// A scene and, when it came from a model file, the voxelization report the GUI and CLI show.
struct BuiltScene {
    /// A scene without a model report.
    explicit BuiltScene(sandcore::Scene built) : scene(std::move(built)) {}
    sandcore::Scene scene;                  ///< ready to step
    std::optional<ModelVoxelization> model; ///< set when request.modelPath was given
    std::int64_t noiseCellsRemoved = 0;     ///< cells the S3 noNoise clean-up removed from the model
    std::vector<PartSummary> parts;         ///< S7: the model's parts with their roles; empty without a model
    VesselKind vessel = VesselKind::Solid;  ///< S8, W2: hourglass from a model: where its sand lives
    int closingCells = 0;                   ///< W2: gaps in the walls closed to find the sand space, cells
    bool neckOpened = false;                ///< W2: a neck under a cell was opened to one cell
    std::int64_t modelledSandCells = 0;     ///< W1: cells of modelled sand in the sand space (0: filled by --fill)
    std::string note;                       ///< W5: why no hourglass was found and what was done instead; empty otherwise
    std::optional<sandcore::UpAxis> upAxis; ///< S9: the model axis turned up; set when a model was loaded
    bool upAxisFound = false;               ///< S9: the up axis was found, not given
    double cavityMilliseconds = 0.0;        ///< S8: time of the walls' voxelization and cavity search, ms
    std::int64_t sandSpaceCells = 0;        ///< cells sand may take (hourglass: both bulbs; sculpture: the model)
    /// S10: the model's parts as modelled, in the scene's world cells (upright); null without a
    /// model or when no part is drawn (a sculpture that is all sand).
    std::shared_ptr<const ModelDrawing> drawing;
    /// W6: how the model's points became world cells (and back); set when a model was loaded.
    std::optional<ModelToWorld> modelToWorld;
};

/// "hourglass", "sculpture", "canvas" or "sandbox" (a canvas) to a scene kind; throws
/// std::invalid_argument otherwise.
sandcore::SceneKind parseSceneKind(std::string_view name);
/// Sets the request's kind and sandbox flag from a scene's name (as parseSceneKind).
void applySceneName(SceneRequest& request, std::string_view name);
/// The name of the scene a request asks for: sceneKindName, or "sandbox".
const char* sceneNameOf(const SceneRequest& request);
/// The name parseSceneKind accepts for a kind.
const char* sceneKindName(sandcore::SceneKind kind);

/// Throws std::invalid_argument unless shape names a procedural shape ("sphere", "cube", "hourglass").
void requireKnownShape(std::string_view shape);

/// The procedural mask named by shape ("sphere", "cube", "hourglass"); throws std::invalid_argument
/// for an unknown name or an invalid resolution.
sandcore::InsideMask makeProceduralMask(std::string_view shape, int resolution, float neckRadius);

/// Builds the requested scene from settings that applySceneDefaults accepted; throws
/// std::invalid_argument (or ModelError, "FILE: cause", for a model) with a one-line message on
/// bad input. Nothing is changed on failure.
sandcore::Scene buildScene(const SceneSettings& settings);

/// As buildScene, also returning the model's voxelization report. SPEC I5: passes `progress`
/// (when given) through each phase up to Done, and throws BuildCancelled at the first phase
/// after its cancel was asked.
BuiltScene buildSceneWithReport(const SceneSettings& settings, BuildProgress* progress = nullptr);

/// The resolution a scene gets when none is asked for: 64 cells, the canvas 60 (R10's 60x10x60 over 60x40x60).
int defaultResolution(sandcore::SceneKind kind);

/// The bundled one-surface vessel, models/hourglass.obj in the source tree (the voxelizer's benchmark shape).
std::string defaultModelPath();

/// The model a scene shows when the user names none: models/framed_hourglass.obj for the hourglass,
/// models/snowman.obj for the sculpture, none (empty) for the canvas.
std::string defaultModelFor(sandcore::SceneKind kind);

} // namespace sandglass
