// SPDX-License-Identifier: MIT
#pragma once
// A scripted sand drawing over the loaded draft (`sandglass gui --scene canvas --draft FILE
// --paint-demo`): strokes go through the same mouse path a hand-drawn one takes, so the
// README picture shows what a user gets.

#include "app/application.hpp"

namespace sandglass {

/// Pours `passes` layers of sand along every row span of the draft that differs from its
/// background (the top-left pixel's colour), colour from draft, letting each layer settle;
/// then hides the draft so the drawing shows. Returns the grains released; 0 without a draft
/// or outside the canvas scene.
std::int64_t paintDraftDemo(Application& app, int passes);

} // namespace sandglass
