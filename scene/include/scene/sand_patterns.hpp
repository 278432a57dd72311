// SPDX-License-Identifier: MIT
#pragma once
// Thesis §3.8 "Scribble": a fixed set of random patterns, each placing up to 32 sub-grains inside
// a cell and giving each a pale sand colour. A grain uses pattern (identity mod count), so the
// choice never changes from frame to frame (no flicker) and costs no random numbers per frame.
// Pure CPU code in the scene layer: the renderer uploads the patterns, the exporters (E2) take
// their colours for grains that have none of their own.

#include "scene/sand_palette.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace sandglass {

/// One pattern: offsets in [-1, 1] per axis (scaled by half a cell when drawn) and RGBA8 colours.
struct SandPattern {
    std::array<std::array<float, 3>, 32> offsets{}; ///< sub-grain positions inside the cell, [-1, 1]
    std::array<std::uint32_t, 32> colors{};         ///< RGBA8, R in the low byte, alpha 255
};

/// Number of patterns the renderer uploads (the thesis's mCount).
inline constexpr int kSandPatternCount = 64;

/// The patterns, the same on every run: one warm tint per pattern from the palette (Desert: RGB in
/// (220-240, 220-240, 150-190), red > green > blue) and a small variation per sub-grain that
/// keeps red > green > blue; sub-grain 0 sits at the cell centre. Offsets do not depend on the palette.
std::vector<SandPattern> makeSandPatterns(int count = kSandPatternCount, SandPalette palette = SandPalette::Desert);

/// The colour a grain is exported with, RGBA8 with alpha 255: its own colour, or for rgba 0 the
/// tint of its pattern (identity mod patterns.size(), the pattern's sub-grain 0).
std::uint32_t grainExportColor(const std::vector<SandPattern>& patterns, std::uint32_t identity, std::uint32_t rgba);

} // namespace sandglass
