// SPDX-License-Identifier: MIT
#include "sandcore/cell_grid.hpp"

#include "layer_neighbourhood.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sandcore {

void validateGridSize(Int3 size) {
    if (size.x <= 0 || size.y <= 0 || size.z <= 0)
        throw std::invalid_argument("grid size must be positive on every axis, got " + std::to_string(size.x) +
                                    "x" + std::to_string(size.y) + "x" + std::to_string(size.z));
    // A layer of two int axes fits in 64 bits; only when it is within the limit is the whole
    // product sure to fit as well, so a huge size cannot overflow the check itself.
    const std::int64_t layer = std::int64_t(size.x) * size.z;
    const std::int64_t cells = layer <= kMaxGridCells ? layer * size.y : -1;
    if (cells < 0 || cells > kMaxGridCells)
        throw std::invalid_argument("grid of " + std::to_string(size.x) + "x" + std::to_string(size.y) + "x" +
                                    std::to_string(size.z) + (cells < 0 ? "" : " = " + std::to_string(cells) + " cells") +
                                    " exceeds the limit of 2^31 cells");
}

CellGrid::CellGrid(Int3 size, CellValue fill) : size_(size) {
    validateGridSize(size);
    layerSize_ = std::uint32_t(size.x) * std::uint32_t(size.z);
    cells_.assign(std::size_t(layerSize_) * std::size_t(size.y), fill);
}

int CellGrid::layerNeighbours(std::uint32_t n, int dy, bool skipCentre, std::uint32_t* out) const {
    const Int3 c = coordinate(n);
    const CellNeighbourhood around(*this, c.x, c.y, c.z);
    if (!around.hasLayer(dy)) return 0;
    int count = 0;
    if (!skipCentre) out[count++] = around.index(0, dy, 0); // the direct neighbour comes first
    around.forEachAround([&](int dx, int dz) { out[count++] = around.index(dx, dy, dz); });
    return count;
}

int CellGrid::successorsOf(std::uint32_t n, std::uint32_t out[9]) const { return layerNeighbours(n, -1, false, out); }
int CellGrid::predecessorsOf(std::uint32_t n, std::uint32_t out[9]) const { return layerNeighbours(n, +1, false, out); }
int CellGrid::nearCellsOf(std::uint32_t n, std::uint32_t out[8]) const { return layerNeighbours(n, 0, true, out); }

std::int64_t CellGrid::countGrains() const {
    return std::count_if(cells_.begin(), cells_.end(), [](CellValue v) { return v >= 0; });
}

CellGrid mirroredInY(const CellGrid& grid) {
    const Int3 size = grid.size();
    CellGrid out(size, kEmpty);
    const std::size_t layer = grid.layerSize();
    for (int y = 0; y < size.y; ++y)
        std::copy_n(grid.cells().begin() + std::ptrdiff_t(std::size_t(y) * layer), layer,
                    out.cells().begin() + std::ptrdiff_t(std::size_t(size.y - 1 - y) * layer));
    return out;
}

} // namespace sandcore
