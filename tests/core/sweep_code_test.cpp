// SPDX-License-Identifier: MIT
// The sweep's two builds (sandcore/sweep_code.hpp): which one a step runs, and that both give
// the same steps, under either rules, sleeping or not, on one thread or two, and when a scene
// changes build halfway.
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/scenes.hpp"
#include "sandcore/sweep_code.hpp"

#include <doctest/doctest.h>

using namespace sandcore;

namespace {

Scene hourglass(PhysicsLevel level, SweepCode code, int threads, bool sleeping) {
    StepSettings step;
    step.seed = 9;
    step.threads = threads;
    step.sleeping = sleeping;
    step.physics.level = level;
    step.physics.gravity = 0.05f;
    step.sweepCode = code;
    return makeHourglassScene(makeHourglassMask({40, 2.0f, 0.0f}), {}, step);
}

// Steps the scene once and tells whether the BMI2 build swept any of its grids.
bool stepRanBmi2(Scene& scene) {
    const std::uint64_t before = bmi2SweepsRun();
    scene.step();
    return bmi2SweepsRun() != before;
}

// Steps both scenes together and requires the same state, moves and falls after every step,
// each step run by the build its scene asks for.
void requireSameSteps(Scene& a, Scene& b, int steps) {
    for (int i = 0; i < steps; ++i) {
        REQUIRE(stepRanBmi2(a) == runsBmi2Sweep(a.settings().physics.level, a.settings().sweepCode));
        REQUIRE(stepRanBmi2(b) == runsBmi2Sweep(b.settings().physics.level, b.settings().sweepCode));
        REQUIRE_MESSAGE(a.stateHash() == b.stateHash(), "states differ after step " << i + 1);
        REQUIRE(a.counters().movesLastStep == b.counters().movesLastStep);
        REQUIRE(a.counters().visitedLastStep == b.counters().visitedLastStep);
        REQUIRE(a.counters().speedChangesLastStep == b.counters().speedChangesLastStep);
    }
    for (std::uint32_t id = 0; id < std::uint32_t(a.grainCount()); ++id) REQUIRE(a.fallOf(id) == b.fallOf(id));
    REQUIRE(a.sweepsMatchCells());
    REQUIRE(b.sweepsMatchCells());
}

} // namespace

TEST_CASE("the sweep's build is chosen by the rules, the setting and the CPU") {
    CHECK(sweepCodeName(PhysicsLevel::Classic, SweepCode::Portable) == "portable");
    CHECK(sweepCodeName(PhysicsLevel::Granular, SweepCode::Portable) == "portable");
    // Classic steps keep the portable build unless asked; granular ones take the BMI2 build
    // wherever it runs.
    CHECK_FALSE(runsBmi2Sweep(PhysicsLevel::Classic, SweepCode::Fastest));
    CHECK(runsBmi2Sweep(PhysicsLevel::Granular, SweepCode::Fastest) == bmi2SweepAvailable());
    CHECK(runsBmi2Sweep(PhysicsLevel::Classic, SweepCode::Bmi2) == bmi2SweepAvailable());
    CHECK(sweepCodeName(PhysicsLevel::Granular, SweepCode::Fastest) == (bmi2SweepAvailable() ? "bmi2" : "portable"));
    if (!bmi2SweepBuilt()) CHECK_FALSE(bmi2SweepAvailable());
#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__) && !defined(__clang__)
    // GCC on x86-64 Linux links with GNU ld, so the build is there: a build step that quietly
    // dropped it would otherwise only show as lost speed.
    CHECK(bmi2SweepBuilt());
#endif
    // The steps themselves run the build chosen: classic by default the portable one.
    Scene classic = hourglass(PhysicsLevel::Classic, SweepCode::Fastest, 1, true);
    Scene granular = hourglass(PhysicsLevel::Granular, SweepCode::Fastest, 1, true);
    for (int i = 0; i < 5; ++i) {
        CHECK_FALSE(stepRanBmi2(classic));
        CHECK(stepRanBmi2(granular) == bmi2SweepAvailable());
    }
    classic.setSweepCode(SweepCode::Bmi2);
    CHECK(stepRanBmi2(classic) == bmi2SweepAvailable());
    granular.setSweepCode(SweepCode::Portable);
    CHECK_FALSE(stepRanBmi2(granular));
}

TEST_CASE("the sweep's choices are spelt as the command line spells them") {
    for (SweepCode code : {SweepCode::Fastest, SweepCode::Portable, SweepCode::Bmi2})
        CHECK(parseSweepCode(sweepCodeChoiceName(code)) == code);
    CHECK(parseSweepCode("BMI2") == SweepCode::Bmi2);
    CHECK_FALSE(parseSweepCode("avx2").has_value());
    CHECK_FALSE(parseSweepCode("").has_value());
    CHECK_FALSE(parseSweepCode("bmi").has_value());
}

TEST_CASE("both builds of the sweep step alike") {
    for (PhysicsLevel level : {PhysicsLevel::Classic, PhysicsLevel::Granular})
        for (int threads : {1, 2})
            for (bool sleeping : {true, false}) {
                CAPTURE(physicsLevelName(level));
                CAPTURE(threads);
                CAPTURE(sleeping);
                Scene portable = hourglass(level, SweepCode::Portable, threads, sleeping);
                Scene bmi2 = hourglass(level, SweepCode::Bmi2, threads, sleeping);
                CHECK(portable.grainCount() > 2000);
                requireSameSteps(portable, bmi2, 400);
                CHECK(portable.counters().grainsLower > 0); // sand passed the neck
            }
}

TEST_CASE("a scene that changes build halfway goes on as if it had not") {
    for (PhysicsLevel level : {PhysicsLevel::Classic, PhysicsLevel::Granular}) {
        CAPTURE(physicsLevelName(level));
        Scene portable = hourglass(level, SweepCode::Portable, 2, true);
        Scene switching = hourglass(level, SweepCode::Bmi2, 2, true);
        requireSameSteps(portable, switching, 150);
        switching.setSweepCode(SweepCode::Portable);
        requireSameSteps(portable, switching, 150);
        switching.setSweepCode(SweepCode::Bmi2);
        requireSameSteps(portable, switching, 150);
        CHECK(switching.settings().sweepCode == SweepCode::Bmi2);
    }
}
