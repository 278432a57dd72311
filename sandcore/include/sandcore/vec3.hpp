// SPDX-License-Identifier: MIT
#pragma once
// Small value types for cell coordinates and display positions. sandcore keeps its own so
// that it depends on nothing but the standard library.

#include <cstdint>

namespace sandcore {

/// Integer cell coordinate or grid size (x right, y up, z towards the viewer).
struct Int3 {
    int x = 0; ///< cells
    int y = 0; ///< cells
    int z = 0; ///< cells
    friend bool operator==(const Int3&, const Int3&) = default;
};

/// Display position or direction in world units.
struct Vec3 {
    float x = 0; ///< world units
    float y = 0; ///< world units
    float z = 0; ///< world units
    friend bool operator==(const Vec3&, const Vec3&) = default;
};

} // namespace sandcore
