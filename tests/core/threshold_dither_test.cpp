// SPDX-License-Identifier: MIT
// The fixed dither of the granular thresholds (threshold_dither.hpp): a blue-noise tile kept as
// data, and the views of it that the 48 slides of each grid read.
#include "threshold_dither.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

using namespace sandcore;

namespace {

constexpr int kSide = kDitherTileSide;

// Variance of the sums of `tile` over every w x w square (wrapping around).
double squareSumVariance(const std::vector<int>& tile, int w) {
    double sum = 0, squares = 0;
    for (int z = 0; z < kSide; ++z)
        for (int x = 0; x < kSide; ++x) {
            double s = 0;
            for (int dz = 0; dz < w; ++dz)
                for (int dx = 0; dx < w; ++dx) s += tile[std::size_t((x + dx) % kSide + kSide * ((z + dz) % kSide))];
            sum += s;
            squares += s * s;
        }
    const double n = kSide * kSide, mean = sum / n;
    return squares / n - mean * mean;
}

double correlation(const std::vector<int>& a, const std::vector<int>& b) {
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
    ma /= double(a.size());
    mb /= double(b.size());
    double ab = 0, aa = 0, bb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ab += (a[i] - ma) * (b[i] - mb);
        aa += (a[i] - ma) * (a[i] - ma);
        bb += (b[i] - mb) * (b[i] - mb);
    }
    return ab / std::sqrt(aa * bb);
}

// Slide k's dither over one tile's worth of columns, from column (x0, z0).
std::vector<int> viewOf(const ThresholdDither& dither, int k, int x0 = 0, int z0 = 0) {
    std::vector<int> view;
    for (int z = 0; z < kSide; ++z)
        for (int x = 0; x < kSide; ++x) view.push_back(int(dither.of(x0 + x, z0 + z, k)));
    return view;
}

} // namespace

TEST_CASE("threshold dither: the kept tile is the generator's") {
    const std::vector<std::uint8_t> generated = blueNoiseTile(kSide, 1.9, 1);
    REQUIRE(generated.size() == kDitherTile.size());
    CHECK(std::equal(generated.begin(), generated.end(), kDitherTile.begin()));
    CHECK_THROWS_AS(blueNoiseTile(3, 1.9, 1), std::invalid_argument); // too small for a start pattern
    CHECK_THROWS_AS(blueNoiseTile(8, 0.0, 1), std::invalid_argument);
}

TEST_CASE("threshold dither: the tile holds every value equally often, spread as blue noise") {
    std::array<int, 256> count{};
    for (std::uint8_t v : kDitherTile) ++count[v];
    CHECK(std::all_of(count.begin(), count.end(), [](int c) { return c == kSide * kSide / 256; }));
    // Sums over squares of columns stay close to their mean: against the same values in a random
    // order (white noise), the variance of a 4x4 square's sum is about a fifth, of an 8x8 one an
    // eighth. For m of the N values drawn at random the sum's variance is m s^2 (N - m) / (N - 1),
    // s^2 the values' variance.
    std::vector<int> blue(kDitherTile.begin(), kDitherTile.end());
    double mean = 0, variance = 0;
    for (int v : blue) mean += v;
    mean /= double(blue.size());
    for (int v : blue) variance += (v - mean) * (v - mean);
    variance /= double(blue.size());
    auto whiteVariance = [&](int w) {
        const double m = w * w, n = double(blue.size());
        return m * variance * (n - m) / (n - 1);
    };
    const double ratio4 = squareSumVariance(blue, 4) / whiteVariance(4);
    const double ratio8 = squareSumVariance(blue, 8) / whiteVariance(8);
    CAPTURE(ratio4);
    CAPTURE(ratio8);
    CHECK(ratio4 < 0.3);
    CHECK(ratio8 < 0.15);
    // A single column says nothing of its neighbour's value (no gradient or stripes).
    std::vector<int> right(blue.size());
    for (int z = 0; z < kSide; ++z)
        for (int x = 0; x < kSide; ++x) right[std::size_t(x + kSide * z)] = blue[std::size_t((x + 1) % kSide + kSide * z)];
    CHECK(correlation(blue, right) < 0.0); // blue noise: a high value's neighbours lean low
}

TEST_CASE("threshold dither: each slide reads the whole tile shifted, the 48 views apart, picked by the seed and the grid") {
    // The shift at which slide k's view is the tile, found by trying every one and checked over a
    // whole tile's worth of columns from far out in the grid; -1 if none fits.
    auto shiftOf = [](const ThresholdDither& dither, int k) {
        for (int shift = 0; shift < kSide * kSide; ++shift) {
            const int sx = shift % kSide, sz = shift / kSide;
            bool fits = true;
            for (int z = 0; z < kSide && fits; ++z)
                for (int x = 0; x < kSide && fits; ++x)
                    fits = dither.of(300 + x, 500 + z, k) == kDitherTile[std::size_t((300 + x + sx) % kSide + kSide * ((500 + z + sz) % kSide))];
            if (fits) return shift;
        }
        return -1;
    };
    // Two views closer than 8 columns (across the wrap) would be related: blue noise leans its
    // neighbours the other way.
    int closest = kSide;
    for (std::uint64_t seed = 1; seed <= 6; ++seed)
        for (std::uint64_t grid = 0; grid < 2; ++grid) {
            const ThresholdDither dither(seed, grid);
            std::vector<int> shifts;
            for (int k = 0; k < 48; ++k) {
                shifts.push_back(shiftOf(dither, k));
                REQUIRE(shifts.back() >= 0);
            }
            for (int a = 0; a < 48; ++a)
                for (int b = a + 1; b < 48; ++b) {
                    const int dx = std::abs(shifts[std::size_t(a)] % kSide - shifts[std::size_t(b)] % kSide);
                    const int dz = std::abs(shifts[std::size_t(a)] / kSide - shifts[std::size_t(b)] / kSide);
                    closest = std::min(closest, std::max(std::min(dx, kSide - dx), std::min(dz, kSide - dz)));
                }
        }
    CHECK(closest >= 8);
    // The same seed and grid give the same dither; another seed or the other grid another.
    const std::vector<int> view = viewOf(ThresholdDither(7, 0), 11);
    CHECK(viewOf(ThresholdDither(7, 0), 11) == view);
    int differ = 0;
    for (std::uint64_t seed = 8; seed < 18; ++seed) differ += viewOf(ThresholdDither(seed, 0), 11) != view ? 1 : 0;
    CHECK(differ >= 9);
    CHECK(viewOf(ThresholdDither(7, 1), 11) != view);
}
