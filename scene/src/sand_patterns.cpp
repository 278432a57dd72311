// SPDX-License-Identifier: MIT
#include "scene/sand_patterns.hpp"

#include "sandcore/counter_random.hpp"

#include <algorithm>

namespace sandglass {

namespace {

// A fixed seed: the patterns are part of the look, not of the simulation.
constexpr std::uint64_t kPatternSeed = 20080611u;

// One stream per kind of number, so adding one kind never shifts the others.
enum PatternStream : std::uint64_t { kTint = 1, kOffset = 2, kWobble = 3 };

// The counter-based hash (not std::mt19937 with std::uniform_*_distribution, whose output
// differs between standard libraries): the same patterns on every platform.
std::uint64_t patternRandom(std::size_t pattern, PatternStream stream, std::size_t index) {
    return sandcore::counterRandom(kPatternSeed, pattern, stream, index);
}

int integerIn(std::uint64_t random, int lowest, int highest) {
    return lowest + int(sandcore::pickBelow(random, std::uint32_t(highest - lowest + 1)));
}

} // namespace

std::vector<SandPattern> makeSandPatterns(int count, SandPalette palette) {
    const PaletteTint tint = paletteTint(palette);
    std::vector<SandPattern> patterns(std::size_t(std::max(count, 1)));
    for (std::size_t p = 0; p < patterns.size(); ++p) {
        SandPattern& pattern = patterns[p];
        // One tint per pattern (thesis: "a light yellow that differs slightly per cell"), warm as
        // real sand is (S12): green below red and blue below green, never drawn independently...
        const int red = integerIn(patternRandom(p, kTint, 0), tint.redLow, tint.redHigh);
        const int greenGap = integerIn(patternRandom(p, kTint, 1), tint.greenGapLow, tint.greenGapHigh);
        const int blueGap = integerIn(patternRandom(p, kTint, 2), tint.blueGapLow, tint.blueGapHigh);
        for (std::size_t i = 0; i < pattern.offsets.size(); ++i) {
            for (std::size_t axis = 0; axis < 3; ++axis) {
                const float unit = sandcore::unitFloat(patternRandom(p, kOffset, 3 * i + axis)); // [0, 1)
                pattern.offsets[i][axis] = i == 0 ? 0.0f : 2.0f * unit - 1.0f;
            }
            // ...and a little variation per sub-grain that keeps red > green > blue.
            const auto wobble = [&](std::size_t channel, int size) {
                return integerIn(patternRandom(p, kWobble, 3 * i + channel), -size, size);
            };
            const int r = std::clamp(red + wobble(0, 6), tint.redLow, tint.redHigh);
            const int g = std::max(tint.greenLow, r - std::max(1, greenGap + wobble(1, 2)));
            const int b = std::clamp(g - std::max(1, blueGap + wobble(2, 4)), tint.blueLow, std::min(tint.blueHigh, g - 1));
            pattern.colors[i] = std::uint32_t(r) | (std::uint32_t(g) << 8) | (std::uint32_t(b) << 16) | (255u << 24);
        }
    }
    return patterns;
}

std::uint32_t grainExportColor(const std::vector<SandPattern>& patterns, std::uint32_t identity, std::uint32_t rgba) {
    if (rgba != 0 || patterns.empty()) return rgba | 0xff000000u;
    return patterns[identity % patterns.size()].colors[0] | 0xff000000u;
}

} // namespace sandglass
