// SPDX-License-Identifier: MIT
#pragma once
// SPEC U5: quitting with unsaved edits asks first, even with the panels hidden.

#include "view/app_state.hpp"

namespace sandglass {

/// While AppState::files.confirmQuit is set: a window in the middle asking "Save and quit",
/// "Quit without saving" or "Cancel"; each answer queues its command or clears the question.
void drawQuitQuestion(AppState& state);

} // namespace sandglass
