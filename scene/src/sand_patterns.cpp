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

std::vector<SandPattern> makeSandPatterns(int count) {
    std::vector<SandPattern> patterns(std::size_t(std::max(count, 1)));
    for (std::size_t p = 0; p < patterns.size(); ++p) {
        SandPattern& pattern = patterns[p];
        // One tint per pattern (thesis: "a light yellow that differs slightly per cell")...
        const int red = integerIn(patternRandom(p, kTint, 0), 220, 240);
        const int green = integerIn(patternRandom(p, kTint, 1), 220, 240);
        const int blueBase = integerIn(patternRandom(p, kTint, 2), 150, 190);
        for (std::size_t i = 0; i < pattern.offsets.size(); ++i) {
            for (std::size_t axis = 0; axis < 3; ++axis) {
                const float unit = sandcore::unitFloat(patternRandom(p, kOffset, 3 * i + axis)); // [0, 1)
                pattern.offsets[i][axis] = i == 0 ? 0.0f : 2.0f * unit - 1.0f;
            }
            // ...and a little variation per sub-grain, kept inside the thesis's range.
            const auto wobble = [&](std::size_t channel) { return integerIn(patternRandom(p, kWobble, 3 * i + channel), -6, 6); };
            const auto r = std::uint32_t(std::clamp(red + wobble(0), 220, 240));
            const auto g = std::uint32_t(std::clamp(green + wobble(1), 220, 240));
            const auto b = std::uint32_t(std::clamp(blueBase + wobble(2), 150, 190));
            pattern.colors[i] = r | (g << 8) | (b << 16) | (255u << 24);
        }
    }
    return patterns;
}

std::uint32_t grainExportColor(const std::vector<SandPattern>& patterns, std::uint32_t identity, std::uint32_t rgba) {
    if (rgba != 0 || patterns.empty()) return rgba | 0xff000000u;
    return patterns[identity % patterns.size()].colors[0] | 0xff000000u;
}

} // namespace sandglass
