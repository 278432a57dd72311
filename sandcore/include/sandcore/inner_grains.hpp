// SPDX-License-Identifier: MIT
#pragma once
// R13: inner grains ("innere Partikel", §3.8): a grain whose 6 face neighbours are all grains,
// INVALID or outside its grid cannot be seen, so the renderer may skip it.

#include "sandcore/scene.hpp"

#include <span>

namespace sandcore {

/// True when the grain in `cell` is hidden by its 6 face neighbours within one grid.
bool isInnerCell(const CellGrid& grid, std::uint32_t cell);

/// As isInnerCell, but across the seam of the scene's two grids: above the lower grid's top row
/// lies the upper grid's layer 1, below the upper grid's layer 0 the lower grid's second row from
/// the top (the two grids share one row, R4).
bool isInnerGrain(const Scene& scene, GridLevel level, std::uint32_t cell);

/// Writes 1 for every inner grain (isInnerGrain) and 0 for the others (out.size() >= grainCount()); returns
/// the number of inner grains.
std::int64_t flagInnerGrains(const Scene& scene, std::span<std::uint8_t> out);

} // namespace sandcore
