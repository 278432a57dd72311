#pragma once
// A grid's layout (which cells are INVALID) as one bit per cell: what a scene keeps to rebuild
// its grids on reset, an eighth of a byte per cell instead of a second copy of the cells.

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

    Int3 size() const { return size_; } ///< cells per axis
    /// True when cell n is open (EMPTY in the layout).
    bool open(std::uint32_t n) const { return (open_[n >> 6] >> (n & 63)) & 1u; }
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
