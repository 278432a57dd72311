#include "scene_request.hpp"

#include "model/mesh_loader.hpp"

#include "sandcore/mask_cleanup.hpp"
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

std::string defaultModelPath() { return std::string(SANDGLASS_SOURCE_DIR) + "/models/hourglass.obj"; }

std::string defaultModelFor(SceneKind kind) {
    switch (kind) {
    case SceneKind::Hourglass: return defaultModelPath();
    case SceneKind::Sculpture: return std::string(SANDGLASS_SOURCE_DIR) + "/models/snowman.obj";
    case SceneKind::Canvas: return {};
    }
    return {};
}

BuiltScene buildSceneWithReport(const SceneRequest& request, const sandcore::StepSettings& step) {
    if (request.resolution < 8)
        throw std::invalid_argument("resolution must be at least 8 cells, got " + std::to_string(request.resolution));
    if (request.kind == SceneKind::Canvas) {
        sandcore::CanvasSettings canvas;
        const int r = request.resolution;
        canvas.upperSize = {r, std::max(2, r / 6), r};
        canvas.lowerSize = {r, std::max(2, r * 2 / 3), r};
        return {sandcore::makeCanvasScene(canvas, step), std::nullopt, 0};
    }
    const bool hourglass = request.kind == SceneKind::Hourglass;
    sandcore::HourglassSettings settings;
    settings.fillFraction = request.fillFraction;
    settings.drainCompletely = request.drainCompletely;
    if (request.modelPath.empty()) {
        const std::string shape = !request.shape.empty() ? request.shape : hourglass ? "hourglass" : "sphere";
        const sandcore::InsideMask mask = makeProceduralMask(shape, request.resolution, request.neckRadius);
        if (!hourglass) return {sandcore::makeSculptureScene(mask, step), std::nullopt, 0};
        return {sandcore::makeHourglassScene(mask, settings, step), std::nullopt, 0};
    }
    if (request.noiseThreshold > 5)
        throw std::invalid_argument("noise threshold must lie in -1..5, got " + std::to_string(request.noiseThreshold));
    sandcore::VoxelizeSettings voxelize;
    voxelize.resolution = request.resolution;
    voxelize.stretch = request.stretch;
    voxelize.robust = request.robust;
    voxelize.threads = std::max(1, step.threads);
    ModelVoxelization model = voxelizeModelFile(request.modelPath, voxelize,
                                                hourglass ? ModelUse::Hourglass : ModelUse::Sculpture,
                                                request.memoryLimit);
    sandcore::InsideMask mask = model.voxels.mask;
    // thesis §3.4 noNoise: single cells and spikes left by discretisation; the hourglass split then
    // carves the upper bulb with noSharpEdges (makeHourglassScene).
    const std::int64_t removed = request.noiseThreshold >= 0 ? sandcore::removeNoise(mask, request.noiseThreshold) : 0;
    if (mask.countInside() == 0)
        throw ModelError(request.modelPath, "no cell lies inside the model at resolution " +
                                                std::to_string(request.resolution) +
                                                (model.voxels.closedness.closed ? "" : " (the mesh is open; try --robust)"));
    try {
        sandcore::Scene scene = hourglass ? sandcore::makeHourglassScene(mask, settings, step)
                                          : sandcore::makeSculptureScene(mask, step);
        return {std::move(scene), std::move(model), removed};
    } catch (const std::invalid_argument& e) {
        throw ModelError(request.modelPath, e.what());
    }
}

sandcore::Scene buildScene(const SceneRequest& request, const sandcore::StepSettings& step) {
    return std::move(buildSceneWithReport(request, step).scene);
}

} // namespace sandglass
