// SPDX-License-Identifier: MIT
#pragma once
// Scratch of the pushes of moving bodies (Scene::moveBody): a breadth-first search through the
// grains of the lower grid for the EMPTY cell nearest to a grain a body covers. Private to sandcore.

#include "sandcore/vec3.hpp"

#include <cstdint>
#include <vector>

namespace sandcore {

struct PushSearch {
    // Per cell of the lower grid: the stamp of the search that reached it (a new stamp per
    // search spares clearing the grid-sized arrays).
    std::vector<std::uint32_t> stamp;
    std::vector<std::uint8_t> cameBy;   // the direction (index into the search's order) it was reached by
    std::vector<std::uint8_t> inWay;    // 1 for a cell the body is entering in this unit move
    struct Reached {
        std::uint32_t cell; // its index
        Int3 at;            // its coordinate
    };
    std::vector<Reached> queue;
    std::vector<std::uint32_t> way; // the push found: cells from the pushed grain's to the EMPTY one
    // The unit move's cells, kept between moves so a move allocates nothing: the body's before
    // and after it, and those it enters and leaves.
    std::vector<std::uint32_t> before, after, entering, leaving;
    std::uint32_t lastStamp = 0;

    explicit PushSearch(std::uint32_t cellCount) : stamp(cellCount, 0), cameBy(cellCount, 0), inWay(cellCount, 0) {}
    std::uint32_t nextStamp() {
        if (lastStamp == UINT32_MAX) {
            std::fill(stamp.begin(), stamp.end(), 0u);
            lastStamp = 0;
        }
        return ++lastStamp;
    }
};

} // namespace sandcore
