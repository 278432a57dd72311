// SPDX-License-Identifier: MIT
#pragma once
// Which cells are EMPTY, as bits: 8 consecutive cells at once (on x86-64, where SSE2 is part of
// the architecture, two compares of 4 cells and one mask, elsewhere 8 compares), and a whole
// grid's kept bits, from which the granular slides and wakes read their 5x5 and 7x7 windows.
// Private to sandcore.

#include "sandcore/cell_grid.hpp"
#include "sandcore/large_pages.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sandcore {

/// Bit i is set when cells[i] is EMPTY, for i = 0..7; cells[0..7] must be readable.
inline unsigned emptyBitsOf8(const CellValue* cells) {
#if defined(__SSE2__)
    const __m128i empty = _mm_set1_epi32(kEmpty);
    const __m128i low = _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(cells)), empty);
    const __m128i high = _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(cells + 4)), empty);
    // Each compare gives 0 or -1 per cell: packed to bytes with sign saturation they stay 0 or -1.
    const __m128i bytes = _mm_packs_epi16(_mm_packs_epi32(low, high), _mm_setzero_si128());
    return unsigned(_mm_movemask_epi8(bytes));
#else
    unsigned bits = 0;
    for (int i = 0; i < 8; ++i) bits |= unsigned(cells[i] == kEmpty) << i;
    return bits;
#endif
}

/// One bit per cell of a grid, set while the cell is EMPTY, in rows of 64-bit words: a window row
/// of up to 16 cells is two words and shifts, where reading the cells is 16 to 36 bytes per row,
/// rows a kilobyte apart. A layer keeps word 0 of all its rows side by side, then word 1, and so
/// on, so the 7 rows of a window are 56 consecutive bytes, one or two cache lines, where rows kept
/// whole lay a row's words apart and took a line each. The rows carry
/// a margin of cells that read as taken (kMarginX cells before x = 0 and a spare word after each
/// row, kMarginZ rows on either side, kMarginBelow layers under y = 0), so a window near the
/// grid's sides needs no bounds tests. Whoever changes a cell's content says so here (GridSweep
/// keeps them for the granular rules, which read 7x7 windows).
class EmptyCellBits {
public:
    static constexpr int kMarginX = 16, kMarginZ = 3, kMarginBelow = 2;

    /// Sized for `size`, every cell taken.
    void resize(Int3 size) {
        size_ = size;
        stride_ = (kMarginX + size.x + 63) / 64 + 1;
        rowsPerLayer_ = size.z + 2 * kMarginZ;
        words_.assign(std::size_t(size.y + kMarginBelow) * std::size_t(rowsPerLayer_) * std::size_t(stride_), 0);
    }
    /// Reads every cell of grid (of this size).
    void read(const CellGrid& grid) {
        for (int y = 0; y < size_.y; ++y)
            for (int z = 0; z < size_.z; ++z) {
                const CellValue* cells = grid.cells().data() + grid.index(0, y, z);
                for (int w = 0; w < stride_; ++w) words_[wordIndex(y, z, w)] = 0;
                int x = 0;
                static_assert(kMarginX % 8 == 0, "8 cells' bits lie in one word");
                for (; x + 8 <= size_.x; x += 8)
                    words_[wordIndex(y, z, (kMarginX + x) >> 6)] |= std::uint64_t(emptyBitsOf8(cells + x)) << ((kMarginX + x) & 63);
                for (; x < size_.x; ++x) setEmpty(x, y, z, cells[x] == kEmpty);
            }
    }
    /// True when the bits say what grid holds.
    bool matches(const CellGrid& grid) const {
        for (int y = 0; y < size_.y; ++y)
            for (int z = 0; z < size_.z; ++z)
                for (int x = 0; x < size_.x; ++x)
                    if (isEmpty(x, y, z) != (grid.at(x, y, z) == kEmpty)) return false;
        return true;
    }
    /// (x, y, z) in the grid.
    bool isEmpty(int x, int y, int z) const {
        const int at = kMarginX + x;
        return (words_[wordIndex(y, z, at >> 6)] >> (at & 63)) & 1u;
    }
    /// (x, y, z) in the grid.
    void setEmpty(int x, int y, int z, bool empty) {
        const int at = kMarginX + x;
        std::uint64_t& word = words_[wordIndex(y, z, at >> 6)];
        const std::uint64_t bit = std::uint64_t{1} << (at & 63);
        word = empty ? word | bit : word & ~bit;
    }
    /// The (2 Reach + 1)^2 cells around column x in layer y (Reach <= 3), bit (dz + Reach) * (2 Reach
    /// + 1) + (dx + Reach) set when EMPTY; cells outside the grid read as taken. x and z in the
    /// grid, y from -kMarginBelow to the grid's top layer.
    template <int Reach> std::uint64_t window(int x, int y, int z) const {
        static_assert(Reach <= kMarginZ && Reach <= kMarginX);
        constexpr int width = 2 * Reach + 1;
        constexpr std::uint64_t rowMask = (std::uint64_t{1} << width) - 1;
        const int at = kMarginX + x - Reach, offset = at & 63;
        const std::uint64_t* words = words_.data() + wordIndex(y, z - Reach, at >> 6); // the window's rows, in a run
        std::uint64_t bits = 0;
        if (offset + width > 64) {
            const std::uint64_t* next = words + rowsPerLayer_; // the rows' next word
            for (int r = 0; r < width; ++r) bits |= (((words[r] >> offset) | (next[r] << (64 - offset))) & rowMask) << (r * width);
        } else {
            for (int r = 0; r < width; ++r) bits |= ((words[r] >> offset) & rowMask) << (r * width);
        }
        return bits;
    }

private:
    // Word w of row (y, z), margins included: y >= -kMarginBelow, z from -kMarginZ to size.z +
    // kMarginZ - 1, w below stride_.
    std::size_t wordIndex(int y, int z, int w) const {
        return (std::size_t(y + kMarginBelow) * std::size_t(stride_) + std::size_t(w)) * std::size_t(rowsPerLayer_) +
               std::size_t(z + kMarginZ);
    }

    Int3 size_{};
    int stride_ = 1;       // words per row, margins and the spare one included
    int rowsPerLayer_ = 0; // size.z and the margins: the distance between a row's words
    std::vector<std::uint64_t, LargePageAllocator<std::uint64_t>> words_; // in huge pages, as the grids (large_pages.hpp)
};

} // namespace sandcore
