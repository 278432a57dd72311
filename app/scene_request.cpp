#include "scene_request.hpp"

#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"

#include <algorithm>
#include <stdexcept>

namespace sandglass {

using sandcore::SceneKind;

SceneKind parseSceneKind(std::string_view name) {
    if (name == "hourglass") return SceneKind::Hourglass;
    if (name == "sculpture") return SceneKind::Sculpture;
    if (name == "canvas") return SceneKind::Canvas;
    throw std::invalid_argument("unknown scene '" + std::string(name) + "' (hourglass, sculpture or canvas)");
}

const char* sceneKindName(SceneKind kind) {
    switch (kind) {
    case SceneKind::Hourglass: return "hourglass";
    case SceneKind::Sculpture: return "sculpture";
    case SceneKind::Canvas: return "canvas";
    }
    return "hourglass";
}

sandcore::InsideMask makeProceduralMask(std::string_view shape, int resolution, float neckRadius) {
    if (shape == "sphere") return sandcore::makeSphereMask(resolution);
    if (shape == "cube") return sandcore::makeCubeMask(resolution);
    if (shape == "hourglass") {
        sandcore::HourglassShape hourglass;
        hourglass.height = resolution;
        hourglass.neckRadius = neckRadius > 0.0f ? neckRadius : std::max(1.5f, float(resolution) / 24.0f);
        return sandcore::makeHourglassMask(hourglass);
    }
    throw std::invalid_argument("unknown shape '" + std::string(shape) + "' (sphere, cube or hourglass)");
}

sandcore::Scene buildScene(const SceneRequest& request, const sandcore::StepSettings& step) {
    if (request.resolution < 8)
        throw std::invalid_argument("resolution must be at least 8 cells, got " + std::to_string(request.resolution));
    if (request.kind == SceneKind::Canvas) {
        sandcore::CanvasSettings canvas;
        const int r = request.resolution;
        canvas.upperSize = {r, std::max(2, r / 6), r};
        canvas.lowerSize = {r, std::max(2, r * 2 / 3), r};
        return sandcore::makeCanvasScene(canvas, step);
    }
    const bool hourglass = request.kind == SceneKind::Hourglass;
    const std::string shape = !request.shape.empty() ? request.shape : hourglass ? "hourglass" : "sphere";
    const sandcore::InsideMask mask = makeProceduralMask(shape, request.resolution, request.neckRadius);
    if (!hourglass) return sandcore::makeSculptureScene(mask, step);
    sandcore::HourglassSettings settings;
    settings.fillFraction = request.fillFraction;
    return sandcore::makeHourglassScene(mask, settings, step);
}

} // namespace sandglass
