// SPDX-License-Identifier: MIT
// CellBits: the reads of several neighbouring cells at once (around, around5) and the flips give
// what a cell-by-cell test gives, across byte boundaries, for any pattern.
#include "cell_bits.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <random>

using namespace sandcore;

TEST_CASE("cell bits: a row's 3 and 5 cells read at once equal the cells read one by one") {
    constexpr std::uint32_t kCells = 1000;
    std::mt19937 random(7);
    for (int pattern = 0; pattern < 20; ++pattern) {
        CellBits bits;
        bits.assign(kCells);
        for (std::uint32_t n = 0; n < kCells; ++n)
            if (random() % 3 == 0) bits.flip(n);
        for (std::uint32_t n = 2; n + 2 < kCells; ++n) {
            unsigned three = 0, five = 0;
            for (unsigned i = 0; i < 3; ++i) three |= unsigned(bits.test(n - 1 + i)) << i;
            for (unsigned i = 0; i < 5; ++i) five |= unsigned(bits.test(n - 2 + i)) << i;
            REQUIRE(bits.around(n) == three);
            REQUIRE(bits.around5(n) == five);
        }
    }
}

TEST_CASE("cell bits: set, flip and word agree") {
    CellBits bits;
    bits.assign(70);
    bits.set(0, true);
    bits.set(31, true);
    bits.flip(33);
    bits.flip(69);
    CHECK(bits.word(0) == ((1u << 0) | (1u << 31)));
    CHECK(bits.word(1) == (1u << 1));
    CHECK(bits.word(2) == (1u << 5));
    bits.flip(33);
    bits.set(31, false);
    CHECK(bits.word(0) == 1u);
    CHECK(bits.word(1) == 0u);
    CHECK(bits.around5(2) == 1u);
}
