// SPDX-License-Identifier: MIT
#pragma once
// The grid a model's sand space is searched in (InsideMask's layout: x fastest, then z, then y),
// with cells as indices and as (x, y, z). Private to sandcore.

#include "sandcore/inside_mask.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace sandcore {

struct Grid {
    Int3 size;
    std::size_t cells() const { return std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z); }
    std::array<int, 3> coordinates(std::uint32_t n) const {
        const std::size_t row = std::size_t(size.x), layer = row * std::size_t(size.z);
        return {int(n % row), int(n / layer), int((n / row) % std::size_t(size.z))};
    }
    std::uint32_t index(const std::array<int, 3>& c) const {
        return std::uint32_t(std::size_t(c[0]) + std::size_t(size.x) * (std::size_t(c[2]) + std::size_t(size.z) * std::size_t(c[1])));
    }
    int length(int axis) const { return axis == 0 ? size.x : axis == 1 ? size.y : size.z; }
};

} // namespace sandcore
