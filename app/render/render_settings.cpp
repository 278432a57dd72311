#include "render/render_settings.hpp"

namespace sandglass {

const char* renderModeName(RenderMode mode) {
    switch (mode) {
    case RenderMode::Points: return "points";
    case RenderMode::Sprites: return "sprites";
    case RenderMode::Billboards: return "billboards";
    case RenderMode::PseudoBillboards: return "pseudo";
    }
    return "points";
}

const char* renderModeShortName(RenderMode mode) {
    switch (mode) {
    case RenderMode::Points: return "P";
    case RenderMode::Sprites: return "S";
    case RenderMode::Billboards: return "BB";
    case RenderMode::PseudoBillboards: return "PBB";
    }
    return "P";
}

const char* renderModeLabel(RenderMode mode) {
    switch (mode) {
    case RenderMode::Points: return "Points";
    case RenderMode::Sprites: return "Sprites";
    case RenderMode::Billboards: return "Billboards";
    case RenderMode::PseudoBillboards: return "Pseudo-billboards";
    }
    return "Points";
}

std::optional<RenderMode> parseRenderMode(std::string_view name) {
    for (RenderMode mode : kRenderModes)
        if (name == renderModeName(mode)) return mode;
    return std::nullopt;
}

} // namespace sandglass
