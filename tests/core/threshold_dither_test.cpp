// The fixed dither of the granular thresholds (threshold_dither.hpp): a blue-noise tile kept as
// data, and the views of it that the 48 slides of each grid read.
#include "threshold_dither.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
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
}

TEST_CASE("threshold dither: the tile holds every value equally often, spread as blue noise") {
    std::array<int, 256> count{};
    for (std::uint8_t v : kDitherTile) ++count[v];
    CHECK(std::all_of(count.begin(), count.end(), [](int c) { return c == kSide * kSide / 256; }));
    // Sums over squares of columns stay close to their mean: against the same values shuffled
    // (white noise), the variance of a 4x4 square's sum is about a fifth, of an 8x8 one an eighth.
    std::vector<int> blue(kDitherTile.begin(), kDitherTile.end()), white = blue;
    std::shuffle(white.begin(), white.end(), std::mt19937(5));
    const double ratio4 = squareSumVariance(blue, 4) / squareSumVariance(white, 4);
    const double ratio8 = squareSumVariance(blue, 8) / squareSumVariance(white, 8);
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

TEST_CASE("threshold dither: 48 unrelated views of the tile, picked by the seed and the grid") {
    const ThresholdDither dither(7, 0);
    std::vector<std::vector<int>> views;
    for (int k = 0; k < 48; ++k) {
        views.push_back(viewOf(dither, k));
        // Each view is the whole tile, shifted: every value equally often, and so from any column on.
        std::array<int, 256> count{};
        for (int v : viewOf(dither, k, 1000 + 3 * k, 77)) ++count[std::size_t(v)];
        CHECK(std::all_of(count.begin(), count.end(), [](int c) { return c == kSide * kSide / 256; }));
        for (int g = 0; g < 6 && k == 0; ++g) // a word holds its 8 slides' bytes
            for (int j = 0; j < 8; ++j) CHECK((dither.group(5, 9, g) >> (8 * j) & 0xff) == dither.of(5, 9, 8 * g + j));
    }
    double largest = 0;
    for (int a = 0; a < 48; ++a)
        for (int b = a + 1; b < 48; ++b) largest = std::max(largest, std::abs(correlation(views[std::size_t(a)], views[std::size_t(b)])));
    CAPTURE(largest);
    CHECK(largest < 0.15);
    // The same seed and grid give the same dither; another seed or the other grid another.
    CHECK(viewOf(ThresholdDither(7, 0), 11) == views[11]);
    int differ = 0;
    for (std::uint64_t seed = 8; seed < 18; ++seed) differ += viewOf(ThresholdDither(seed, 0), 11) != views[11] ? 1 : 0;
    CHECK(differ >= 9);
    CHECK(viewOf(ThresholdDither(7, 1), 11) != views[11]);
}
