#include "sandcore/grain_store.hpp"

namespace sandcore {

void GrainStore::clear() {
    level.clear();
    cell.clear();
    cameFrom.clear();
    movedAtStep.clear();
    identity.clear();
    color.clear();
    for (std::vector<FallState>& grid : fall) grid.clear();
}

void GrainStore::reserve(std::uint32_t count) {
    level.reserve(count);
    cell.reserve(count);
    cameFrom.reserve(count);
    movedAtStep.reserve(count);
    identity.reserve(count);
    color.reserve(count);
    for (std::vector<FallState>& grid : fall) grid.reserve(count);
}

std::uint32_t GrainStore::add(GridLevel where, std::uint32_t cellIndex, std::uint32_t grainIdentity,
                              std::uint32_t rgba) {
    level.push_back(where);
    cell.push_back(cellIndex);
    cameFrom.push_back(kNoMove);
    movedAtStep.push_back(0);
    identity.push_back(grainIdentity);
    color.push_back(rgba);
    for (std::vector<FallState>& grid : fall) grid.push_back({});
    return std::uint32_t(cell.size() - 1);
}

std::uint32_t GrainStore::removeBySwap(std::uint32_t id) {
    const std::uint32_t last = size() - 1;
    level[id] = level[last];
    cell[id] = cell[last];
    cameFrom[id] = cameFrom[last];
    movedAtStep[id] = movedAtStep[last];
    identity[id] = identity[last];
    color[id] = color[last];
    for (std::vector<FallState>& grid : fall) grid[id] = grid[last];
    level.pop_back();
    cell.pop_back();
    cameFrom.pop_back();
    movedAtStep.pop_back();
    identity.pop_back();
    color.pop_back();
    for (std::vector<FallState>& grid : fall) grid.pop_back();
    return last;
}

} // namespace sandcore
