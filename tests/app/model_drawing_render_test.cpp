// SPDX-License-Identifier: MIT
// SPEC S10 in pixels: the default scene, the framed hourglass, drawn as modelled. The wooden
// frame is opaque in its MTL colour (the same pixel on a white and a black background, and
// absent when the voxel hull is asked for instead), the sand shows through the glass walls in
// front of it, and the glass is clear where it faces the eye with a rim brighter than its centre.
#include "support/app_test_support.hpp"

#include "app/application.hpp"
#include "scene/scene_request.hpp"

#include "sandcore/display_positions.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

using namespace sandglass;

namespace {

constexpr int kSize = 240;

ApplicationOptions framedHourglass(bool black, bool voxelHull) {
    ApplicationOptions options;
    options.window = {kSize, kSize, false, false, "sandglass model drawing test"};
    options.offscreen = true;
    options.initial.showGui = false;
    options.initial.scene.request.modelPath = defaultModelFor(sandcore::SceneKind::Hourglass);
    options.initial.scene.request.resolution = 32;
    options.initial.render.blackBackground = black;
    options.initial.render.voxelHull = voxelHull;
    return options;
}

using testing::ScreenPoint;

ScreenPoint project(Application& app, glm::vec3 world) { return testing::projectToFrame(app, world, kSize); }

// The centre of a drawn part, world units.
glm::vec3 centreOf(const ModelDrawing& drawing, const std::string& name, float cellSize) {
    for (const DrawnPart& part : drawing.parts)
        if (part.name == name) {
            glm::vec3 sum(0.0f);
            for (const ModelVertex& v : part.vertices) sum += glm::vec3(v.x, v.y, v.z);
            return sum / float(part.vertices.size()) * cellSize;
        }
    FAIL("no part " << name);
    return {};
}

bool wood(testing::Pixel p) { return p.r > p.g && p.g > p.b && p.r > p.b + 25; }
bool warm(testing::Pixel p) { return p.r > p.g && p.g > p.b; }
int brightness(testing::Pixel p) { return p.r + p.g + p.b; }

struct Frame {
    RgbImage image;
    ScreenPoint topPlate{}, lowerBulb{};
    int grainPixels = 0, warmGrainPixels = 0;
    std::int64_t glassTriangles = 0;
};

Frame drawFramedHourglass(bool black, bool voxelHull) {
    Frame frame;
    std::optional<Application> app = testing::openApplication(framedHourglass(black, voxelHull), "the model drawing");
    if (!app) return frame;
    app->renderFrame(0.0);
    frame.image = app->captureFrame();
    const std::shared_ptr<const ModelDrawing>& drawing = app->host().modelDrawing();
    REQUIRE(drawing != nullptr);
    const float cellSize = app->state().render.cellSize;
    frame.topPlate = project(*app, centreOf(*drawing, "top_plate", cellSize));
    // The middle of the lower bulb, still empty: glass only.
    glm::vec3 glass = centreOf(*drawing, "glass", cellSize);
    float low = 1e30f, high = -1e30f;
    for (const ModelVertex& v : drawing->parts[0].vertices) low = std::min(low, v.y), high = std::max(high, v.y);
    glass.y = (low + 0.25f * (high - low)) * cellSize;
    frame.lowerBulb = project(*app, glass);
    for (const DrawnPart& part : drawing->parts)
        if (part.look == PartLook::Glass) frame.glassTriangles += std::int64_t(part.vertices.size() / 3);
    const sandcore::Scene& scene = app->scene();
    std::vector<sandcore::Vec3> positions(scene.grains().size());
    sandcore::writeDisplayPositions(scene, app->displayStepFraction(), {cellSize, app->state().render.jitter}, positions);
    for (const sandcore::Vec3& p : positions) {
        const ScreenPoint s = project(*app, {p.x, p.y, p.z});
        if (s.x < 0 || s.y < 0 || s.x >= kSize || s.y >= kSize) continue;
        ++frame.grainPixels;
        if (warm(testing::pixelAt(frame.image, s.x, s.y))) ++frame.warmGrainPixels;
    }
    return frame;
}

} // namespace

TEST_CASE("render: the framed hourglass is drawn as modelled, an opaque frame and glass the sand shows through") {
    if (!testing::requireDisplay("the model drawing")) return;
    const Frame white = drawFramedHourglass(false, false);
    const Frame black = drawFramedHourglass(true, false);
    const Frame voxels = drawFramedHourglass(false, true);
    REQUIRE(white.image.width == kSize);
    REQUIRE(black.image.width == kSize);
    REQUIRE(voxels.image.width == kSize);
    CHECK(white.glassTriangles > 1000);

    // The frame: wood, the same on either background (opaque), not there in the voxel hull's look.
    const testing::Pixel plateOnWhite = testing::pixelAt(white.image, white.topPlate.x, white.topPlate.y);
    const testing::Pixel plateOnBlack = testing::pixelAt(black.image, black.topPlate.x, black.topPlate.y);
    CAPTURE(plateOnWhite.r);
    CAPTURE(plateOnWhite.g);
    CAPTURE(plateOnWhite.b);
    MESSAGE("top plate " << plateOnWhite.r << " " << plateOnWhite.g << " " << plateOnWhite.b); // with -s
    CHECK(wood(plateOnWhite));
    CHECK(std::abs(plateOnWhite.r - plateOnBlack.r) <= 2);
    CHECK(std::abs(plateOnWhite.g - plateOnBlack.g) <= 2);
    CHECK(std::abs(plateOnWhite.b - plateOnBlack.b) <= 2);
    // In the voxel hull's look no frame is drawn: where the plate was, at most the pale hull of
    // the sand space's top cells (which reach the plate's lower face).
    const testing::Pixel plateAsVoxels = testing::pixelAt(voxels.image, voxels.topPlate.x, voxels.topPlate.y);
    CHECK(!wood(plateAsVoxels));
    CHECK(brightness(plateAsVoxels) >= 3 * 220);

    // The sand inside both glass walls: its pixels stay sand coloured behind the near wall.
    REQUIRE(white.grainPixels > 100);
    MESSAGE("warm grain pixels behind the glass: " << white.warmGrainPixels << " of " << white.grainPixels); // with -s
    CHECK(white.warmGrainPixels * 10 >= white.grainPixels * 9);

    // The glass over the empty lower bulb, on black: faint where it faces the eye, a brighter
    // rim where it turns away, on both sides of the bulb.
    const int row = black.lowerBulb.y;
    const testing::Pixel centre = testing::pixelAt(black.image, black.lowerBulb.x, row);
    CAPTURE(centre.r);
    CAPTURE(centre.g);
    CAPTURE(centre.b);
    CHECK(brightness(centre) > 0);    // glass is there
    CHECK(brightness(centre) < 200);  // and nearly clear
    for (int direction : {-1, 1}) {
        CAPTURE(direction);
        int rim = 0;
        for (int x = black.lowerBulb.x; x >= 0 && x < kSize; x += direction) {
            const testing::Pixel p = testing::pixelAt(black.image, x, row);
            if (!wood(p)) rim = std::max(rim, brightness(p));
        }
        MESSAGE("glass on black, side " << direction << ": rim " << rim << ", centre " << brightness(centre)); // with -s
        CHECK(rim > brightness(centre) + 90);
    }
}
