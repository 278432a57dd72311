// SPDX-License-Identifier: MIT
#include "sandcore/grain_store.hpp"

namespace sandcore {

void GrainStore::clear() {
    level.clear();
    place.clear();
    identity.clear();
    color.clear();
    for (FallStates& grid : fall) grid.clear();
}

void GrainStore::reserve(std::uint32_t count) {
    level.reserve(count);
    place.reserve(count);
    identity.reserve(count);
    color.reserve(count);
    for (FallStates& grid : fall) grid.reserve(count);
}

std::uint32_t GrainStore::add(GridLevel where, std::uint32_t cellIndex, std::uint32_t grainIdentity,
                              std::uint32_t rgba) {
    level.push_back(where);
    place.push_back({cellIndex, kNoMove, 0});
    identity.push_back(grainIdentity);
    color.push_back(rgba);
    for (FallStates& grid : fall) grid.push_back({});
    return std::uint32_t(place.size() - 1);
}

std::uint32_t GrainStore::removeBySwap(std::uint32_t id) {
    const std::uint32_t last = size() - 1;
    level[id] = level[last];
    place[id] = place[last];
    identity[id] = identity[last];
    color[id] = color[last];
    for (FallStates& grid : fall) grid[id] = grid[last];
    level.pop_back();
    place.pop_back();
    identity.pop_back();
    color.pop_back();
    for (FallStates& grid : fall) grid.pop_back();
    return last;
}

} // namespace sandcore
