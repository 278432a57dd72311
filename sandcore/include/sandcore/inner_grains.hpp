#pragma once
// R13: inner grains ("innere Partikel", §3.8): a grain whose 6 face neighbours are all grains,
// INVALID or outside its grid cannot be seen, so the renderer may skip it.

#include "sandcore/scene.hpp"

#include <span>

namespace sandcore {

/// True when the grain in `cell` is hidden by its 6 face neighbours.
bool isInnerCell(const CellGrid& grid, std::uint32_t cell);

/// Writes 1 for every inner grain and 0 for the others (out.size() >= grainCount()); returns
/// the number of inner grains.
std::int64_t flagInnerGrains(const Scene& scene, std::span<std::uint8_t> out);

} // namespace sandcore
