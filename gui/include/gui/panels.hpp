// SPDX-License-Identifier: MIT
#pragma once
// The ImGui panels (SPEC G1, G2): every control of thesis §3.7 with its default, plus scene,
// model, resolution, sizes, flow speed, jitter, seed and statistics. They read and change the
// application state and raise commands; they own no state and never touch the grids.

#include "view/app_state.hpp"

#include <string>

namespace sandglass {

/// Builds the panels for this frame (between ImGui::NewFrame and ImGui::Render): a Help button,
/// what is loaded, then tabs (Run, Paint on the canvas, View, Scene, File) and the status line.
void drawPanels(AppState& state);

/// SPEC U3: the one line naming the scene that runs, e.g. "sculpture: snowman.obj, resolution 64".
std::string sceneSummary(const SceneRequest& loaded);
/// A hint line in the lighter grey, wrapped to the panel's width.
void hint(const char* text);
/// SPEC U2: ImGuiTreeNodeFlags_DefaultOpen where the window is tall enough for the panel's
/// folded parts to start open, else 0.
int openWhereRoomy();
/// SPEC U2: the panel's width for a window this wide (window units) at this font size.
float panelWidth(float displayWidth, float fontSize);
/// Where a window of this size is shown in a display of this size: the chosen place, moved just
/// enough to stay inside (top-left corner wins when it cannot fit).
WindowPlacement placeOnScreen(const WindowPlacement& chosen, float width, float height, float displayWidth,
                              float displayHeight);

/// Thesis §3.7 "Kontrolle": simulation on/off, reset, single step, exit.
void drawControlSection(AppState& state);
/// The hourglass as a timer: a duration in minutes:seconds and Start, or elapsed and remaining time.
void drawTimer(AppState& state);
/// Thesis §3.7 "Darstellung": grains per cell, background, mode, lighting, inner grains; sizes, jitter, hull.
void drawDisplaySection(AppState& state);
/// SPEC G2: scene kind, shape or model file, resolution, seed, threads, rebuild.
void drawSceneSection(AppState& state);
/// SPEC S2, S3, S5 (inside the scene section): robust inside test, stretch, noNoise threshold,
/// upper-bulb carving; each change raises a rebuild.
void drawModelOptions(AppState& state);
/// Thesis §3.7 "Zeichnen": draw/erase, source/target, thick/thin, draft (canvas only); brush,
/// colour, colour from draft, draft file, undo and obstacles (SPEC P3, P5-P7, G2).
void drawPaintingSection(AppState& state);
/// SPEC G2 and V7: grains, moving grains, steps/s, ms per step, ms per frame, frame-time plot.
void drawStatisticsSection(AppState& state);
/// SPEC E1, E2: save, open and export paths with their buttons.
void drawFileSection(AppState& state);

} // namespace sandglass
