// SPDX-License-Identifier: MIT
#pragma once
// A moving body: a solid made of cells (a blade, a box, a ball, or any voxelized model) that the
// user or a program moves through the sand of a scene's lower grid between steps. Its cells are
// INVALID while it stands there, so the rules treat it as a wall; the scene moves it one cell at
// a time and pushes the grains in its way out of it (Scene::moveBody, docs/engine.md "Moving bodies").

#include "sandcore/inside_mask.hpp"
#include "sandcore/vec3.hpp"

#include <cstdint>
#include <vector>

namespace sandcore {

/// A body standing in a scene's lower grid.
struct MovingBody {
    /// Its cells in its own frame. The anchor, the cell that `position` names, is the mask's
    /// cell (size.x / 2, 0, size.z / 2): the middle of its bottom layer.
    InsideMask shape;
    Int3 position;        ///< the anchor's cell in the lower grid
    int quarterTurns = 0; ///< heading: quarter turns about the vertical, 0..3 (1 turns +x into +z)
};

/// What one call that moves, turns, places or removes a body did.
struct BodyMove {
    Int3 reached;                  ///< the anchor's cell afterwards
    int cellsMoved = 0;            ///< unit moves made (a turn or a placement counts 1)
    std::int64_t grainsPushed = 0; ///< grains pushed out of the cells the body entered
    bool stopped = false;          ///< a wall, the grid's edge or sand with no room left stopped it short
};

/// The offsets of a body's cells from its anchor, turned by quarterTurns about the vertical, in
/// the shape's index order.
std::vector<Int3> bodyOffsets(const InsideMask& shape, int quarterTurns);

/// A blade: a box `width` cells wide (along x at heading 0), `height` high and `thickness` thick
/// (along z). Throws std::invalid_argument for a size below 1.
InsideMask makeBladeShape(int width, int height, int thickness);
/// A box of `size` cells. Throws std::invalid_argument for a size below 1.
InsideMask makeBoxShape(Int3 size);
/// A ball `diameter` cells across. Throws std::invalid_argument for a diameter below 1.
InsideMask makeBallShape(int diameter);

} // namespace sandcore
