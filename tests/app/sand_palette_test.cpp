// SPDX-License-Identifier: MIT
// SPEC S12: sand that looks like sand. Every grain of the warm palettes has red > green > blue,
// the default stays in V2's range, and in the default look (the framed hourglass, unlit and lit)
// at least 90% of the pixels where grains are drawn are warm. The layers palette shows its bands
// on both grain paths, in the same picture, also when chosen while the grains are on the GPU.
#include "support/app_test_support.hpp"

#include "app/application.hpp"
#include "scene/scene_request.hpp"
#include "scene/sand_palette.hpp"
#include "scene/sand_patterns.hpp"

#include "sandcore/display_positions.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

using namespace sandglass;

namespace {

struct Rgb {
    int r, g, b;
};

Rgb channels(std::uint32_t color) { return {int(color & 255u), int((color >> 8) & 255u), int((color >> 16) & 255u)}; }

bool warm(int r, int g, int b) { return r > g && g > b; }

// The default hourglass (its model) framed in a 200 x 200 window after 60 steps, panels off.
ApplicationOptions defaultHourglass(const RenderSettings& render, const char* title) {
    ApplicationOptions options;
    options.window = {200, 200, false, false, title};
    options.offscreen = true;
    options.initial.showGui = false;
    options.initial.scene.request.modelPath = defaultModelFor(sandcore::SceneKind::Hourglass);
    options.initial.scene.request.resolution = 32;
    options.initial.render = render;
    options.initial.simulationRunning = false;
    options.stepsBeforeStart = 60;
    return options;
}

// The pixels of `image` (the application's last frame) where its grains' display positions fall,
// the background's grey left out; `grains` is set to the number of grains.
std::vector<testing::Pixel> sandPixels(Application& app, const RgbImage& image, int& grains) {
    const sandcore::Scene& scene = app.scene();
    const RenderSettings& render = app.state().render;
    std::vector<sandcore::Vec3> positions(scene.grains().size());
    sandcore::writeDisplayPositions(scene, app.displayStepFraction(), {render.cellSize, render.jitter}, positions);
    grains = int(positions.size());
    const glm::mat4 viewProjection = app.camera().projection(float(image.width) / float(image.height)) * app.camera().view();
    std::vector<testing::Pixel> sand;
    for (const sandcore::Vec3& p : positions) {
        const glm::vec4 clip = viewProjection * glm::vec4(p.x, p.y, p.z, 1.0f);
        const int x = int((clip.x / clip.w * 0.5f + 0.5f) * float(image.width));
        const int y = int((0.5f - clip.y / clip.w * 0.5f) * float(image.height));
        if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
        const testing::Pixel px = testing::pixelAt(image, x, y);
        if (std::abs(px.r - px.g) <= 2 && std::abs(px.g - px.b) <= 2) continue; // background grey
        sand.push_back(px);
    }
    return sand;
}

constexpr std::uint32_t kLayerBands = 6;

// The layers palette's band a pixel shows, or -1 for none: the band colour nearest in
// chromaticity (each channel over their sum, which shading and lighting leave alone), if near.
int bandOf(testing::Pixel px) {
    const float sum = float(std::max(px.r + px.g + px.b, 1));
    int nearest = -1;
    // The pattern's variation keeps a band's grains within this; of desert sand only a few dark
    // grains come as near, to terracotta.
    float nearestDistance = 0.03f;
    for (std::uint32_t band = 0; band < kLayerBands; ++band) {
        const Rgb color = channels(layerColor(SandPalette::Layers, band, 1));
        const float colorSum = float(color.r + color.g + color.b);
        const float dr = float(px.r) / sum - float(color.r) / colorSum, dg = float(px.g) / sum - float(color.g) / colorSum,
                    db = float(px.b) / sum - float(color.b) / colorSum;
        const float distance = std::sqrt(dr * dr + dg * dg + db * db);
        if (distance < nearestDistance) {
            nearest = int(band);
            nearestDistance = distance;
        }
    }
    return nearest;
}

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
        RenderSettings render;
        render.lighting = light;
        std::optional<Application> app = testing::openApplication(defaultHourglass(render, "sandglass warm sand test"), "warm sand");
        if (!app) return;
        app->renderFrame(0.0);
        int grains = 0;
        const std::vector<testing::Pixel> sand = sandPixels(*app, app->captureFrame(), grains);
        const auto warmPixels = std::count_if(sand.begin(), sand.end(), [](testing::Pixel px) { return warm(px.r, px.g, px.b); });
        REQUIRE(int(sand.size()) > grains / 2);
        MESSAGE("warm sand pixels, lighting " << light << ": " << warmPixels << " of " << sand.size()); // shown with -s
        CHECK(std::size_t(warmPixels) * 10 >= sand.size() * 9);
    }
}

TEST_CASE("render: the layers palette draws its colour bands on both grain paths, also when chosen while drawing") {
    if (!testing::requireDisplay("layers palette")) return;
    std::vector<RgbImage> images; // the CPU path's, the GPU path's, the GPU path's after a change of palette
    for (GrainPath path : {GrainPath::CpuFullUpload, GrainPath::GpuInterpolated}) {
        CAPTURE(path == GrainPath::GpuInterpolated);
        RenderSettings render = thesisLook(); // unlit points: every pixel in its band's own colour
        render.palette = SandPalette::Layers;
        render.grainPath = path;
        std::optional<Application> app = testing::openApplication(defaultHourglass(render, "sandglass layers test"), "layers palette");
        if (!app) return;
        app->renderFrame(0.0);
        images.push_back(app->captureFrame());
        int grains = 0;
        const std::vector<testing::Pixel> sand = sandPixels(*app, images.back(), grains);
        REQUIRE(int(sand.size()) > grains / 2);
        std::array<std::size_t, kLayerBands> perBand{};
        for (testing::Pixel px : sand)
            if (const int band = bandOf(px); band >= 0) ++perBand[std::size_t(band)];
        // Bands of at least a twentieth of the sand pixels each: the picture really is banded.
        const auto shown = std::count_if(perBand.begin(), perBand.end(), [&](std::size_t n) { return n * 20 >= sand.size(); });
        MESSAGE("sand pixels per band: " << perBand[0] << " " << perBand[1] << " " << perBand[2] << " " << perBand[3]
                                         << " " << perBand[4] << " " << perBand[5] << " of " << sand.size());
        CHECK(shown >= 2);
    }
    // Desert sand first, then layers: the grains already on the GPU take the new colours.
    RenderSettings render = thesisLook();
    render.grainPath = GrainPath::GpuInterpolated;
    std::optional<Application> app = testing::openApplication(defaultHourglass(render, "sandglass layers test"), "layers palette");
    if (!app) return;
    app->renderFrame(0.0);
    const RgbImage desert = app->captureFrame();
    app->state().render.palette = SandPalette::Layers;
    app->renderFrame(0.0);
    images.push_back(app->captureFrame());
    CHECK(testing::differentPixels(desert, images[2]) > 0);
    CHECK(testing::differentPixels(images[0], images[1]) == 0);
    CHECK(testing::differentPixels(images[0], images[2]) == 0);
}
