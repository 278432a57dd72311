// SPDX-License-Identifier: MIT
#pragma once
// SPEC S7, S9 and S12 controls: the model's parts with their roles, the up axis with quarter-turn
// buttons, and the sand palette. They change the request or the render settings and raise a rebuild.

#include "view/app_state.hpp"

namespace sandglass {

/// S9 up-axis choice and "turn 90°" buttons, S7 parts checklist (read when opened), in the model options.
void drawModelShapeOptions(AppState& state);
/// S12: the sand palette, in the display section.
void drawPaletteChoice(AppState& state);

/// The up axis after turning the model a quarter turn about model axis x (0) or z (2): the up
/// direction cycles +y, -z, -y, +z about x and +y, +x, -y, -x about z; an axis along the turn stays.
/// An empty `up` counts as +y.
std::string upAxisAfterQuarterTurn(const std::string& up, int aboutAxis);

} // namespace sandglass
