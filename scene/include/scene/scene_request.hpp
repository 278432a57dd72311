#pragma once
// What the user asked for (scene kind, shape, resolution), turned into a sandcore::Scene. The
// command line, the benchmark and the window all build scenes through here.

#include "scene/model_voxelizer.hpp"

#include "sandcore/inside_mask.hpp"
#include "sandcore/scene.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace sandglass {

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
};

/// A scene and, when it came from a model file, the voxelization report the GUI and CLI show.
struct BuiltScene {
    sandcore::Scene scene;                  ///< ready to step
    std::optional<ModelVoxelization> model; ///< set when request.modelPath was given
    std::int64_t noiseCellsRemoved = 0;     ///< cells the S3 noNoise clean-up removed from the model
};

/// "hourglass", "sculpture" or "canvas" to a scene kind; throws std::invalid_argument otherwise.
sandcore::SceneKind parseSceneKind(std::string_view name);
/// The name parseSceneKind accepts for a kind.
const char* sceneKindName(sandcore::SceneKind kind);

/// Throws std::invalid_argument unless shape names a procedural shape ("sphere", "cube", "hourglass").
void requireKnownShape(std::string_view shape);

/// The procedural mask named by shape ("sphere", "cube", "hourglass"); throws std::invalid_argument
/// for an unknown name or an invalid resolution.
sandcore::InsideMask makeProceduralMask(std::string_view shape, int resolution, float neckRadius);

/// The command line's check that a canvas request names no model or shape (the window simply
/// ignores them when the user switches to the canvas); throws std::invalid_argument.
void requireNoShapeForCanvas(const SceneRequest& request);

/// Builds the requested scene (a canvas ignores modelPath and shape); throws std::invalid_argument (or ModelError, "FILE: cause", for a
/// model) with a one-line message on bad input. Nothing is changed on failure.
sandcore::Scene buildScene(const SceneRequest& request, const sandcore::StepSettings& step);

/// As buildScene, also returning the model's voxelization report.
BuiltScene buildSceneWithReport(const SceneRequest& request, const sandcore::StepSettings& step);

/// The resolution a scene gets when none is asked for: 64 cells, the canvas 60 (R10's 60x10x60 over 60x40x60).
int defaultResolution(sandcore::SceneKind kind);

/// The bundled default vessel, models/hourglass.obj in the source tree.
std::string defaultModelPath();

/// The model a scene shows when the user names none: models/hourglass.obj for the hourglass,
/// models/snowman.obj for the sculpture, none (empty) for the canvas.
std::string defaultModelFor(sandcore::SceneKind kind);

} // namespace sandglass
