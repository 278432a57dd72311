// SPDX-License-Identifier: MIT
#pragma once
// Options shared by `sandglass gui` and `sandglass render`: which scene, how it is drawn, and
// the window size, turned into the application's start settings.

#include "app/application.hpp"
#include "app/cli/scene_options.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace sandglass {

/// Scene and display choices as typed on the command line.
struct ViewOptions {
    SceneOptions scene;               ///< scene, model or shape, resolution, seed, threads
    std::string mode;                 ///< points, sprites, billboards or pseudo; empty: the look's (pseudo, or points with --thesis-look)
    std::string palette = "desert";   ///< S12: desert, beach, white, volcanic or layers
    int grainsPerCell = 4;            ///< 1..32
    bool light = false;               ///< --light: grains lit from estimated normals (the default unless --thesis-look)
    bool unlit = false;               ///< --unlit: flat colours (the thesis's default)
    std::string lights = "studio";    ///< studio (warm key, cool fill, sky) or thesis (white light near the camera)
    bool thesisLook = false;          ///< start from the thesis's look: unlit points, thesis light, no studio elements
    bool noOcclusion = false;         ///< --no-ao
    bool noShadows = false;           ///< --no-shadows
    bool noToneMapping = false;       ///< --no-tone-map
    bool noEnvironment = false;       ///< --no-env
    std::string normals = "gradient"; ///< R12: gradient (occupancy gradient) or columns (the thesis's column heights)
    bool hideInner = false;           ///< skip inner grains
    bool black = false;               ///< black background
    bool noHull = false;              ///< no glass
    bool voxelHull = false;           ///< S10: the voxel hull instead of the model as modelled
    std::string size;                 ///< "WxH" in pixels; empty = the command's default
    int steps = 0;                    ///< simulation steps before the first frame
    float zoom = 1.0f;                ///< camera distance as a share of the distance that frames the scene
    std::string dig;                  ///< sandbox: a path "X,Y,Z ..." a body digs along during the steps
    std::string digBody = "blade";    ///< blade, box, ball or a model file
    int digSpeed = 1;                 ///< cells the body moves per step
};

/// Adds the scene options and --mode --grains-per-cell --light --unlit --lights --thesis-look --no-ao
/// --no-shadows --no-tone-map --no-env --normals --no-inner --black --no-hull --size --steps --zoom
/// to a subcommand.
void addViewOptions(CLI::App& command, ViewOptions& options);

/// Application options from the typed ones; throws std::invalid_argument with one line on a bad value.
/// Without --model and --shape the hourglass is models/hourglass.obj and the sculpture models/snowman.obj.
ApplicationOptions applicationOptionsFrom(const ViewOptions& options, int defaultWidth, int defaultHeight);

} // namespace sandglass
