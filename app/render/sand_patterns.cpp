#include "render/sand_patterns.hpp"

#include <algorithm>
#include <random>

namespace sandglass {

std::vector<SandPattern> makeSandPatterns(int count) {
    // A fixed seed: the patterns are part of the look, not of the simulation.
    std::mt19937 random(20080611u);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_int_distribution<int> redGreen(220, 240), blue(150, 190), wobble(-6, 6);
    std::vector<SandPattern> patterns(std::size_t(std::max(count, 1)));
    for (SandPattern& pattern : patterns) {
        // One tint per pattern (thesis: "a light yellow that differs slightly per cell")...
        const int red = redGreen(random), green = redGreen(random), blueBase = blue(random);
        for (std::size_t i = 0; i < pattern.offsets.size(); ++i) {
            pattern.offsets[i] = i == 0 ? std::array<float, 3>{0.0f, 0.0f, 0.0f}
                                        : std::array<float, 3>{unit(random), unit(random), unit(random)};
            // ...and a little variation per sub-grain, kept inside the thesis's range.
            const auto r = std::uint32_t(std::clamp(red + wobble(random), 220, 240));
            const auto g = std::uint32_t(std::clamp(green + wobble(random), 220, 240));
            const auto b = std::uint32_t(std::clamp(blueBase + wobble(random), 150, 190));
            pattern.colors[i] = r | (g << 8) | (b << 16) | (255u << 24);
        }
    }
    return patterns;
}

} // namespace sandglass
