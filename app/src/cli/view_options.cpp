// SPDX-License-Identifier: MIT
#include "app/cli/view_options.hpp"

#include "scene/digger.hpp"

#include "app/cli/checked_options.hpp"

#include <cstdio>
#include <stdexcept>

namespace sandglass {

void addViewOptions(CLI::App& command, ViewOptions& options) {
    addSceneOptions(command, options.scene);
    command.add_option("--mode", options.mode, "points, sprites, billboards or pseudo (default pseudo; points with --thesis-look)");
    command.add_option("--palette", options.palette, "sand colours: desert, beach, white, volcanic or layers")
        ->capture_default_str();
    addNumberOption(command, "--grains-per-cell", options.grainsPerCell, 1, kMaxGrainsPerCell,
                    "grains drawn per cell (default 4)");
    command.add_flag("--light", options.light, "grains lit from estimated normals (the default; with --thesis-look: its light)");
    command.add_flag("--unlit", options.unlit, "grains in flat colours (the thesis's default)");
    command.add_option("--lights", options.lights,
                       "studio (warm key, cool fill, sky; default) or thesis (a white light near the camera, no elements)")
        ->capture_default_str();
    command.add_flag("--thesis-look", options.thesisLook,
                     "the thesis's look: unlit points, its light when lit, no occlusion, shadows, tone mapping or sky");
    command.add_flag("--no-ao", options.noOcclusion, "no ambient occlusion from the cells");
    command.add_flag("--no-shadows", options.noShadows, "no shadows of the key light");
    command.add_flag("--no-tone-map", options.noToneMapping, "light clamped, not tone mapped");
    command.add_flag("--no-env", options.noEnvironment, "glass without the reflected sky");
    command.add_option("--normals", options.normals,
                       "how --light estimates normals: gradient (of the occupancy, default) or columns (the thesis's column heights)")
        ->capture_default_str();
    command.add_flag("--no-inner", options.hideInner, "skip grains hidden by their neighbours");
    command.add_flag("--black", options.black, "black background (default white)");
    command.add_flag("--no-hull", options.noHull, "do not draw the glass vessel");
    command.add_flag("--voxel-hull", options.voxelHull, "draw a model's vessel as its voxel cells, not as modelled");
    command.add_option("--size", options.size, "window or image size in pixels, WxH");
    addNumberOption(command, "--steps", options.steps, 0, 100'000'000, "simulation steps before the first frame");
    auto* dig = command.add_option("--dig", options.dig,
                                   "sandbox: a body digs along this path of cells, \"X,Y,Z X,Y,Z ...\", during the steps");
    command.add_option("--dig-body", options.digBody, "with --dig: blade (default), box, ball or a model file")->needs(dig);
    addNumberOption(command, "--dig-speed", options.digSpeed, 1, kMaxDigSpeed, "with --dig: cells the body moves per step (default 1)")
        ->needs(dig);
    addNumberOption(command, "--zoom", options.zoom, 0.05f, 20.0f,
                    "camera distance as a share of the framing distance (0.5 = twice as close)");
}

ApplicationOptions applicationOptionsFrom(const ViewOptions& options, int defaultWidth, int defaultHeight) {
    ApplicationOptions result;
    AppState& state = result.initial;
    SceneOptions scene = options.scene;
    SceneRequest& request = scene.settings.request;
    // The window's default scenes are the bundled models, not the procedural shapes.
    if (request.modelPath.empty() && request.shape.empty()) request.modelPath = defaultModelFor(parseSceneKind(scene.scene));
    state.scene = sceneSettingsFrom(scene);
    state.render = options.thesisLook ? thesisLook() : RenderSettings{};
    if (!options.mode.empty()) {
        const std::optional<RenderMode> mode = parseRenderMode(options.mode);
        if (!mode) throw std::invalid_argument("--mode: unknown mode '" + options.mode + "' (points, sprites, billboards or pseudo)");
        state.render.mode = *mode;
    }
    if (options.light && options.unlit) throw std::invalid_argument("--light and --unlit contradict each other");
    if (options.light) state.render.lighting = true;
    if (options.unlit) state.render.lighting = false;
    if (!options.thesisLook || options.lights != "studio") {
        const std::optional<LightRig> rig = parseLightRig(options.lights);
        if (!rig) throw std::invalid_argument("--lights: unknown lights '" + options.lights + "' (studio or thesis)");
        state.render.light = *rig;
    }
    if (options.noOcclusion) state.render.ambientOcclusion = false;
    if (options.noShadows) state.render.shadows = false;
    if (options.noToneMapping) state.render.toneMapping = false;
    if (options.noEnvironment) state.render.glassEnvironment = false;
    const std::optional<SandPalette> palette = parseSandPalette(options.palette);
    if (!palette)
        throw std::invalid_argument("--palette: unknown palette '" + options.palette + "' (desert, beach, white, volcanic or layers)");
    state.render.palette = *palette;
    state.render.grainsPerCell = options.grainsPerCell;
    const std::optional<sandcore::NormalMethod> normals = parseNormalMethod(options.normals);
    if (!normals) throw std::invalid_argument("--normals: unknown method '" + options.normals + "' (gradient or columns)");
    state.render.normals = *normals;
    state.render.innerGrains = !options.hideInner;
    state.render.blackBackground = options.black;
    state.render.hull = !options.noHull;
    state.render.voxelHull = options.voxelHull;
    result.cameraZoom = options.zoom;
    result.window.width = defaultWidth;
    result.window.height = defaultHeight;
    if (!options.size.empty()) {
        int width = 0, height = 0;
        char extra = 0;
        if (std::sscanf(options.size.c_str(), "%dx%d%c", &width, &height, &extra) != 2 || width < 16 || height < 16 ||
            width > 8192 || height > 8192)
            throw std::invalid_argument("--size wants WxH with 16..8192 pixels each, got '" + options.size + "'");
        result.window.width = width;
        result.window.height = height;
    }
    result.stepsBeforeStart = options.steps;
    if (!options.dig.empty()) {
        if (state.scene.request.kind != sandcore::SceneKind::Canvas)
            throw std::invalid_argument("--dig drives a body through a canvas; use it with --scene sandbox or canvas");
        parseDigPath(options.dig); // a bad path is refused before the window opens
        result.digPath = options.dig;
        result.digBody = options.digBody;
        result.digSpeed = options.digSpeed;
    }
    return result;
}

} // namespace sandglass
