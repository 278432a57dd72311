// SPDX-License-Identifier: MIT
// The granular wakes of an emptied cell c's own layer (grid_sweep.cpp) read tables of the slides
// across c, target column by target column (GranularRules::grainsWithOpenSlideAcrossCentreTo),
// over the columns some of the grains slide into (GranularRules::targetsAcrossCentreOf).
// Here the tables are checked against the slides themselves, and the wakes against a full sweep
// where sand lies against the grid's sides and on its lowest layers, where the windows read the
// kept bits' margins.
#include "granular_rules.hpp"

#include "sandcore/inside_mask.hpp"
#include "sandcore/scenes.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <random>

using namespace sandcore;

namespace {

constexpr int kReach = kGranularReach, kWindow = GranularRules::kWindow;
constexpr int kAcross = GranularRules::kAcrossReach, kAcrossWindow = GranularRules::kAcrossWindow;

// Window bit of the cell (dx, dz) from the window's centre.
int windowBit(int dx, int dz) { return (dz + kReach) * kWindow + dx + kReach; }

// From the slides' own paths: the grains around c (of `among`) with a slide into column t (from c)
// whose path crosses c and lies EMPTY in `clear`.
std::uint64_t openSlidesAcrossCentreTo(const GranularRules& rules, int tx, int tz, std::uint64_t among, std::uint64_t clear) {
    std::uint64_t grains = 0;
    for (int k = 0; k < GranularRules::kOffsets; ++k) {
        const GranularRules::Offset& o = rules.offset(k);
        const int bx = tx - o.dx, bz = tz - o.dz; // the grain, from c
        if (std::abs(bx) > kReach || std::abs(bz) > kReach || !(among >> windowBit(bx, bz) & 1)) continue;
        bool crossesCentre = false, open = true;
        for (int cell = 0; cell < kWindow * kWindow; ++cell) {
            if (!(o.pathMask >> cell & 1)) continue;
            const int px = cell % kWindow - kReach + bx, pz = cell / kWindow - kReach + bz; // from c
            crossesCentre = crossesCentre || (px == 0 && pz == 0);
            open = open && std::abs(px) <= kReach && std::abs(pz) <= kReach && (clear >> windowBit(px, pz) & 1);
        }
        if (crossesCentre && open) grains |= std::uint64_t{1} << windowBit(bx, bz);
    }
    return grains;
}

StepSettings granular(std::uint64_t seed, float repose) {
    StepSettings step;
    step.seed = seed;
    step.physics.level = PhysicsLevel::Granular;
    step.physics.reposeDegrees = repose;
    step.physics.gravity = 1.0f;
    return step;
}

GranularRules granularRulesAt(float repose) {
    PhysicsSettings physics;
    physics.level = PhysicsLevel::Granular;
    physics.reposeDegrees = repose;
    return GranularRules(physics);
}

} // namespace

TEST_CASE("granular wake tables: the grains with an open slide across a cell into each column are those the "
          "slides' paths give") {
    std::mt19937_64 random(5);
    const std::uint64_t window = (std::uint64_t{1} << (kWindow * kWindow)) - 1;
    for (float repose : {20.0f, 33.0f, 45.0f}) {
        CAPTURE(repose);
        const GranularRules rules = granularRulesAt(repose);
        // Every slide whose path crosses c ends in one of the 5x5 columns: all open, every grain.
        int slides = 0;
        for (int t = 0; t < kAcrossWindow * kAcrossWindow; ++t)
            for (std::uint64_t g = rules.grainsWithOpenSlideAcrossCentreTo(t, window, window); g; g &= g - 1) ++slides;
        int pathCells = 0;
        for (int k = 0; k < GranularRules::kOffsets; ++k)
            for (std::uint64_t p = rules.offset(k).pathMask; p; p &= p - 1) ++pathCells;
        CHECK(slides == pathCells);
        // The columns a wake asks about, grain by grain (the random windows below hold many).
        for (int bit = 0; bit < kWindow * kWindow; ++bit) {
            std::uint32_t targets = 0;
            for (int t = 0; t < kAcrossWindow * kAcrossWindow; ++t)
                if (openSlidesAcrossCentreTo(rules, t % kAcrossWindow - kAcross, t / kAcrossWindow - kAcross,
                                             std::uint64_t{1} << bit, window))
                    targets |= 1u << t;
            CHECK_MESSAGE(rules.targetsAcrossCentreOf(std::uint64_t{1} << bit) == targets, "grain at window bit " << bit);
        }
        for (int trial = 0; trial < 2000; ++trial) {
            // Dense and sparse windows, some around a centre the path must cross taken.
            const std::uint64_t clear = (trial % 3 == 0 ? random() | random() : random() & random()) & window;
            const std::uint64_t among = (trial % 2 == 0 ? ~std::uint64_t{0} : random()) & window;
            // The columns a wake asks about: those into which some grain of `among` slides across c.
            std::uint32_t targets = 0;
            for (int t = 0; t < kAcrossWindow * kAcrossWindow; ++t) {
                const int tx = t % kAcrossWindow - kAcross, tz = t / kAcrossWindow - kAcross;
                const std::uint64_t expected = openSlidesAcrossCentreTo(rules, tx, tz, among, clear);
                if (rules.grainsWithOpenSlideAcrossCentreTo(t, among, clear) != expected)
                    FAIL("column (" << tx << ", " << tz << "), clear " << clear << ", among " << among);
                if (openSlidesAcrossCentreTo(rules, tx, tz, among, window)) targets |= 1u << t;
            }
            if (rules.targetsAcrossCentreOf(among) != targets) FAIL("targets across the centre, among " << among);
        }
    }
}

TEST_CASE("granular: sand against the grid's sides and on its lowest layers moves as a full sweep moves it") {
    // Two box-shaped bulbs joined by a 3x3 neck: each bulb is as wide and deep as the grid, so the
    // sand lies against the grid's sides in x and z, drains from them towards the neck and piles
    // up to them on the lower grid's floor, where the windows of the wakes and slides reach past
    // the grid and below layer 0 (the kept bits' margins).
    const Int3 size{21, 24, 19};
    InsideMask box = InsideMask::empty(size);
    for (int y = 0; y < size.y; ++y)
        for (int z = 0; z < size.z; ++z)
            for (int x = 0; x < size.x; ++x) {
                const bool neck = y >= 10 && y < 12;
                if (!neck || (std::abs(x - size.x / 2) <= 1 && std::abs(z - size.z / 2) <= 1)) box.set(x, y, z, true);
            }
    for (std::uint64_t seed : {3ull, 8ull}) {
        for (float repose : {25.0f, 40.0f}) {
            CAPTURE(seed);
            CAPTURE(repose);
            Scene sleeping = makeHourglassScene(box, {}, granular(seed, repose));
            Scene full = makeHourglassScene(box, {}, granular(seed, repose));
            full.setSleeping(false);
            const std::int64_t grains = sleeping.grainCount();
            int step = 0;
            for (; step < 3000 && !sleeping.settled(); ++step) {
                sleeping.step();
                full.step();
                REQUIRE_MESSAGE(sleeping.stateHash() == full.stateHash(), "states differ after step " << step + 1);
                REQUIRE(sleeping.sweepsMatchCells());
            }
            CHECK(sleeping.settled());
            CHECK(sleeping.grainCount() == grains);
            CHECK(sleeping.counters().grainsLower > 0);
        }
    }
}

TEST_CASE("granular wake tables: the grains around a column by the whole cells of their slide's need agree with "
          "needsDepth grain by grain") {
    std::mt19937_64 random(11);
    for (float repose : {20.0f, 33.0f, 45.0f}) {
        CAPTURE(repose);
        const GranularRules rules = granularRulesAt(repose);
        std::uint64_t covered = 0;
        for (int whole = 0; whole <= rules.maxDrop(); ++whole) {
            CHECK((covered & rules.towardsCentreWithWhole(whole)) == 0); // each grain has one whole part
            covered |= rules.towardsCentreWithWhole(whole);
        }
        CHECK(covered == rules.towardsCentreWithWholeAtLeast(0));
        CHECK(rules.towardsCentreWithWhole(rules.maxDrop() + 1) == 0);
        for (int bit = 0; bit < kWindow * kWindow; ++bit) {
            const int dx = bit % kWindow - kReach, dz = bit / kWindow - kReach; // the grain, from the column
            CHECK(((covered >> bit) & 1) == (dx != 0 || dz != 0 ? 1u : 0u));
            if (dx == 0 && dz == 0) continue;
            const int slide = GranularRules::offsetIndex(-dx, -dz);
            int whole = 0;
            while (!(rules.towardsCentreWithWhole(whole) >> bit & 1)) ++whole;
            for (int trial = 0; trial < 50; ++trial) {
                const int x = int(random() % 500), z = int(random() % 500);
                const std::uint64_t seed = random(), grid = random() & 1; // drawn in this order
                const ThresholdDither dither(seed, grid);
                const bool carried = rules.carries(dither, x, z, slide);
                for (int depth = 2; depth <= rules.maxDrop() + 1; ++depth) {
                    const bool expected = depth <= whole || (depth == whole + 1 && carried);
                    if (rules.needsDepth(dither, x, z, slide, depth) != expected)
                        FAIL("grain at (" << dx << ", " << dz << "), depth " << depth << ", column " << x << ", " << z);
                    const bool atLeast = rules.towardsCentreWithWholeAtLeast(depth) >> bit & 1;
                    CHECK(atLeast == (whole >= depth));
                }
            }
        }
    }
}

TEST_CASE("granular thresholds: the slide's carries of all 48 slides at once agree with carries() slide by slide") {
    // The slide reads them 16 at a time with saturating byte compares (SSE2); carries() compares
    // one byte. Over several angles (other rests, so other compares), seeds, both grids and
    // columns near and far from 0, including the 64-column tile's edges.
    std::mt19937_64 random(23);
    int carried = 0, notCarried = 0;
    for (float repose : {20.0f, 25.0f, 33.0f, 40.0f, 43.0f, 45.0f}) {
        CAPTURE(repose);
        const GranularRules rules = granularRulesAt(repose);
        for (int trial = 0; trial < 400; ++trial) {
            const std::uint64_t seed = random(), grid = random() & 1; // drawn in this order
            const ThresholdDither dither(seed, grid);
            const int x = trial < 8 ? 63 * (trial & 1) + 64 * (trial >> 2) : int(random() % 1000);
            const int z = trial < 8 ? 63 * ((trial >> 1) & 1) : int(random() % 1000);
            const std::uint64_t all = rules.carriedSlides(dither, x, z);
            CHECK((all >> GranularRules::kOffsets) == 0);
            for (int k = 0; k < GranularRules::kOffsets; ++k) {
                const bool one = rules.carries(dither, x, z, k);
                if (bool(all >> k & 1) != one) FAIL("slide " << k << ", column " << x << ", " << z << ", seed " << seed);
                ++(one ? carried : notCarried);
            }
        }
    }
    // Both answers occur often, so a mask that is always 0 or always full would fail above.
    CHECK(carried > 10000);
    CHECK(notCarried > 10000);
}
