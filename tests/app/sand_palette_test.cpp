// SPDX-License-Identifier: MIT
// SPEC S12: sand that looks like sand. Every grain of the warm palettes has red > green > blue,
// the default stays in V2's range, and in the default look (the framed hourglass, unlit and lit)
// at least 90% of the pixels where grains are drawn are warm.
#include "support/app_test_support.hpp"

#include "app/application.hpp"
#include "scene/scene_request.hpp"
#include "scene/sand_palette.hpp"
#include "scene/sand_patterns.hpp"

#include "sandcore/display_positions.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <optional>
#include <vector>

using namespace sandglass;

namespace {

struct Rgb {
    int r, g, b;
};

Rgb channels(std::uint32_t color) { return {int(color & 255u), int((color >> 8) & 255u), int((color >> 16) & 255u)}; }

bool warm(int r, int g, int b) { return r > g && g > b; }

} // namespace

TEST_CASE("palettes: every grain of the warm palettes has red > green > blue") {
    for (SandPalette palette : {SandPalette::Desert, SandPalette::Beach, SandPalette::White, SandPalette::Volcanic}) {
        CAPTURE(sandPaletteName(palette));
        int cold = 0;
        for (const SandPattern& pattern : makeSandPatterns(kSandPatternCount, palette))
            for (std::uint32_t color : pattern.colors) {
                const Rgb c = channels(color);
                if (!warm(c.r, c.g, c.b)) ++cold;
            }
        CHECK(cold == 0);
    }
    // The default keeps V2's range (220-240, 220-240, 150-190).
    for (const SandPattern& pattern : makeSandPatterns())
        for (std::uint32_t color : pattern.colors) {
            const Rgb c = channels(color);
            CHECK((c.r >= 220 && c.r <= 240 && c.g >= 220 && c.g <= 240 && c.b >= 150 && c.b <= 190));
        }
    // Volcanic sand is dark, white sand light; offsets do not depend on the palette.
    CHECK(channels(makeSandPatterns(8, SandPalette::Volcanic)[3].colors[5]).r < 80);
    CHECK(channels(makeSandPatterns(8, SandPalette::White)[3].colors[5]).b > 220);
    CHECK(makeSandPatterns(8, SandPalette::Beach)[3].offsets == makeSandPatterns(8)[3].offsets);
    CHECK(parseSandPalette("volcanic") == SandPalette::Volcanic);
    CHECK(!parseSandPalette("olive").has_value());
}

TEST_CASE("palettes: coloured layers band the fill by grain identity, other palettes keep the pattern") {
    CHECK(layerColor(SandPalette::Desert, 5, 100) == 0u);
    const std::uint32_t first = layerColor(SandPalette::Layers, 0, 100);
    CHECK(first != 0u);
    CHECK(layerColor(SandPalette::Layers, 99, 100) == first);
    CHECK(layerColor(SandPalette::Layers, 100, 100) != first);
}

TEST_CASE("render: in the default look at least 90% of sand pixels are warm, unlit and lit") {
    if (!testing::requireDisplay("warm sand")) return;
    for (bool light : {false, true}) {
        CAPTURE(light);
        ApplicationOptions options;
        options.window = {200, 200, false, false, "sandglass warm sand test"};
        options.offscreen = true;
        options.initial.showGui = false;
        options.initial.scene.request.modelPath = defaultModelFor(sandcore::SceneKind::Hourglass);
        options.initial.scene.request.resolution = 32;
        options.initial.render.lighting = light;
        options.stepsBeforeStart = 60;
        std::optional<Application> app = testing::openApplication(std::move(options), "warm sand");
        if (!app) return;
        app->renderFrame(0.0);
        const RgbImage image = app->captureFrame();
        const sandcore::Scene& scene = app->scene();
        const RenderSettings& render = app->state().render;
        std::vector<sandcore::Vec3> positions(scene.grains().size());
        sandcore::writeDisplayPositions(scene, app->displayStepFraction(), {render.cellSize, render.jitter}, positions);
        const glm::mat4 viewProjection = app->camera().projection(1.0f) * app->camera().view();
        int sand = 0, warmPixels = 0;
        for (const sandcore::Vec3& p : positions) {
            const glm::vec4 clip = viewProjection * glm::vec4(p.x, p.y, p.z, 1.0f);
            const int x = int((clip.x / clip.w * 0.5f + 0.5f) * float(image.width));
            const int y = int((0.5f - clip.y / clip.w * 0.5f) * float(image.height));
            if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
            const testing::Pixel px = testing::pixelAt(image, x, y);
            if (std::abs(px.r - px.g) <= 2 && std::abs(px.g - px.b) <= 2) continue; // background grey
            ++sand;
            if (warm(px.r, px.g, px.b)) ++warmPixels;
        }
        REQUIRE(sand > int(positions.size()) / 2);
        MESSAGE("warm sand pixels, lighting " << light << ": " << warmPixels << " of " << sand); // shown with -s
        CHECK(warmPixels * 10 >= sand * 9);
    }
}
