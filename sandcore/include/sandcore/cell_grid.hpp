// SPDX-License-Identifier: MIT
#pragma once
// The thesis's ParticleManager storage (§3.3.1): a box of cells, each holding one grain id,
// kEmpty, or kInvalid. Index layout: x fastest, then z, then y, so one layer is sizeX*sizeZ
// cells and the cell above n is n + layerSize().

#include "sandcore/large_pages.hpp"
#include "sandcore/vec3.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace sandcore {

/// Cell content: a grain id (>= 0), or one of these markers.
using CellValue = std::int32_t;
inline constexpr CellValue kEmpty = -1;   ///< fillable, holds no grain
inline constexpr CellValue kInvalid = -2; ///< never fillable: outside a vessel or inside an obstacle

/// Largest number of cells a grid may have (R1): indices stay within 32 bits.
inline constexpr std::int64_t kMaxGridCells = std::int64_t{1} << 31;

/// Throws std::invalid_argument with a one-line message unless size is a valid grid size.
void validateGridSize(Int3 size);

/// A box of sizeX x sizeY x sizeZ cells, y up, y = 0 the bottom layer.
class CellGrid {
public:
    /// A grid of the given size with every cell set to fill; throws std::invalid_argument on
    /// a non-positive size or more than kMaxGridCells cells, before allocating.
    explicit CellGrid(Int3 size, CellValue fill = kEmpty);

    Int3 size() const { return size_; }                           ///< cells per axis
    std::uint32_t cellCount() const { return std::uint32_t(cells_.size()); } ///< all cells
    std::uint32_t layerSize() const { return layerSize_; }        ///< cells in one y layer

    /// Index of the cell at (x, y, z); the coordinate must lie inside the grid.
    std::uint32_t index(int x, int y, int z) const {
        return std::uint32_t(x) + std::uint32_t(size_.x) * (std::uint32_t(z) + std::uint32_t(size_.z) * std::uint32_t(y));
    }
    std::uint32_t index(Int3 c) const { return index(c.x, c.y, c.z); } ///< as above
    /// Coordinate of cell n.
    Int3 coordinate(std::uint32_t n) const {
        const std::uint32_t x = n % std::uint32_t(size_.x);
        const std::uint32_t rest = n / std::uint32_t(size_.x);
        return {int(x), int(rest / std::uint32_t(size_.z)), int(rest % std::uint32_t(size_.z))};
    }
    /// True when (x, y, z) lies inside the box.
    bool contains(int x, int y, int z) const {
        return x >= 0 && y >= 0 && z >= 0 && x < size_.x && y < size_.y && z < size_.z;
    }

    CellValue operator[](std::uint32_t n) const { return cells_[n]; } ///< content of cell n
    CellValue& operator[](std::uint32_t n) { return cells_[n]; }      ///< content of cell n
    CellValue at(int x, int y, int z) const { return cells_[index(x, y, z)]; } ///< content at (x, y, z)
    std::span<const CellValue> cells() const { return cells_; }       ///< all cells in index order
    std::span<CellValue> cells() { return cells_; }                   ///< all cells in index order

    /// The 9 cells of the layer below within +-1 in x and z that lie in the box; the direct
    /// successor (straight below) comes first. Returns how many were written to out.
    int successorsOf(std::uint32_t n, std::uint32_t out[9]) const;
    /// The 9 cells of the layer above within +-1 in x and z that lie in the box.
    int predecessorsOf(std::uint32_t n, std::uint32_t out[9]) const;
    /// The 8 cells of the same layer within +-1 in x and z that lie in the box.
    int nearCellsOf(std::uint32_t n, std::uint32_t out[8]) const;

    /// Number of cells holding a grain (a full scan; Scene keeps a running count).
    std::int64_t countGrains() const;

private:
    int layerNeighbours(std::uint32_t n, int dy, bool skipCentre, std::uint32_t* out) const;

    Int3 size_;
    std::uint32_t layerSize_ = 0;
    std::vector<CellValue, LargePageAllocator<CellValue>> cells_; // huge pages for big grids
};

/// The grid upside down: cell (x, y, z) of the result is cell (x, sizeY - 1 - y, z) of `grid`.
CellGrid mirroredInY(const CellGrid& grid);

} // namespace sandcore
