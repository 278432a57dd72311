// SPDX-License-Identifier: MIT
#pragma once
// SPEC S9: which of a model's six axis directions points up. Masks are turned by quarter turns
// (a proper rotation, never a mirror image), so every cell maps to exactly one cell.

#include "sandcore/inside_mask.hpp"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace sandcore {

/// A model axis direction that becomes the scene's +y.
enum class UpAxis : std::uint8_t { PlusX, MinusX, PlusY, MinusY, PlusZ, MinusZ };

/// "+x", "-x", "+y", "-y", "+z" or "-z".
const char* upAxisName(UpAxis axis);
/// The axis named "+x" ... "-z" (also "x", "y", "z" for the plus directions); nullopt otherwise.
std::optional<UpAxis> parseUpAxis(std::string_view name);

/// For a turned axis a' (0 = x, 1 = y, 2 = z), the source axis and sign: new[a'] = sign * old[source].
struct AxisTurn {
    int source[3];  ///< model axis that feeds each scene axis
    int sign[3];    ///< +1 or -1
};
/// The quarter-turn rotation that maps `up` onto +y (determinant +1).
AxisTurn axisTurnFor(UpAxis up);

/// The mask turned so that `up` points along +y; +y returns it unchanged.
InsideMask turnToUp(const InsideMask& mask, UpAxis up);

/// How much an hourglass a mask looks like along one axis (S9).
struct NeckProfile {
    bool hasNeck = false;      ///< a layer in the middle half narrower than the widest layer on both sides
    int neckLayer = -1;        ///< layer index along the axis, from the low end
    double ratio = 1.0;        ///< neck cross-section / the smaller bulb's largest cross-section (0..1)
};

/// The neck of the mask's inside cells along axis 0 (x), 1 (y) or 2 (z): the smallest non-empty
/// cross-section in the middle half of the occupied span, ties to the middle.
NeckProfile neckAlong(const InsideMask& mask, int axis);

/// As neckAlong, from the inside cells of each layer along the axis, low end first.
NeckProfile neckOfAreas(const std::vector<std::int64_t>& area);

/// The axis along which the mask has the narrowest neck between two bulbs (plus direction);
/// +y when no axis has one or on a tie with y.
UpAxis findUpAxis(const InsideMask& mask);

} // namespace sandcore
