// SPDX-License-Identifier: MIT
#pragma once
// The cells of a ball in its bounding box, shared by the sphere sculpture and the digger's ball.
// Private to sandcore.

#include "sandcore/inside_mask.hpp"

namespace sandcore {

/// A box of `diameter` cells a side whose cells are set where the cell centre lies within the
/// box's inscribed ball, its squared radius widened by `slackSquared` (cells squared). diameter >= 1.
InsideMask ballCells(int diameter, double slackSquared);

} // namespace sandcore
