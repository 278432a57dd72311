// SPDX-License-Identifier: MIT
#pragma once
// SPEC S4: where an hourglass mask is cut into its upper and lower grid.

#include "sandcore/inside_mask.hpp"

namespace sandcore {

/// The neck: the layer with the smallest non-empty inside cross-section within the middle part
/// of the mask's height (from 25% to 75%); ties go to the layer nearest the middle. Returns -1
/// when that part holds no inside cell. A mask whose narrowest middle layer is not narrower
/// than both the widest layer above and the widest layer below has no neck; see hasNeck().
int findNeckLayer(const InsideMask& mask);

/// True when the neck layer is strictly narrower than the widest layer above it and the
/// widest layer below it (an hourglass, not a plain vessel).
bool hasNeck(const InsideMask& mask, int neckLayer);

/// Layers [fromLayer, toLayer] of a mask as a mask of their own (y renumbered from 0).
InsideMask sliceLayers(const InsideMask& mask, int fromLayer, int toLayer);

} // namespace sandcore
