// SPDX-License-Identifier: MIT
#include "sandcore/moving_body.hpp"

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
    InsideMask mask = InsideMask::empty({diameter, diameter, diameter});
    // Cell centres within the radius of the box's centre; a diameter of 1 or 2 fills the box.
    const double centre = diameter / 2.0, radius = diameter / 2.0;
    for (int y = 0; y < diameter; ++y)
        for (int z = 0; z < diameter; ++z)
            for (int x = 0; x < diameter; ++x) {
                const double dx = x + 0.5 - centre, dy = y + 0.5 - centre, dz = z + 0.5 - centre;
                mask.set(x, y, z, dx * dx + dy * dy + dz * dz <= radius * radius + 0.25);
            }
    return mask;
}

} // namespace sandcore
