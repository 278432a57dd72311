// SPDX-License-Identifier: MIT
#pragma once
// Clean-up of voxel masks (thesis §3.4, SPEC S3).

#include "sandcore/inside_mask.hpp"

namespace sandcore {

/// thesis §3.4 noNoise: removes every inside cell with at most `threshold` inside face
/// neighbours (of 6), repeated until nothing changes. Returns the number of cells removed.
std::int64_t removeNoise(InsideMask& mask, int threshold);

/// thesis §3.4 noSharpEdges (Abb. 23): in layers [fromLayer, toLayer] of the mask, from the
/// bottom up, removes inside cells that have no inside successor (none of the 9 cells below
/// within +-1 in x and z), except on the outlet layer fromLayer itself; repeated until nothing
/// changes, so sand resting on the region's floor always finds a way down. Returns the number
/// of cells removed.
std::int64_t removeSharpEdges(InsideMask& mask, int fromLayer, int toLayer);

} // namespace sandcore
