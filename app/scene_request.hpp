#pragma once
// What the user asked for (scene kind, shape, resolution), turned into a sandcore::Scene. The
// command line, the benchmark and the window all build scenes through here.

#include "sandcore/inside_mask.hpp"
#include "sandcore/scene.hpp"

#include <string>
#include <string_view>

namespace sandglass {

/// A scene as the user describes it.
struct SceneRequest {
    sandcore::SceneKind kind = sandcore::SceneKind::Hourglass; ///< which of the three scenes
    std::string shape;          ///< procedural shape: "sphere", "cube" or "hourglass"; empty = the scene's default
    int resolution = 64;        ///< cells along the shape's largest extent (the canvas: its width)
    float neckRadius = 0.0f;    ///< procedural hourglass neck radius in cells; 0 = resolution / 24, at least 1.5
    float fillFraction = 0.85f; ///< share of the upper bulb filled at reset (hourglass)
};

/// "hourglass", "sculpture" or "canvas" to a scene kind; throws std::invalid_argument otherwise.
sandcore::SceneKind parseSceneKind(std::string_view name);
/// The name parseSceneKind accepts for a kind.
const char* sceneKindName(sandcore::SceneKind kind);

/// The procedural mask named by shape ("sphere", "cube", "hourglass"); throws std::invalid_argument
/// for an unknown name or an invalid resolution.
sandcore::InsideMask makeProceduralMask(std::string_view shape, int resolution, float neckRadius);

/// Builds the requested scene; throws std::invalid_argument with a one-line message on bad input.
sandcore::Scene buildScene(const SceneRequest& request, const sandcore::StepSettings& step);

} // namespace sandglass
