// SPDX-License-Identifier: MIT
#include "gui/quit_question.hpp"

#include <imgui.h>

#include <string>

namespace sandglass {

void drawQuitQuestion(AppState& state) {
    FileSettings& files = state.files;
    if (!files.confirmQuit) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowFocus();
    ImGui::Begin("Quit sandglass?", nullptr,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextUnformatted("The scene has changes that are not saved.");
    const std::string saveLabel = "Save to " + files.statePath + " and quit";
    if (ImGui::Button(saveLabel.c_str())) state.commands.push(Command::SaveAndQuit);
    if (ImGui::Button("Quit without saving")) state.commands.push(Command::QuitNow);
    ImGui::SameLine();
    if (ImGui::Button("Cancel (Esc)")) files.confirmQuit = false;
    ImGui::End();
}

} // namespace sandglass
