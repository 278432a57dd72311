// SPDX-License-Identifier: MIT
#pragma once
// SPEC I5: a scene being built shows what it does, how far it is, and a Cancel that keeps the
// running scene; shown even with the panels hidden.

#include "view/app_state.hpp"

namespace sandglass {

/// While AppState::building: a small window at the top middle with the phase, the time so far,
/// a progress bar and "Cancel (Esc)", which queues Command::CancelBuild.
void drawBuildProgress(AppState& state);

} // namespace sandglass
