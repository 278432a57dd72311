// SPDX-License-Identifier: MIT
#include "sandcore/inside_mask.hpp"

#include "sandcore/cell_grid.hpp"

#include <algorithm>

namespace sandcore {

InsideMask InsideMask::empty(Int3 size) {
    validateGridSize(size);
    InsideMask mask;
    mask.size = size;
    mask.inside.assign(std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z), 0);
    return mask;
}

std::int64_t InsideMask::countInside() const { return std::count(inside.begin(), inside.end(), std::uint8_t{1}); }

std::int64_t InsideMask::countInsideLayer(int y) const {
    const auto layer = std::size_t(size.x) * std::size_t(size.z);
    const auto first = inside.begin() + std::ptrdiff_t(layer * std::size_t(y));
    return std::count(first, first + std::ptrdiff_t(layer), std::uint8_t{1});
}

} // namespace sandcore
