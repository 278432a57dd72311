// SPDX-License-Identifier: MIT
#pragma once
// A grid's layout (which cells are INVALID) as one bit per cell: what a scene keeps to rebuild
// its grids on reset, an eighth of a byte per cell instead of a second copy of the cells, and what
// a granular sweep keeps of its grid's INVALID cells as they are now (obstacles included).

#include "sandcore/cell_grid.hpp"

#include <cstdint>
#include <vector>

namespace sandcore {

/// The open (not INVALID) cells of a grid, one bit each, in the grid's index order.
class LayoutBits {
public:
    LayoutBits() = default;
    /// The layout of grid: a cell is open unless it is INVALID.
    explicit LayoutBits(const CellGrid& grid);
    /// Every cell of a grid of this size INVALID.
    explicit LayoutBits(Int3 size);

    Int3 size() const { return size_; } ///< cells per axis
    /// True when cell n is open (EMPTY in the layout).
    bool open(std::uint32_t n) const { return (open_[n >> 6] >> (n & 63)) & 1u; }
    /// Cell n became open (EMPTY) or closed (INVALID).
    void setOpen(std::uint32_t n, bool open) {
        const std::uint64_t bit = std::uint64_t{1} << (n & 63);
        open_[n >> 6] = open ? open_[n >> 6] | bit : open_[n >> 6] & ~bit;
    }
    /// True when the bits say which cells of grid (of any size) are INVALID.
    bool matches(const CellGrid& grid) const;
    /// Open cells of layer 0.
    std::int64_t openCellsOfBottomLayer() const;
    /// Writes the layout into grid, which has this size: open cells EMPTY, the others INVALID.
    void writeInto(CellGrid& grid) const;
    /// The layout as a grid of EMPTY and INVALID cells.
    CellGrid grid() const;

private:
    Int3 size_{};
    std::vector<std::uint64_t> open_;
};

} // namespace sandcore
