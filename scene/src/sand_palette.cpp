// SPDX-License-Identifier: MIT
#include "scene/sand_palette.hpp"

#include <algorithm>

namespace sandglass {

const char* sandPaletteName(SandPalette palette) {
    switch (palette) {
    case SandPalette::Desert: return "desert";
    case SandPalette::Beach: return "beach";
    case SandPalette::White: return "white";
    case SandPalette::Volcanic: return "volcanic";
    case SandPalette::Layers: return "layers";
    }
    return "desert";
}

std::optional<SandPalette> parseSandPalette(std::string_view name) {
    for (SandPalette palette : kSandPalettes)
        if (name == sandPaletteName(palette)) return palette;
    return std::nullopt;
}

PaletteTint paletteTint(SandPalette palette) {
    switch (palette) {
    case SandPalette::Beach: return {236, 250, 12, 20, 30, 50, 0, 0, 255};
    case SandPalette::White: return {242, 252, 3, 6, 6, 12, 0, 0, 255};
    case SandPalette::Volcanic: return {52, 72, 5, 9, 3, 6, 0, 0, 255};
    case SandPalette::Desert:
    case SandPalette::Layers: break;
    }
    // Within V2's range: green 220-240 below red, blue 150-190 well below green.
    return {236, 240, 12, 18, 40, 66, 220, 150, 190};
}

std::uint32_t layerColor(SandPalette palette, std::uint32_t identity, std::uint32_t grainsPerBand) {
    if (palette != SandPalette::Layers) return 0;
    // Rose, ochre, sky, sage, lavender, terracotta: the colours of bottled sand art.
    constexpr std::uint32_t bands[] = {0xff8c8ce6u, 0xff4ab4e6u, 0xffe0b46eu, 0xff8cc8a0u, 0xffd2a0b4u, 0xff4678c8u};
    const std::uint32_t band = identity / std::max<std::uint32_t>(grainsPerBand, 1);
    return bands[band % (sizeof bands / sizeof bands[0])];
}

} // namespace sandglass
