// SPDX-License-Identifier: MIT
#include "view/render/render_settings.hpp"

namespace sandglass {

namespace {
// Every name of a mode, in the order of RenderMode.
struct ModeNames {
    const char* name;      // command line
    const char* shortName; // thesis §4.3 table
    const char* label;     // panel
};
constexpr ModeNames kModeNames[] = {
    {"points", "P", "Points"},
    {"sprites", "S", "Sprites"},
    {"billboards", "BB", "Billboards"},
    {"pseudo", "PBB", "Pseudo-billboards"},
};
const ModeNames& namesOf(RenderMode mode) { return kModeNames[static_cast<int>(mode)]; }
} // namespace

const char* renderModeName(RenderMode mode) { return namesOf(mode).name; }
const char* renderModeShortName(RenderMode mode) { return namesOf(mode).shortName; }
const char* renderModeLabel(RenderMode mode) { return namesOf(mode).label; }

std::optional<RenderMode> parseRenderMode(std::string_view name) {
    for (RenderMode mode : kRenderModes)
        if (name == renderModeName(mode)) return mode;
    return std::nullopt;
}

const char* normalMethodName(sandcore::NormalMethod method) {
    return method == sandcore::NormalMethod::ColumnHeights ? "columns" : "gradient";
}

std::optional<sandcore::NormalMethod> parseNormalMethod(std::string_view name) {
    for (sandcore::NormalMethod method : {sandcore::NormalMethod::ColumnHeights, sandcore::NormalMethod::OccupancyGradient})
        if (name == normalMethodName(method)) return method;
    return std::nullopt;
}

const char* lightRigName(LightRig rig) { return rig == LightRig::Thesis ? "thesis" : "studio"; }

std::optional<LightRig> parseLightRig(std::string_view name) {
    for (LightRig rig : {LightRig::Studio, LightRig::Thesis})
        if (name == lightRigName(rig)) return rig;
    return std::nullopt;
}

RenderSettings thesisLook() {
    RenderSettings settings;
    settings.mode = RenderMode::Points;
    settings.lighting = false;
    settings.light = LightRig::Thesis;
    settings.ambientOcclusion = false;
    settings.shadows = false;
    settings.toneMapping = false;
    settings.glassEnvironment = false;
    return settings;
}

} // namespace sandglass
