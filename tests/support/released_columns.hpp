// SPDX-License-Identifier: MIT
#pragma once
// Where painting released sand: the columns of the upper grid's top row that hold a grain.

#include "sandcore/scene.hpp"

#include <set>
#include <utility>

namespace support {

/// (x, z) of every top-row cell of the upper grid that holds a grain.
inline std::set<std::pair<int, int>> releasedColumns(const sandcore::Scene& scene) {
    std::set<std::pair<int, int>> columns;
    const auto& upper = scene.grid(sandcore::GridLevel::Upper);
    const sandcore::Int3 s = upper.size();
    for (int z = 0; z < s.z; ++z)
        for (int x = 0; x < s.x; ++x)
            if (upper.at(x, s.y - 1, z) >= 0) columns.insert({x, z});
    return columns;
}

} // namespace support
