// SPDX-License-Identifier: MIT
// SPEC V8 with R12, R13: the GPU path that works out inner flags and gradient normals from the
// cells' occupancy bits draws exactly what the CPU path draws from sandcore's flags and normals:
// on the hourglass after frames that upload only changes, and on a canvas whose grains lie on
// every face of both grids and on the seam between them (where "outside the grid hides" makes
// edge grains inner, visible from outside), unlit, lit by the thesis's light and in the studio
// look (lit pseudo-billboards, occlusion from the same cell reads, shadows, tone mapping), inner
// grains hidden and shown.
#include "support/app_test_support.hpp"

#include "app/application.hpp"
#include "scene/scene_host.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

using namespace sandglass;

namespace {

enum class Path { Cpu, GpuCellBits, GpuGrainFlags };

const char* pathName(Path path) {
    return path == Path::Cpu ? "cpu" : path == Path::GpuCellBits ? "gpu, cell bits" : "gpu, per-grain flags";
}

// The environment switch is read when the store decides, so it is set around the whole run. It
// forces the cell bits too: on a software GL the store would draw hidden inner grains per grain.
struct GrainFlagsSwitch {
    explicit GrainFlagsSwitch(bool perGrain) { setenv("SANDGLASS_GPU_CELL_BITS", perGrain ? "0" : "1", 1); }
    ~GrainFlagsSwitch() { unsetenv("SANDGLASS_GPU_CELL_BITS"); }
};

// The thesis's points unlit and lit (by the occupancy gradient, the default method), and the default studio look.
enum class Look { Unlit, ThesisLight, Studio };

const char* lookName(Look look) { return look == Look::Unlit ? "unlit" : look == Look::ThesisLight ? "thesis light" : "studio"; }

RenderSettings renderSettings(Path path, Look look, bool inner) {
    RenderSettings render = look == Look::Studio ? RenderSettings{} : thesisLook();
    render.lighting = look != Look::Unlit;
    render.innerGrains = inner;
    render.grainPath = path == Path::Cpu ? GrainPath::CpuFullUpload : GrainPath::GpuInterpolated;
    return render;
}

// Grains on every face of a grid and at its corners, blocks whose middle grains are inner, and
// layers with holes on both sides of the seam (the lower grid's top two rows, the upper grid's
// bottom two), each with its own pattern of holes: a grain there is inner or not by what the
// other grid holds.
void fillEdgesAndSeam(sandcore::Scene& scene) {
    for (sandcore::GridLevel level : {sandcore::GridLevel::Lower, sandcore::GridLevel::Upper}) {
        const sandcore::CellGrid& grid = scene.grid(level);
        const sandcore::Int3 s = grid.size();
        auto add = [&](int x, int y, int z) {
            if (!grid.contains(x, y, z)) return;
            const std::uint32_t cell = grid.index(x, y, z);
            if (grid[cell] == sandcore::kEmpty) scene.addGrain(level, cell, (x * 7 + z * 13) % 3 == 0 ? 0xff3050c0u : 0u);
        };
        const bool lower = level == sandcore::GridLevel::Lower;
        for (int z = 0; z < s.z; ++z)
            for (int x = 0; x < s.x; ++x) {
                const bool holes[2] = {lower ? (x + 2 * z) % 5 == 0 : (x + 3 * z) % 4 == 0,  // lower top-1, upper 0
                                       lower ? (2 * x + z) % 7 == 0 : (x + z) % 3 == 0}; // lower top, upper 1
                if (!holes[0]) add(x, lower ? s.y - 2 : 0, z);
                if (!holes[1]) add(x, lower ? s.y - 1 : 1, z);
            }
        // 3x3x3 blocks in the corners (their middle grain and the corner's own are inner).
        for (int cx : {0, s.x - 3})
            for (int cz : {0, s.z - 3})
                for (int y = 0; y < 3; ++y)
                    for (int z = cz; z < cz + 3; ++z)
                        for (int x = cx; x < cx + 3; ++x) add(x, lower ? y : s.y - 3 + y, z);
    }
}

// Frames as opened, steeply from above and from below (where the grains under the seam and the
// bottom corners show; the canvas keeps its own top view): first with everything uploaded, then after `steps` stepped frames, each of which
// uploads only changes on the GPU path.
std::vector<RgbImage> picturesOf(Path path, Look look, bool inner, bool canvas, int steps, std::int64_t* innerGrains) {
    const GrainFlagsSwitch perGrain(path == Path::GpuGrainFlags);
    // Canvas rows of 20 cells: the 32-bit words of the cell bits begin and end inside rows too.
    ApplicationOptions options = canvas ? testing::canvasOptions(200, 160, 20, "cell bits on the GPU")
                                        : testing::proceduralHourglassOptions(160, 160, 24, "cell bits on the GPU");
    options.initial.render = renderSettings(path, look, inner);
    options.initial.simulationRunning = false;
    options.stepsBeforeStart = canvas ? 0 : 40;
    std::optional<Application> app = testing::openApplication(std::move(options), "cell bits on the GPU");
    REQUIRE(app);
    if (canvas) fillEdgesAndSeam(app->host().editScene());
    std::vector<RgbImage> pictures;
    auto bothViews = [&] {
        const float pitch = app->camera().pitch();
        for (float to : {pitch, 1.3f, -1.3f}) { // as opened, steeply from above (into holes), from below
            app->camera().rotate(0.0f, to - app->camera().pitch());
            app->renderFrame(0.0);
            pictures.push_back(app->captureFrame());
        }
        app->camera().rotate(0.0f, pitch - app->camera().pitch());
    };
    bothViews();
    for (int step = 0; step < steps; ++step) {
        app->runSteps(1);
        app->renderFrame(0.0);
        if (path != Path::Cpu) REQUIRE(!app->renderer().stats().fullUpload);
    }
    bothViews();
    if (path != Path::Cpu) CHECK(app->renderer().gpuStore().flagsFromBits() == (path == Path::GpuCellBits));
    *innerGrains = app->renderer().stats().innerGrains;
    return pictures;
}

} // namespace

TEST_CASE("V8: grains at the grid edges and the seam: the GPU's flags and normals from the cell bits draw the CPU's picture") {
    if (!testing::requireDisplay("cell bits on the GPU")) return;
    for (bool canvas : {true, false})
        for (Look look : {Look::ThesisLight, Look::Unlit, Look::Studio})
            for (bool inner : {false, true}) {
                CAPTURE(canvas);
                CAPTURE(lookName(look));
                CAPTURE(inner);
                std::int64_t innerCpu = 0;
                const std::vector<RgbImage> reference = picturesOf(Path::Cpu, look, inner, canvas, 6, &innerCpu);
                CHECK(innerCpu > 0); // there are inner grains to hide
                for (Path path : {Path::GpuCellBits, Path::GpuGrainFlags}) {
                    CAPTURE(pathName(path));
                    std::int64_t innerGpu = 0;
                    const std::vector<RgbImage> gpu = picturesOf(path, look, inner, canvas, 6, &innerGpu);
                    CHECK(innerGpu == innerCpu);
                    REQUIRE(gpu.size() == reference.size());
                    for (std::size_t picture = 0; picture < gpu.size(); ++picture) {
                        CAPTURE(picture); // 0-2: the three views before the steps; 3-5: after them
                        CHECK(testing::differentPixels(gpu[picture], reference[picture]) == 0);
                    }
                }
            }
}

TEST_CASE("V8: inner grains hidden and shown draw different pictures at the grid edges (the check above can fail)") {
    if (!testing::requireDisplay("cell bits on the GPU")) return;
    std::int64_t inner = 0;
    const std::vector<RgbImage> hidden = picturesOf(Path::GpuCellBits, Look::ThesisLight, false, true, 0, &inner);
    const std::vector<RgbImage> shown = picturesOf(Path::GpuCellBits, Look::ThesisLight, true, true, 0, &inner);
    // A corner grain is inner (the grid's outside hides it) yet faces the camera: showing it shows.
    CHECK(testing::differentPixels(hidden[0], shown[0]) > 0);
    CHECK(testing::differentPixels(hidden[1], shown[1]) > 0);
    CHECK(testing::differentPixels(hidden[2], shown[2]) > 0);
}

TEST_CASE("V8: a software GL draws hidden inner grains from the per-grain flags, shown ones from the cell bits") {
    CHECK(isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    CHECK(isSoftwareRenderer("SwiftShader Device (Subzero)"));
    CHECK_FALSE(isSoftwareRenderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
    CHECK_FALSE(isSoftwareRenderer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7, DRM 3.54)"));
    if (!testing::requireDisplay("cell bits on the GPU")) return;
    unsetenv("SANDGLASS_GPU_CELL_BITS");
    for (bool inner : {false, true}) {
        CAPTURE(inner);
        ApplicationOptions options = testing::proceduralHourglassOptions(160, 160, 24, "cell bits on the GPU");
        options.initial.render = renderSettings(Path::GpuCellBits, Look::ThesisLight, inner);
        options.initial.simulationRunning = false;
        std::optional<Application> app = testing::openApplication(std::move(options), "cell bits on the GPU");
        REQUIRE(app);
        app->renderFrame(0.0);
        const GrainGpuStore& store = app->renderer().gpuStore();
        // The tests draw with Mesa's llvmpipe; on a GPU the cell bits serve both at few vertices a grain.
        CHECK(store.flagsFromBits() == !hiddenInnerGrainsFromList(store.softwareRenderer(), app->state().render));
        CHECK(store.flagsFromBits() == (inner || !store.softwareRenderer()));
        app->runSteps(3);
        app->renderFrame(0.0);
        CHECK(!app->renderer().stats().fullUpload);
    }
}

TEST_CASE("V8: with inner grains hidden, a GPU draws from the visible list once a grain costs 8 vertex runs") {
    RenderSettings render;
    render.innerGrains = true;
    for (bool software : {false, true}) CHECK_FALSE(hiddenInnerGrainsFromList(software, render)); // shown: the bits
    render.innerGrains = false;
    render.mode = RenderMode::Points;
    render.grainsPerCell = 1;
    CHECK(hiddenInnerGrainsFromList(true, render)); // a software GL: always the list
    struct Case {
        RenderMode mode;
        int grainsPerCell;
        int vertices;
        bool fromList;
    };
    const Case cases[] = {{RenderMode::Points, 1, 1, false},          {RenderMode::Points, 4, 4, false},
                          {RenderMode::Sprites, 7, 7, false},         {RenderMode::Points, 8, 8, true},
                          {RenderMode::Points, 20, 20, true},         {RenderMode::Billboards, 1, 4, false},
                          {RenderMode::Billboards, 2, 8, true},       {RenderMode::PseudoBillboards, 20, 80, true},
                          {RenderMode::Points, 0, 1, false},          {RenderMode::PseudoBillboards, 100, 128, true}};
    for (const Case& c : cases) {
        CAPTURE(int(c.mode));
        CAPTURE(c.grainsPerCell);
        render.mode = c.mode;
        render.grainsPerCell = c.grainsPerCell; // out of 1..32: clamped as the renderer clamps it
        CHECK(verticesPerGrain(render) == c.vertices);
        CHECK(hiddenInnerGrainsFromList(false, render) == c.fromList);
        CHECK(hiddenInnerGrainsFromList(true, render));
    }
}
