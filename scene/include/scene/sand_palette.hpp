// SPDX-License-Identifier: MIT
#pragma once
// SPEC S12: sand that looks like sand. Every palette gives warm grains (red > green > blue in
// every grain) except the coloured layers, which band the hourglass fill by grain identity.

#include <cstdint>
#include <optional>
#include <string_view>

namespace sandglass {

/// The looks of the sand.
enum class SandPalette : std::uint8_t {
    Desert,   ///< the default: pale warm sand, within V2's range (220-240, 220-240, 150-190)
    Beach,    ///< golden, lighter
    White,    ///< nearly white quartz sand, still warm
    Volcanic, ///< black volcanic sand
    Layers,   ///< desert sand in coloured bands by fill order (grain identity)
};

/// Every palette in panel order.
inline constexpr SandPalette kSandPalettes[] = {SandPalette::Desert, SandPalette::Beach, SandPalette::White,
                                                SandPalette::Volcanic, SandPalette::Layers};

/// Command-line name: "desert", "beach", "white", "volcanic" or "layers".
const char* sandPaletteName(SandPalette palette);
/// The palette named by sandPaletteName, or nothing.
std::optional<SandPalette> parseSandPalette(std::string_view name);

/// A palette's tint per pattern: red in [redLow, redHigh], green below red by [greenGapLow,
/// greenGapHigh], blue below green by [blueGapLow, blueGapHigh], 0..255.
struct PaletteTint {
    int redLow, redHigh;           ///< red, 0..255
    int greenGapLow, greenGapHigh; ///< red - green, at least 1
    int blueGapLow, blueGapHigh;   ///< green - blue, at least 1
    int greenLow, blueLow, blueHigh; ///< clamps that keep Desert inside V2's range
};
/// The tint range of a palette (Layers uses Desert's).
PaletteTint paletteTint(SandPalette palette);

/// Layers: the band colour (RGBA8, R low byte) of a grain, bands by identity in fills of
/// `grainsPerBand` grains (at least 1); 0 for every other palette (the pattern's colour).
std::uint32_t layerColor(SandPalette palette, std::uint32_t identity, std::uint32_t grainsPerBand);

} // namespace sandglass
