// SPDX-License-Identifier: MIT
#include "sandcore/moving_body.hpp"

#include "ball_cells.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sandcore {

namespace {

void requirePositive(int value, const char* what) {
    if (value < 1) throw std::invalid_argument(std::string(what) + " must be at least 1 cell, got " + std::to_string(value));
}

// (dx, dz) turned a quarter turn at a time: +x into +z, +z into -x.
Int3 turned(Int3 offset, int quarterTurns) {
    for (int t = 0; t < (quarterTurns & 3); ++t) offset = {-offset.z, offset.y, offset.x};
    return offset;
}

} // namespace

std::vector<Int3> bodyOffsets(const InsideMask& shape, int quarterTurns) {
    std::vector<Int3> offsets;
    const int anchorX = shape.size.x / 2, anchorZ = shape.size.z / 2;
    for (int y = 0; y < shape.size.y; ++y)
        for (int z = 0; z < shape.size.z; ++z)
            for (int x = 0; x < shape.size.x; ++x)
                if (shape.at(x, y, z)) offsets.push_back(turned({x - anchorX, y, z - anchorZ}, quarterTurns));
    return offsets;
}

InsideMask makeBoxShape(Int3 size) {
    requirePositive(size.x, "a box's width");
    requirePositive(size.y, "a box's height");
    requirePositive(size.z, "a box's depth");
    InsideMask mask = InsideMask::empty(size);
    std::fill(mask.inside.begin(), mask.inside.end(), std::uint8_t{1});
    return mask;
}

InsideMask makeBladeShape(int width, int height, int thickness) {
    requirePositive(width, "a blade's width");
    requirePositive(height, "a blade's height");
    requirePositive(thickness, "a blade's thickness");
    return makeBoxShape({width, height, thickness});
}

InsideMask makeBallShape(int diameter) {
    requirePositive(diameter, "a ball's diameter");
    // A quarter cell squared of slack: a diameter of 1 or 2 fills its box, so a small body is
    // never empty.
    return ballCells(diameter, 0.25);
}

} // namespace sandcore
