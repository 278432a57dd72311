// SPDX-License-Identifier: MIT
#include "gui/help_window.hpp"

#include "gui/panels.hpp"

#include <imgui.h>

#include <algorithm>

namespace sandglass {

const std::vector<ControlHelp>& controlHelp() {
    static const std::vector<ControlHelp> controls = {
        {"F1 or ?", "show or hide this help"},
        {"Space", "hide or show the panels"},
        {"Esc", "quit (asks first when painting is unsaved; stops the frame benchmark or cancels a scene build)"},
        {"Left drag", "rotate the view (on the canvas: pour or erase sand)"},
        {"Middle drag", "pan the view"},
        {"Right drag", "zoom"},
        {"Mouse wheel", "zoom"},
        {"Alt + drag", "on the canvas: move the view instead of painting"},
        {"Arrow keys", "rotate the view (with the digger on: move it a cell)"},
        {"+ / -", "zoom in / out"},
        {"1 / 2 / 3", "perspective / front / top view"},
        {"T", "turn the hourglass over"},
        {"Ctrl+Z", "undo the last stroke (canvas)"},
        {"Ctrl+Y, Ctrl+Shift+Z", "redo"},
        {"Ctrl+S / Ctrl+O", "save / open the state file named in the File section"},
        {"P", "save a screenshot of the sand (PNG, in the folder the File tab names)"},
        {"B", "frame benchmark (Esc cancels)"},
        {"F", "print frames per second to the terminal"},
        {"#", "print the number of grains to the terminal"},
        {"Drop a file", "a 3D model builds a scene; a .sand opens; a PNG or JPEG on the canvas is the draft"},
    };
    return controls;
}

void drawHelpWindow(AppState& state) {
    if (!state.showHelp) return;
    state.showHelpHint = false;
    const ImGuiIO& io = ImGui::GetIO();
    const float em = ImGui::GetFontSize();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    // Never larger than the window, so the close button stays in reach at 640x480.
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(std::max(em * 10.0f, io.DisplaySize.x - em),
                                                                   std::max(em * 6.0f, io.DisplaySize.y - em)));
    if (ImGui::Begin("Keys and mouse", &state.showHelp,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
        // Kept inside the window through any resize.
        const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        const WindowPlacement inside = placeOnScreen({at.x, at.y}, size.x, size.y, io.DisplaySize.x, io.DisplaySize.y);
        if (inside.x != at.x || inside.y != at.y) ImGui::SetWindowPos(ImVec2(inside.x, inside.y));
        if (ImGui::BeginTable("controls", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
            for (const ControlHelp& control : controlHelp()) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(control.input);
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(control.action);
            }
            ImGui::EndTable();
        }
        if (ImGui::Button("Close")) state.showHelp = false;
    }
    ImGui::End();
}

void drawHelpHint(AppState& state) {
    if (!state.showHelpHint || state.showHelp) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // Centred under the scene, clear of the panel on the left.
    const float left = state.showGui ? state.panelCoverage * display.x : 0.0f;
    ImGui::SetNextWindowPos(ImVec2(0.5f * (left + display.x), display.y - ImGui::GetFontSize()), ImGuiCond_Always,
                            ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::Begin("##helphint", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::TextUnformatted("F1 or ? shows the keys and mouse controls");
    ImGui::End();
    // A hint, not a fixture: it goes after a while or with the first look at the help.
    if (ImGui::GetTime() > 20.0) state.showHelpHint = false;
}

} // namespace sandglass
