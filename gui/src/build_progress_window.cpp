// SPDX-License-Identifier: MIT
#include "gui/build_progress_window.hpp"

#include <imgui.h>

namespace sandglass {

void drawBuildProgress(AppState& state) {
    if (!state.building) return;
    const BuildStatus& build = state.build;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float em = ImGui::GetFontSize();
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, 20.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("Building scene", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    if (build.cancelling)
        ImGui::Text("cancelling (stops when %s ends)  %.1f s", build.phase.c_str(), build.seconds);
    else
        ImGui::Text("building scene: %s...  %.1f s", build.phase.c_str(), build.seconds);
    ImGui::ProgressBar(build.shareDone, ImVec2(em * 16.0f, 0.0f));
    // The button goes once pressed: the build stops at the end of its phase, not at once.
    if (!build.cancelling && ImGui::Button("Cancel (Esc)")) state.commands.push(Command::CancelBuild);
    ImGui::End();
}

} // namespace sandglass
