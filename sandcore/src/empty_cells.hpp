#pragma once
// Which cells are EMPTY, as bits: 8 consecutive cells at once (on x86-64, where SSE2 is part of
// the architecture, two compares of 4 cells and one mask, elsewhere 8 compares), and a whole
// grid's kept bits, from which the granular slides and wakes read their 7x7 and 9x9 windows.
// Private to sandcore.

#include "sandcore/cell_grid.hpp"

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

/// One bit per cell of a grid, set while the cell is EMPTY, in rows of 64-bit words (row y * sizeZ + z)
/// with a spare word after each row: a window row of up to 16 cells is two words and shifts, where
/// reading the cells is 16 to 36 bytes per row, rows a kilobyte apart. Whoever changes a cell's
/// content says so here (GridSweep keeps them for the granular rules, which read 7x7 windows).
class EmptyCellBits {
public:
    /// Sized for `size`, every cell taken.
    void resize(Int3 size) {
        size_ = size;
        stride_ = (size.x + 63) / 64 + 1;
        words_.assign(std::size_t(size.y) * std::size_t(size.z) * std::size_t(stride_), 0);
    }
    /// Reads every cell of grid (of this size).
    void read(const CellGrid& grid) {
        for (int y = 0; y < size_.y; ++y)
            for (int z = 0; z < size_.z; ++z) {
                const CellValue* cells = grid.cells().data() + grid.index(0, y, z);
                std::uint64_t* words = words_.data() + std::size_t(y * size_.z + z) * std::size_t(stride_);
                std::fill(words, words + stride_, 0);
                int x = 0;
                for (; x + 8 <= size_.x; x += 8) words[x >> 6] |= std::uint64_t(emptyBitsOf8(cells + x)) << (x & 63);
                for (; x < size_.x; ++x) words[x >> 6] |= std::uint64_t(cells[x] == kEmpty) << (x & 63);
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
    bool isEmpty(int x, int y, int z) const { return (row(y, z)[x >> 6] >> (x & 63)) & 1u; }
    void setEmpty(int x, int y, int z, bool empty) {
        std::uint64_t& word = words_[std::size_t(y * size_.z + z) * std::size_t(stride_) + std::size_t(x >> 6)];
        const std::uint64_t bit = std::uint64_t{1} << (x & 63);
        word = empty ? word | bit : word & ~bit;
    }
    /// Bit i for cell (x0 + i, y, z), i < width <= 16, x0 >= -16, x0 < size.x: set when EMPTY;
    /// cells outside the grid read as taken.
    unsigned span(int x0, int y, int z, int width) const {
        if (y < 0 || y >= size_.y || z < 0 || z >= size_.z) return 0;
        const std::uint64_t* words = row(y, z);
        std::uint64_t bits;
        if (x0 < 0) {
            bits = words[0] << -x0;
        } else {
            const int offset = x0 & 63;
            bits = words[x0 >> 6] >> offset;
            if (offset + width > 64) bits |= words[(x0 >> 6) + 1] << (64 - offset);
        }
        return unsigned(bits) & ((1u << width) - 1);
    }

    /// The rows z - Reach .. z + Reach of layer y around column x, as span(x - Reach, y, z', 2 Reach + 1)
    /// each: away from the grid's sides with one address and no bounds tests.
    template <int Reach> void rowsAround(int x, int y, int z, std::uint16_t (&rows)[2 * Reach + 1]) const {
        constexpr int width = 2 * Reach + 1;
        const int x0 = x - Reach;
        if (y < 0 || y >= size_.y || z < Reach || z + Reach >= size_.z || x0 < 0) {
            for (int r = 0; r < width; ++r) rows[r] = std::uint16_t(span(x0, y, z - Reach + r, width));
            return;
        }
        const std::uint64_t* words = row(y, z - Reach) + (x0 >> 6);
        const int offset = x0 & 63;
        if (offset + width > 64) {
            for (int r = 0; r < width; ++r, words += stride_)
                rows[r] = std::uint16_t(((words[0] >> offset) | (words[1] << (64 - offset))) & ((1u << width) - 1));
        } else {
            for (int r = 0; r < width; ++r, words += stride_) rows[r] = std::uint16_t((words[0] >> offset) & ((1u << width) - 1));
        }
    }
    /// The (2 Reach + 1)^2 cells around column x in layer y (Reach <= 3), bit (dz + Reach) * (2 Reach
    /// + 1) + (dx + Reach) set when EMPTY.
    template <int Reach> std::uint64_t window(int x, int y, int z) const {
        static_assert(Reach <= 3);
        constexpr int width = 2 * Reach + 1;
        constexpr std::uint64_t rowMask = (std::uint64_t{1} << width) - 1;
        const int x0 = x - Reach;
        std::uint64_t bits = 0;
        if (y < 0 || y >= size_.y || z < Reach || z + Reach >= size_.z || x0 < 0) {
            for (int r = 0; r < width; ++r) bits |= std::uint64_t(span(x0, y, z - Reach + r, width)) << (r * width);
            return bits;
        }
        const std::uint64_t* words = row(y, z - Reach) + (x0 >> 6);
        const int offset = x0 & 63;
        if (offset + width > 64) {
            for (int r = 0; r < width; ++r, words += stride_)
                bits |= (((words[0] >> offset) | (words[1] << (64 - offset))) & rowMask) << (r * width);
        } else {
            for (int r = 0; r < width; ++r, words += stride_) bits |= ((words[0] >> offset) & rowMask) << (r * width);
        }
        return bits;
    }

private:
    const std::uint64_t* row(int y, int z) const { return words_.data() + std::size_t(y * size_.z + z) * std::size_t(stride_); }

    Int3 size_{};
    int stride_ = 1; // words per row, the spare one included
    std::vector<std::uint64_t> words_;
};

} // namespace sandcore
