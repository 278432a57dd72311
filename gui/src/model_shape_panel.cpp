// SPDX-License-Identifier: MIT
#include "gui/model_shape_panel.hpp"

#include "scene/model_parts.hpp"

#include "sandcore/up_axis.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <exception>

namespace sandglass {

std::string upAxisAfterQuarterTurn(const std::string& up, int aboutAxis) {
    const std::string current = up.empty() ? "+y" : up;
    const std::array<const char*, 4> aboutX{"+y", "-z", "-y", "+z"}, aboutZ{"+y", "+x", "-y", "-x"};
    const auto& cycle = aboutAxis == 0 ? aboutX : aboutZ;
    for (std::size_t i = 0; i < cycle.size(); ++i)
        if (current == cycle[i]) return cycle[(i + 1) % cycle.size()];
    return current;
}

namespace {

void setRole(SceneRequest& request, const std::string& name, PartRole role) {
    auto it = std::find_if(request.partRoles.begin(), request.partRoles.end(),
                           [&](const PartRoleChoice& c) { return c.name == name; });
    if (it != request.partRoles.end()) it->role = role;
    else request.partRoles.push_back({name, role});
}

// Reads the parts of the chosen model once per file, with the roles the next build will use.
void readParts(AppState& state) {
    const SceneRequest& request = state.scene.request;
    state.partsListPath = request.modelPath;
    state.partsList.clear();
    try {
        std::vector<ModelPart> parts = loadModelParts(request.modelPath);
        chooseRoles(parts, request.kind, request.partRoles);
        state.partsList = summarize(parts);
    } catch (const std::exception&) {
        // The build reports a bad file; the checklist just stays empty.
    }
}

} // namespace

void drawModelShapeOptions(AppState& state) {
    SceneRequest& request = state.scene.request;
    // Roles were set for the parts of the file the list was read from; another file has others.
    if (!request.partRoles.empty() && state.partsListPath != request.modelPath) request.partRoles.clear();
    if (request.modelPath.empty()) return;
    // S9: which model axis points up; automatic finds the hourglass's neck, the sculpture keeps +y.
    const char* choices[] = {"automatic", "+x", "-x", "+y", "-y", "+z", "-z"};
    int chosen = 0;
    for (int i = 1; i < 7; ++i)
        if (request.upAxis == choices[i]) chosen = i;
    if (ImGui::Combo("up axis", &chosen, choices, 7)) {
        request.upAxis = chosen == 0 ? std::string() : std::string(choices[chosen]);
        state.commands.push(Command::Rebuild);
    }
    if (ImGui::Button("turn 90° about x")) {
        request.upAxis = upAxisAfterQuarterTurn(request.upAxis, 0);
        state.commands.push(Command::Rebuild);
    }
    ImGui::SameLine();
    if (ImGui::Button("turn 90° about z")) {
        request.upAxis = upAxisAfterQuarterTurn(request.upAxis, 2);
        state.commands.push(Command::Rebuild);
    }
    // S7: the parts and their roles; reading a file happens when the list is opened.
    if (!ImGui::TreeNode("parts")) return;
    if (state.partsListPath != request.modelPath) readParts(state);
    const char* roles[] = {"vessel", "frame", "sand", "static"};
    for (PartSummary& part : state.partsList) {
        ImGui::PushID(part.name.c_str());
        int role = int(part.role);
        ImGui::SetNextItemWidth(90.0f);
        if (ImGui::Combo("##role", &role, roles, 4)) {
            part.role = PartRole(role);
            setRole(request, part.name, part.role);
            state.commands.push(Command::Rebuild);
        }
        ImGui::SameLine();
        ImGui::Text("%s  (%lld triangles, %s)", part.name.c_str(), (long long)part.triangles,
                    part.closed ? "closed" : "open");
        ImGui::PopID();
    }
    if (state.partsList.empty()) ImGui::TextDisabled("(no parts read)");
    ImGui::TreePop();
}

void drawPaletteChoice(AppState& state) {
    int palette = int(state.render.palette);
    const char* names[] = {"desert", "beach", "white", "volcanic black", "coloured layers"};
    if (ImGui::Combo("sand colours", &palette, names, 5)) state.render.palette = SandPalette(palette);
}

} // namespace sandglass
