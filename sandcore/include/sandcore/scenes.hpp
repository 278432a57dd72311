// SPDX-License-Identifier: MIT
#pragma once
// The one place where the three scenes of R10 are set up, shared by the tests, the command
// line, the benchmark and the application.

#include "sandcore/inside_mask.hpp"
#include "sandcore/scene.hpp"
#include "sandcore/scene_geometry.hpp"

namespace sandcore {

/// R10 hourglass options.
struct HourglassSettings {
    float fillFraction = 0.85f;   ///< share of the upper bulb's cells filled at reset, from the neck up (0..1]
    bool drainCompletely = true;  ///< S3: carve both bulbs with removeSharpEdges (the lower one upside down) so no sand stays behind, turned over or not
    /// Fill no more than the heap under the neck can take in the lower bulb (a pyramid of
    /// 45-degree faces), so all the sand runs through a lower bulb that is wide and flat. Off for
    /// shapes made to fit (the procedural hourglass); on for models from files (W1).
    bool fitLowerBulb = false;
};

/// The shape of the scenes a kind's recipe builds: the hourglass has a neck with Beverloo flow
/// and turns over (no bodies); the sculpture and the canvas are an open box under the grid the
/// sand starts in, and take moving bodies. A scene saved with its kind is built again with this.
SceneShape sceneShapeOf(SceneKind kind);

/// An empty canvas (MODE_PAINT). Throws std::invalid_argument for invalid sizes or unequal x/z.
Scene makeCanvasScene(const CanvasSettings& canvas = {}, const StepSettings& step = {});

/// The sandbox: a canvas whose painting box starts with a bed of sand `bedDepth` layers deep over
/// its whole floor, for moving bodies to dig in. The bed is added as grains, not as a fill:
/// reset() empties the box as it empties a canvas. Throws std::invalid_argument for sizes the
/// canvas refuses or a depth outside 1..the box's height.
Scene makeSandboxScene(const CanvasSettings& canvas, int bedDepth, const StepSettings& step = {});
/// The bed depth the sandbox gets by default: a third of the painting box's height, at least 1.
int defaultSandboxBedDepth(const CanvasSettings& canvas);

/// An hourglass from a vessel's inside mask (MODE_SHAPE + SHAPE_FIX): split at its neck (S4),
/// every outside cell INVALID, the upper bulb filled. A mask without a neck becomes an upper
/// vessel over an open lower box of the same height. Throws std::invalid_argument for an empty mask.
Scene makeHourglassScene(const InsideMask& vessel, const HourglassSettings& hourglass = {},
                         const StepSettings& step = {});

/// W1: as above, with the modelled sand `initialSand` (a mask of the vessel's size) as the sand
/// reset fills in place of the fill fraction: its cells in the upper bulb, and as many again
/// from the bottom up as carving the bulb (S3) took from it. An empty mask, or one that marks no
/// cell of the upper bulb, fills by the fraction.
Scene makeHourglassScene(const InsideMask& vessel, const InsideMask& initialSand, const HourglassSettings& hourglass,
                         const StepSettings& step);

/// A sculpture from a model's inside mask (MODE_SHAPE + SHAPE_LOSE): the grids of
/// sceneGridSizes(SceneKind::Sculpture, model.size), the upper one twice as wide and deep as the
/// model with the model filled in its middle; below it an EMPTY grid twice as wide, deep and
/// high as the model. Throws std::invalid_argument for an empty mask.
Scene makeSculptureScene(const InsideMask& model, const StepSettings& step = {});

/// S11: as makeSculptureScene, with the cells of `obstacles` (the model's static parts, a mask of
/// the model's size, or an empty mask for none) INVALID where the model is not: the sand
/// collapses onto and around them. Throws std::invalid_argument for a mask of another size.
Scene makeSculptureScene(const InsideMask& model, const InsideMask& obstacles, const StepSettings& step);

/// S10: where makeHourglassScene (kind Hourglass) or makeSculptureScene (kind Sculpture) puts the
/// cell (0, 0, 0) of the mask it is given, in world cells (the upper grid sits on the lower one,
/// sharing a row), so that a model can be drawn where its cells are. Throws
/// std::invalid_argument for an empty mask or a canvas.
Int3 maskOriginInScene(SceneKind kind, const InsideMask& mask);

/// The cell of the upper grid's top row over the grid's centre, where `simulate --pour` releases sand.
std::uint32_t pourCell(const Scene& scene);

} // namespace sandcore
