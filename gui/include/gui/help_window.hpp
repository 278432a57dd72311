// SPDX-License-Identifier: MIT
#pragma once
// SPEC U1: the keys and mouse controls in a window of their own (F1, ? or the Help button), and
// a one-line hint of it on the first start.

#include "view/app_state.hpp"

#include <vector>

namespace sandglass {

/// One control: what to press and what it does.
struct ControlHelp {
    const char* input;  ///< e.g. "Ctrl+Z"
    const char* action; ///< e.g. "undo the last stroke"
};

/// Every key and mouse control of the window, in the order the help shows them (input_routing.cpp
/// and the application's key handling are the source; a test keeps them in step).
const std::vector<ControlHelp>& controlHelp();

/// The help window while AppState::showHelp; its close button clears it.
void drawHelpWindow(AppState& state);
/// The one-line hint at the bottom of the window until help has been opened once.
void drawHelpHint(AppState& state);

} // namespace sandglass
