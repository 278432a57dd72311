// SPDX-License-Identifier: MIT
#include "threshold_dither.hpp"

#include "sandcore/counter_random.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace sandcore {

std::vector<std::uint8_t> blueNoiseTile(int side, double sigma, std::uint32_t seed) {
    // A start of a tenth of the cells needs at least one point; beyond a side of 4096 the int cell
    // counts and the quadratic time are out of bounds.
    if (side < 4 || side > 4096 || !(sigma > 0))
        throw std::invalid_argument("blueNoiseTile: the side must be 4 to 4096 and sigma positive");
    const int cells = side * side;
    // The energy a point puts on the cells around it: a Gaussian of the distance across the
    // wrap, in integers so that sums and comparisons are exact.
    std::vector<std::int64_t> kernel(static_cast<std::size_t>(cells));
    for (int dz = 0; dz < side; ++dz)
        for (int dx = 0; dx < side; ++dx) {
            const int ax = std::min(dx, side - dx), az = std::min(dz, side - dz);
            kernel[std::size_t(dx + side * dz)] = std::llround(std::exp(-(ax * ax + az * az) / (2 * sigma * sigma)) * (1 << 24));
        }
    std::vector<std::int64_t> energy(static_cast<std::size_t>(cells), 0);
    std::vector<std::uint8_t> taken(static_cast<std::size_t>(cells), 0);
    auto put = [&](int cell, int sign) {
        taken[std::size_t(cell)] = sign > 0;
        const int cx = cell % side, cz = cell / side;
        for (int i = 0; i < cells; ++i) {
            const int dx = (i % side - cx + side) % side, dz = (i / side - cz + side) % side;
            energy[std::size_t(i)] += sign * kernel[std::size_t(dx + side * dz)];
        }
    };
    // The tightest cluster: the taken cell with the most energy; the largest void: the free cell
    // with the least. Ties go to the lowest index.
    auto tightest = [&] {
        int best = -1;
        for (int i = 0; i < cells; ++i)
            if (taken[std::size_t(i)] && (best < 0 || energy[std::size_t(i)] > energy[std::size_t(best)])) best = i;
        return best;
    };
    auto largestVoid = [&] {
        int best = -1;
        for (int i = 0; i < cells; ++i)
            if (!taken[std::size_t(i)] && (best < 0 || energy[std::size_t(i)] < energy[std::size_t(best)])) best = i;
        return best;
    };
    // A random tenth of the cells, then moved from the tightest cluster to the largest void until
    // the point taken out is the one put back: an evenly spread start.
    std::mt19937 random(seed);
    const int start = cells / 10;
    for (int placed = 0; placed < start;) {
        const int cell = int(random() % std::uint32_t(cells));
        if (taken[std::size_t(cell)]) continue;
        put(cell, +1);
        ++placed;
    }
    for (int round = 0; round < cells; ++round) {
        const int cluster = tightest();
        put(cluster, -1);
        const int gap = largestVoid();
        put(gap, +1);
        if (gap == cluster) break;
    }
    const std::vector<std::uint8_t> startTaken = taken;
    const std::vector<std::int64_t> startEnergy = energy;
    std::vector<int> rank(static_cast<std::size_t>(cells), -1);
    // The start's points ranked from the last down, each time taking out the tightest cluster ...
    for (int r = start - 1; r >= 0; --r) {
        const int cluster = tightest();
        put(cluster, -1);
        rank[std::size_t(cluster)] = r;
    }
    // ... and the rest ranked upwards, each time filling the largest void. (For the second half
    // the tightest cluster of free cells is the same cell: the energy of the free cells is the
    // kernel's total less that of the taken.)
    taken = startTaken;
    energy = startEnergy;
    for (int r = start; r < cells; ++r) {
        const int gap = largestVoid();
        put(gap, +1);
        rank[std::size_t(gap)] = r;
    }
    std::vector<std::uint8_t> tile(static_cast<std::size_t>(cells));
    for (int i = 0; i < cells; ++i) tile[std::size_t(i)] = std::uint8_t(std::int64_t(rank[std::size_t(i)]) * 256 / cells);
    return tile;
}

const std::array<std::uint64_t, kDitherTileSide * kDitherTileSide>& ThresholdDither::wordTile() {
    static const auto words = [] {
        std::array<std::uint64_t, kDitherTileSide * kDitherTileSide> result{};
        for (int z = 0; z < kDitherTileSide; ++z)
            for (int x = 0; x < kDitherTileSide; ++x)
                for (int j = 0; j < 8; ++j)
                    result[std::size_t(x + kDitherTileSide * z)] |=
                        std::uint64_t(kDitherTile[std::size_t(((x + 8 * j) & kMask) + kDitherTileSide * z)]) << (8 * j);
        return result;
    }();
    return words;
}

ThresholdDither::ThresholdDither(std::uint64_t seed, std::uint64_t stream) : words_(wordTile().data()) {
    const std::uint64_t key = mix64(mix64(seed ^ 0x3d) ^ stream);
    // Each word's 8 views lie 8 columns apart in x; the words' views apart in z by 10 or 11 rows
    // (64 / 6), from a z picked by the seed, and anywhere in x: no two of the 48 views are within
    // 8 columns of each other, where the blue noise of one is still related to the other's.
    const std::uint64_t firstZ = key & kMask;
    for (int g = 0; g < kGroups; ++g) {
        shiftX_[std::size_t(g)] = int(mix64(key + std::uint64_t(g) + 1) & kMask);
        shiftZ_[std::size_t(g)] = int((firstZ + std::uint64_t(g * kDitherTileSide / kGroups)) & kMask);
    }
}

} // namespace sandcore
