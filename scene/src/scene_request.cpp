// SPDX-License-Identifier: MIT
#include "scene/scene_request.hpp"

#include "scene/data_paths.hpp"
#include "scene/mesh_loader.hpp"

#include "sandcore/mask_cleanup.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scene_geometry.hpp"
#include "sandcore/scenes.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <type_traits>

namespace sandglass {

using sandcore::SceneKind;

SceneKind parseSceneKind(std::string_view name) {
    if (name == "hourglass") return SceneKind::Hourglass;
    if (name == "sculpture") return SceneKind::Sculpture;
    if (name == "canvas" || name == "sandbox") return SceneKind::Canvas;
    throw std::invalid_argument("unknown scene '" + std::string(name) + "' (hourglass, sculpture, canvas or sandbox)");
}

void applySceneName(SceneRequest& request, std::string_view name) {
    request.kind = parseSceneKind(name);
    request.sandbox = name == "sandbox";
}

const char* sceneNameOf(const SceneRequest& request) {
    return request.kind == SceneKind::Canvas && request.sandbox ? "sandbox" : sceneKindName(request.kind);
}

const char* sceneKindName(SceneKind kind) {
    switch (kind) {
    case SceneKind::Hourglass: return "hourglass";
    case SceneKind::Sculpture: return "sculpture";
    case SceneKind::Canvas: return "canvas";
    }
    return "hourglass";
}

void requireKnownShape(std::string_view shape) {
    if (shape != "sphere" && shape != "cube" && shape != "hourglass")
        throw std::invalid_argument("unknown shape '" + std::string(shape) + "' (sphere, cube or hourglass)");
}

sandcore::InsideMask makeProceduralMask(std::string_view shape, int resolution, float neckRadius) {
    requireKnownShape(shape);
    if (shape == "sphere") return sandcore::makeSphereMask(resolution);
    if (shape == "cube") return sandcore::makeCubeMask(resolution);
    if (shape == "hourglass") {
        sandcore::HourglassShape hourglass;
        hourglass.height = resolution;
        hourglass.neckRadius = neckRadius > 0.0f ? neckRadius : sandcore::defaultNeckRadius(resolution);
        return sandcore::makeHourglassMask(hourglass);
    }
    throw std::invalid_argument("unknown shape '" + std::string(shape) + "' (sphere, cube or hourglass)");
}

std::string defaultModelPath() { return (modelsFolder() / "hourglass.obj").string(); }

std::string defaultModelFor(SceneKind kind) {
    switch (kind) {
    // SPEC S12: the default scene shows a glass with thickness in its frame (S7-S10).
    case SceneKind::Hourglass: return (modelsFolder() / "framed_hourglass.obj").string();
    case SceneKind::Sculpture: return (modelsFolder() / "snowman.obj").string();
    case SceneKind::Canvas: return {};
    }
    return {};
}

int defaultResolution(SceneKind kind) { return kind == SceneKind::Canvas ? 60 : 64; }

namespace {

std::string gibibytes(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1ull << 30));
    return text;
}

// S1 for scenes without a model file: refuse before allocating what memory cannot hold.
void requireMemory(const std::string& what, int resolution, std::uint64_t needed, std::uint64_t memoryLimit) {
    const std::uint64_t limit = memoryLimit != 0 ? memoryLimit : availableMemoryBytes();
    if (limit != 0 && needed > limit)
        throw std::invalid_argument(what + " too large for memory at resolution " + std::to_string(resolution) +
                                    ": it needs about " + gibibytes(needed) + ", " + gibibytes(limit) +
                                    " available; choose a lower resolution");
}

sandcore::Int3 proceduralMaskSize(std::string_view shape, int resolution) {
    if (shape == "hourglass") return sandcore::hourglassMaskSize({resolution, 1.0f, 0.0f});
    return {resolution, resolution, resolution};
}

} // namespace

namespace {

template <class T> std::string valueText(T value) {
    if constexpr (std::is_floating_point_v<T>) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", double(value));
        return text;
    } else {
        return std::to_string(value);
    }
}

template <class T> void requireInRange(const SettingRange<T>& range, T value) {
    // Written so that NaN fails too.
    if (!(value >= range.min && value <= range.max))
        throw std::invalid_argument(std::string(range.option) + " must lie in " + valueText(range.min) + ".." +
                                    valueText(range.max) + ", got " + valueText(value));
}

} // namespace

void applySceneDefaults(SceneSettings& settings) {
    SceneRequest& request = settings.request;
    if (request.resolution == 0) request.resolution = defaultResolution(request.kind);
    requireInRange(kResolutionRange, request.resolution);
    requireInRange(kThreadsRange, settings.step.threads);
    requireInRange(kNeckRadiusRange, double(request.neckRadius));
    requireInRange(kFillRange, double(request.fillFraction));
    requireInRange(kNoiseRange, request.noiseThreshold);
    requireInRange(kReposeRange, double(settings.step.physics.reposeDegrees));
    requireInRange(kGravityRange, double(settings.step.physics.gravity));
    if (!request.modelPath.empty() && !request.shape.empty()) throw std::invalid_argument("choose either --model or --shape");
    if (!request.shape.empty()) requireKnownShape(request.shape);
    if (request.kind == SceneKind::Canvas && (!request.modelPath.empty() || !request.shape.empty()))
        throw std::invalid_argument("the canvas takes no model or shape (they are for the hourglass and the sculpture)");
    if (!request.upAxis.empty() && !sandcore::parseUpAxis(request.upAxis))
        throw std::invalid_argument("--up must be one of +x, -x, +y, -y, +z, -z, got '" + request.upAxis + "'");
    if (request.modelPath.empty() && (!request.upAxis.empty() || !request.partRoles.empty()))
        throw std::invalid_argument(std::string(request.upAxis.empty() ? "--part" : "--up") + " applies to a model file (--model)");
}

// Every phase but Done; buildSceneWithReport passes that last checkpoint whichever way the scene was made.
static BuiltScene buildSceneUntilDone(const SceneSettings& requested, BuildProgress* progress) {
    SceneSettings checked = requested;
    applySceneDefaults(checked);
    const SceneRequest& request = checked.request;
    const sandcore::StepSettings& step = checked.step;
    const int resolution = request.resolution;
    if (request.kind == SceneKind::Canvas) {
        checkpoint(progress, BuildPhase::Filling);
        const sandcore::Int3 width{resolution, resolution, resolution};
        sandcore::validateSceneGridSizes(SceneKind::Canvas, width);
        requireMemory("the canvas is", resolution, sandcore::estimateSceneBytes(SceneKind::Canvas, width),
                      request.memoryLimit);
        const sandcore::CanvasSettings canvas = sandcore::canvasSettingsForWidth(resolution);
        if (request.sandbox)
            return BuiltScene(sandcore::makeSandboxScene(canvas, sandcore::defaultSandboxBedDepth(canvas), step));
        return BuiltScene(sandcore::makeCanvasScene(canvas, step));
    }
    const bool hourglass = request.kind == SceneKind::Hourglass;
    sandcore::HourglassSettings settings;
    settings.fillFraction = request.fillFraction;
    // A model's bulbs were not made to fit this program's piles; the procedural shapes were.
    settings.fitLowerBulb = !request.modelPath.empty();
    settings.drainCompletely = request.drainCompletely;
    if (request.modelPath.empty()) {
        checkpoint(progress, BuildPhase::Filling);
        const std::string shape = !request.shape.empty() ? request.shape : hourglass ? "hourglass" : "sphere";
        requireKnownShape(shape);
        const sandcore::Int3 size = proceduralMaskSize(shape, resolution);
        sandcore::validateSceneGridSizes(request.kind, size);
        requireMemory("the " + shape + " is", resolution, sandcore::estimateSceneBytes(request.kind, size),
                      request.memoryLimit);
        const sandcore::InsideMask mask = makeProceduralMask(shape, resolution, request.neckRadius);
        if (!hourglass) return BuiltScene(sandcore::makeSculptureScene(mask, step));
        return BuiltScene(sandcore::makeHourglassScene(mask, settings, step));
    }
    sandcore::VoxelizeSettings voxelize;
    voxelize.resolution = resolution;
    voxelize.stretch = request.stretch;
    voxelize.robust = request.robust;
    voxelize.threads = std::max(1, step.threads);
    ModelShapeRequest shape;
    shape.kind = request.kind;
    shape.roles = request.partRoles;
    if (!request.upAxis.empty()) shape.up = sandcore::parseUpAxis(request.upAxis);
    SandSpace space = loadSandSpace(request.modelPath, voxelize, hourglass ? ModelUse::Hourglass : ModelUse::Sculpture,
                                    shape, request.memoryLimit, progress);
    checkpoint(progress, BuildPhase::Filling);
    sandcore::InsideMask mask = std::move(space.space);
    // thesis §3.4 noNoise: single cells and spikes left by discretisation; the hourglass split then
    // carves the upper bulb with noSharpEdges (makeHourglassScene).
    const std::int64_t removed = request.noiseThreshold >= 0 ? sandcore::removeNoise(mask, request.noiseThreshold) : 0;
    if (mask.countInside() == 0)
        throw ModelError(request.modelPath, noCellInsideMessage(space.parts, space.model.voxels.placement, resolution,
                                                                space.model.voxels.closedness.closed));
    try {
        sandcore::Scene scene = !hourglass ? sandcore::makeSculptureScene(mask, space.obstacles, step)
                                : space.modelledSand.inside.empty()
                                    ? sandcore::makeHourglassScene(mask, settings, step)
                                    : sandcore::makeHourglassScene(mask, space.modelledSand, settings, step);
        BuiltScene built(std::move(scene));
        built.model = std::move(space.model);
        built.noiseCellsRemoved = removed;
        built.parts = summarize(space.parts);
        built.vessel = space.vessel;
        built.upAxis = space.up;
        built.upAxisFound = space.upFound;
        built.cavityMilliseconds = space.cavityMilliseconds;
        built.closingCells = space.closingCells;
        built.neckOpened = space.neckOpened;
        built.modelledSandCells = space.modelledSand.inside.empty() ? 0 : space.modelledSand.countInside();
        built.note = space.note;
        built.sandSpaceCells = mask.countInside();
        ModelToWorld toWorld{space.model.voxels.placement, space.up, sandcore::maskOriginInScene(request.kind, mask),
                             space.parts.front().fileCentre};
        const sandcore::Int3 upperOrigin = built.scene.gridOrigin(sandcore::GridLevel::Upper);
        const float height = float(upperOrigin.y + built.scene.grid(sandcore::GridLevel::Upper).size().y);
        built.modelToWorld = toWorld;
        ModelDrawing drawing = makeModelDrawing(space.parts, toWorld, height);
        if (!drawing.parts.empty()) built.drawing = std::make_shared<const ModelDrawing>(std::move(drawing));
        return built;
    } catch (const std::invalid_argument& e) {
        throw ModelError(request.modelPath, e.what());
    }
}

BuiltScene buildSceneWithReport(const SceneSettings& requested, BuildProgress* progress) {
    BuiltScene built = buildSceneUntilDone(requested, progress);
    checkpoint(progress, BuildPhase::Done);
    return built;
}

sandcore::Scene buildScene(const SceneSettings& settings) { return std::move(buildSceneWithReport(settings).scene); }

} // namespace sandglass
