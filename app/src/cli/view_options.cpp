#include "app/cli/view_options.hpp"

#include <cstdio>
#include <stdexcept>

namespace sandglass {

void addViewOptions(CLI::App& command, ViewOptions& options) {
    command.add_option("--scene", options.scene, "hourglass, sculpture or canvas")->capture_default_str();
    command.add_option("--model", options.model, "model file (OBJ, STL, PLY, glTF, ...) as vessel or sculpture");
    command.add_option("--shape", options.shape, "procedural shape: hourglass, sphere or cube (default per scene)");
    command.add_option("--res", options.resolution,
                       "cells along the shape's largest extent (default 64; the canvas: its width, default 60)")
        ->check(CLI::Range(1, 1 << 20));
    command.add_option("--seed", options.seed, "seed of the slip randomness")->capture_default_str();
    command.add_option("--mode", options.mode, "points, sprites, billboards or pseudo")->capture_default_str();
    command.add_option("--grains-per-cell", options.grainsPerCell, "grains drawn per cell, 1..32")
        ->capture_default_str()
        ->check(CLI::Range(1, kMaxGrainsPerCell));
    command.add_flag("--light", options.light, "lighting from estimated normals");
    command.add_flag("--no-inner", options.hideInner, "skip grains hidden by their neighbours");
    command.add_flag("--black", options.black, "black background (default white)");
    command.add_flag("--no-hull", options.noHull, "do not draw the glass vessel");
    command.add_option("--size", options.size, "window or image size in pixels, WxH");
    command.add_option("--steps", options.steps, "simulation steps before the first frame")
        ->check(CLI::NonNegativeNumber);
    command.add_option("--zoom", options.zoom, "camera distance as a share of the framing distance (0.5 = twice as close)")
        ->check(CLI::Range(0.05, 20.0));
}

ApplicationOptions applicationOptionsFrom(const ViewOptions& options, int defaultWidth, int defaultHeight) {
    ApplicationOptions result;
    AppState& state = result.initial;
    state.scene.request.kind = parseSceneKind(options.scene);
    state.scene.request.shape = options.shape;
    if (!options.model.empty() && !options.shape.empty())
        throw std::invalid_argument("choose either --model or --shape");
    state.scene.request.modelPath = options.model;
    requireNoShapeForCanvas(state.scene.request);
    if (options.model.empty() && options.shape.empty())
        state.scene.request.modelPath = defaultModelFor(state.scene.request.kind);
    state.scene.request.resolution =
        options.resolution != 0 ? options.resolution : defaultResolution(state.scene.request.kind);
    state.scene.seed = options.seed;
    const std::optional<RenderMode> mode = parseRenderMode(options.mode);
    if (!mode) throw std::invalid_argument("unknown mode '" + options.mode + "' (points, sprites, billboards or pseudo)");
    state.render.mode = *mode;
    state.render.grainsPerCell = options.grainsPerCell;
    state.render.lighting = options.light;
    state.render.innerGrains = !options.hideInner;
    state.render.blackBackground = options.black;
    state.render.hull = !options.noHull;
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
    return result;
}

} // namespace sandglass
