// SPDX-License-Identifier: MIT
// The data the GPU draws from: Scribble patterns (V2), packed normals, the glass hull (V6) and
// the benchmark's table form (B1). No GL needed.
#include "app/frame_benchmark.hpp"
#include "view/render/grain_instances.hpp"
#include "view/render/hull_mesh.hpp"
#include "scene/sand_patterns.hpp"
#include "scene/scene_request.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <sstream>

using namespace sandglass;

TEST_CASE("patterns: thesis sand colours, offsets inside the cell, the same on every run") {
    const std::vector<SandPattern> patterns = makeSandPatterns();
    REQUIRE(patterns.size() == std::size_t(kSandPatternCount));
    std::set<std::uint32_t> tints;
    for (const SandPattern& pattern : patterns) {
        tints.insert(pattern.colors[0]);
        for (std::size_t i = 0; i < pattern.colors.size(); ++i) {
            const std::uint32_t c = pattern.colors[i];
            CHECK((c & 0xffu) >= 220u);
            CHECK((c & 0xffu) <= 240u);
            CHECK(((c >> 8) & 0xffu) >= 220u);
            CHECK(((c >> 8) & 0xffu) <= 240u);
            CHECK(((c >> 16) & 0xffu) >= 150u);
            CHECK(((c >> 16) & 0xffu) <= 190u);
            for (float v : pattern.offsets[i]) CHECK(std::abs(v) <= 1.0f);
        }
    }
    CHECK(tints.size() > patterns.size() / 2); // patterns differ from each other
    const std::vector<SandPattern> again = makeSandPatterns();
    CHECK(again[7].colors == patterns[7].colors);
    CHECK(again[7].offsets == patterns[7].offsets);
}

TEST_CASE("patterns: the counter-based hash gives these exact values with every standard library") {
    // Pinned values: std::uniform_*_distribution differs between libstdc++, libc++ and MSVC, the
    // hash does not, so a change here is a change of the look everywhere.
    const std::vector<SandPattern> patterns = makeSandPatterns();
    // S12 made green follow red (warm sand); these are (236, 224, 156) and (239, 223, 172).
    CHECK(patterns[0].colors[1] == 0xff9ce0ecu);
    CHECK(patterns[5].colors[0] == 0xffacdfefu);
    CHECK(patterns[3].offsets[5][0] == -0.019474864f);
    CHECK(patterns[3].offsets[5][1] == -0.952885509f);
    CHECK(patterns[3].offsets[5][2] == -0.778452992f);
    CHECK(patterns[9].offsets[0] == std::array<float, 3>{0.0f, 0.0f, 0.0f}); // sub-grain 0 at the centre
}

TEST_CASE("instances: normals survive packing within 1/500") {
    for (sandcore::Vec3 n : {sandcore::Vec3{0, 1, 0}, sandcore::Vec3{0.6f, 0.8f, 0}, sandcore::Vec3{-0.48f, 0.6f, -0.64f}}) {
        const sandcore::Vec3 back = unpackNormal(packNormal(n));
        CHECK(back.x == doctest::Approx(n.x).epsilon(0.002));
        CHECK(back.y == doctest::Approx(n.y).epsilon(0.002));
        CHECK(back.z == doctest::Approx(n.z).epsilon(0.002));
    }
}

TEST_CASE("instances: hiding inner grains draws only the visible ones") {
    SceneRequest request;
    request.resolution = 24;
    sandcore::Scene scene = buildScene({request, {}});
    GrainInstanceBuilder builder;
    RenderSettings settings;
    const std::size_t all = builder.build(scene, 0.0f, settings).size();
    CHECK(all == std::size_t(scene.grainCount()));
    settings.innerGrains = false;
    builder.sceneChanged();
    const std::size_t visible = builder.build(scene, 0.0f, settings).size();
    CHECK(builder.innerGrainCount() > 0);
    CHECK(visible == all - std::size_t(builder.innerGrainCount()));
}

TEST_CASE("hull: the hourglass gets glass faces, the canvas an outline, the sculpture only a floor") {
    SceneRequest request;
    request.resolution = 24;
    const HullMesh hourglass = buildHullMesh(buildScene({request, {}}), request.kind, 1.0f);
    CHECK(hourglass.triangles.size() > 0);
    CHECK(hourglass.triangles.size() % 6 == 0);
    for (const HullVertex& v : hourglass.triangles)
        CHECK(std::abs(v.nx * v.nx + v.ny * v.ny + v.nz * v.nz - 1.0f) < 1e-3f);
    request.kind = sandcore::SceneKind::Canvas;
    const HullMesh canvas = buildHullMesh(buildScene({request, {}}), request.kind, 1.0f);
    CHECK(canvas.triangles.empty());
    CHECK(canvas.lines.size() == 2 * 12 * 2); // two boxes of 12 edges, 2 vertices each
    request.kind = sandcore::SceneKind::Sculpture;
    const HullMesh sculpture = buildHullMesh(buildScene({request, {}}), request.kind, 1.0f);
    CHECK(sculpture.triangles.empty());
    CHECK(sculpture.lines.size() == 8);
}

TEST_CASE("benchmark: the thesis's table form, every mode with and without light and inner grains") {
    const std::vector<BenchmarkCase> cases = thesisBenchmarkCases();
    CHECK(cases.size() == 32);
    BenchmarkReport report{"hourglass, resolution 38", "test GPU", "3.3 test", 640, 480, {}};
    for (const BenchmarkCase& c : cases) {
        BenchmarkRow row{c, true, true, 3482, 10, 0.5};
        row.gpuMillisecondsPerFrame = 1.25;
        report.rows.push_back(row);
    }
    std::ostringstream text, csv;
    writeBenchmarkText(text, {report}, "sandglass bench --render");
    writeBenchmarkCsv(csv, {report});
    CHECK(text.str().find("Sim\tGui\tMode\tPpC\tfilled\tLight\tinner\tFPS\tB/frame\tmoves\tCPU ms\tapp ms\tupkeep\tGPU ms\n") !=
          std::string::npos);
    CHECK(text.str().find("on\ton\tPBB\t20\t3482\ton\tno\t20.0\t0\t0\t0.00\t0.00\t0.000\t1.25\n") != std::string::npos);
    CHECK(csv.str().find(",fps,upload_bytes_per_frame,moves_per_step,cpu_ms_per_frame,app_cpu_ms_per_frame,upkeep_ms_per_step,"
                         "gpu_ms_per_frame,median_frame_ms,look\n") != std::string::npos);
    CHECK(text.str().find("GPU (GL_RENDERER): test GPU") != std::string::npos);
    CHECK(text.str().find("Driver (GL_VERSION): 3.3 test") != std::string::npos);
    std::istringstream lines(csv.str());
    std::string line;
    int count = 0;
    while (std::getline(lines, line)) ++count;
    CHECK(count == 33);
}

TEST_CASE("benchmark: the look rows compare the default look with the thesis's and with each studio element off") {
    const std::vector<BenchmarkCase> cases = lookBenchmarkCases();
    REQUIRE(cases.size() == 8);
    const RenderSettings standard;
    const RenderSettings first = benchmarkRenderSettings(cases[0], thesisLook());
    CHECK(cases[0].look == "default");
    CHECK((first.mode == standard.mode && first.grainsPerCell == standard.grainsPerCell && first.lighting &&
           first.light == LightRig::Studio && first.ambientOcclusion && first.shadows && first.toneMapping &&
           first.glassEnvironment));
    const RenderSettings thesis = benchmarkRenderSettings(cases[1], RenderSettings{});
    CHECK((thesis.mode == RenderMode::Points && !thesis.lighting && thesis.light == LightRig::Thesis &&
           !thesis.ambientOcclusion && !thesis.shadows && !thesis.toneMapping && !thesis.glassEnvironment));
    CHECK(!benchmarkRenderSettings(cases[2], standard).ambientOcclusion);
    CHECK(!benchmarkRenderSettings(cases[3], standard).shadows);
    CHECK(!benchmarkRenderSettings(cases[4], standard).toneMapping);
    CHECK(!benchmarkRenderSettings(cases[5], standard).glassEnvironment);
    CHECK(!benchmarkRenderSettings(cases[6], standard).lighting);
    CHECK(benchmarkRenderSettings(cases[7], standard).light == LightRig::Thesis);
    BenchmarkReport report{"hourglass, resolution 38", "test GPU", "3.3 test", 640, 480, {}};
    for (const BenchmarkCase& c : cases) {
        BenchmarkRow row{c, true, true, 2123, 10, 0.5};
        row.medianFrameMilliseconds = 48.5;
        report.rows.push_back(row);
    }
    std::ostringstream text;
    writeBenchmarkText(text, {report}, "sandglass bench --render --look");
    CHECK(text.str().find("Look\tMode\tPpC\tfilled\tframe ms\tFPS\tCPU ms\tGPU ms\n") != std::string::npos);
    CHECK(text.str().find("AO off\tPBB\t4\t2123\t48.5\t20.0\t") != std::string::npos);
    CHECK(text.str().find("thesis default\tP\t4\t2123\t48.5\t") != std::string::npos);
}
