// SPDX-License-Identifier: MIT
#pragma once
// The thesis's rules (§3.2, Abb. 13 and 16), private to sandcore: a grain falls to its direct
// successor when that cell is empty; otherwise it slips to one of its empty successors, chosen
// uniformly at random; INVALID cells are never entered.

#include "layer_neighbourhood.hpp"
#include "sandcore/counter_random.hpp"

#include <optional>

namespace sandcore {

/// Where a grain moves: the offset (dx, dz) of its successor in the layer below.
struct MoveTarget {
    int dx;
    int dz;
};

/// Where the grain with this neighbourhood (not on the floor layer) goes this step, or nothing
/// if every successor is full. random() is called only for a slip.
template <class RandomSource>
std::optional<MoveTarget> chooseMove(const CellNeighbourhood& grain, RandomSource&& random) {
    if (grain.below(0, 0) == kEmpty) return MoveTarget{0, 0}; // fall

    MoveTarget emptySuccessors[8];
    std::uint32_t count = 0;
    grain.forEachAround([&](int dx, int dz) {
        if (grain.below(dx, dz) == kEmpty) emptySuccessors[count++] = {dx, dz};
    });
    if (count == 0) return std::nullopt;
    return emptySuccessors[pickBelow(random(), count)]; // slip
}

} // namespace sandcore
