// SPDX-License-Identifier: MIT
#pragma once
// What SurfaceUpkeep needs to look at a grain's neighbourhood cheaply, for every grain a step
// moved: one bit per cell (holds a grain; hides a neighbour) and a cell index turned into a
// coordinate without a division.

#include "sandcore/cell_grid.hpp"
#include "sandcore/large_pages.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace sandcore {

/// Exact n / d for n < 2^31 (every cell index, R1) by one multiply and one shift: with
/// l = ceil(log2 d) and M = ceil(2^(32+l) / d), n*M < 2^64 and the rounding error of n*M / 2^(32+l)
/// stays below 1/d, so the floor is n / d.
class Divider {
public:
    Divider() = default;
    explicit Divider(std::uint32_t d) {
        int l = 0;
        while ((std::uint64_t{1} << l) < d) ++l;
        shift_ = 32 + l;
        multiplier_ = ((std::uint64_t{1} << shift_) + d - 1) / d;
    }
    std::uint32_t operator()(std::uint32_t n) const { return std::uint32_t((std::uint64_t(n) * multiplier_) >> shift_); }

private:
    std::uint64_t multiplier_ = std::uint64_t{1} << 32;
    int shift_ = 32;
};

/// A grid's size, with the cell-to-coordinate conversion of CellGrid::coordinate done by Dividers.
struct GridShape {
    Int3 size{};
    std::uint32_t row = 0, layer = 0; // cells in one row (sizeX), in one layer
    Divider byRow, byDepth;           // / sizeX, / sizeZ

    explicit GridShape(Int3 s = {})
        : size(s), row(std::uint32_t(s.x)), layer(std::uint32_t(s.x) * std::uint32_t(s.z)),
          byRow(std::uint32_t(s.x > 0 ? s.x : 1)), byDepth(std::uint32_t(s.z > 0 ? s.z : 1)) {}
    Int3 coordinate(std::uint32_t n) const {
        const std::uint32_t rest = byRow(n), y = byDepth(rest);
        return {int(n - rest * row), int(y), int(rest - y * std::uint32_t(size.z))};
    }
    /// True when all 26 neighbours of c lie in the grid (none on the edge, none across the seam).
    bool interior(Int3 c) const {
        return c.x > 0 && c.y > 0 && c.z > 0 && c.x + 1 < size.x && c.y + 1 < size.y && c.z + 1 < size.z;
    }
};

/// One bit per cell in cell index order (x fastest), bytes rather than words so the 3 bits of a
/// row around a cell read the same on any byte order.
class CellBits {
public:
    /// All 0, with at least one byte past the end, whole 32-bit words. Bits of 1 MiB and more
    /// sit on huge pages (LargePageAllocator): a moved grain's cell is read at random.
    void assign(std::uint32_t cells) { bytes_.assign((std::size_t(cells) / 8 + 2 + 3) & ~std::size_t(3), 0); }
    bool test(std::uint32_t n) const { return (bytes_[n >> 3] >> (n & 7u)) & 1u; }
    void set(std::uint32_t n, bool on) {
        std::uint8_t& byte = bytes_[n >> 3];
        byte = std::uint8_t(on ? byte | (1u << (n & 7u)) : byte & ~(1u << (n & 7u)));
    }
    /// Every byte, cell n in bit n % 8 of byte n / 8 (what CellBitWords reads).
    std::span<const std::uint8_t> bytes() const { return bytes_; }
    /// The address of the byte holding cell n's bit (to fetch it ahead).
    const std::uint8_t* byteOf(std::uint32_t n) const { return bytes_.data() + (n >> 3); }
    void flip(std::uint32_t n) { bytes_[n >> 3] = std::uint8_t(bytes_[n >> 3] ^ (1u << (n & 7u))); }
    /// 32-bit words in the bits (cell n is bit n % 32 of word n / 32).
    std::uint32_t wordCount() const { return std::uint32_t(bytes_.size() / 4); }
    /// Word w, the same on any byte order.
    std::uint32_t word(std::uint32_t w) const {
        const std::uint8_t* b = bytes_.data() + std::size_t(w) * 4;
        return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
    }
    /// Bits of `count` (at most 9) cells from `first` on, as bits 0 .. count-1: two bytes read.
    unsigned run(std::uint32_t first, unsigned count) const {
        const unsigned pair = unsigned(bytes_[first >> 3]) | unsigned(bytes_[(first >> 3) + 1]) << 8;
        return (pair >> (first & 7u)) & ((1u << count) - 1u);
    }
    /// Bits of cells n-1, n and n+1 as bits 0, 1 and 2 (n >= 1).
    unsigned around(std::uint32_t n) const { return run(n - 1, 3); }
    /// Bits of cells n-2 .. n+2 as bits 0 .. 4 (n >= 2).
    unsigned around5(std::uint32_t n) const { return run(n - 2, 5); }

private:
    std::vector<std::uint8_t, LargePageAllocator<std::uint8_t>> bytes_;
};

} // namespace sandcore
