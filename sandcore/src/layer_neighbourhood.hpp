// SPDX-License-Identifier: MIT
#pragma once
// The thesis's neighbourhood of a cell (§3.2, Abb. 13): the 3x3 columns within +-1 in x and z,
// seen in the layer below (successors), the cell's own layer (near cells) and the layer above
// (predecessors). Private to sandcore: the rules, the mask clean-up, the normals and CellGrid's
// neighbour queries all walk the 3x3 through this one view, so the loop is written once.

#include "sandcore/cell_grid.hpp"

#include <cstdint>

namespace sandcore {

/// The 3x3 columns around column (x, z) of a box sizeX x sizeZ, by offsets dx, dz in -1..1,
/// clipped at the box.
class LayerNeighbourhood {
public:
    /// Column (x, z), which must lie in the box, of a box sizeX x sizeZ cells.
    LayerNeighbourhood(int x, int z, int sizeX, int sizeZ)
        : x_(x), z_(z), sizeX_(sizeX), dxMin_(x > 0 ? -1 : 0), dxMax_(x + 1 < sizeX ? 1 : 0),
          dzMin_(z > 0 ? -1 : 0), dzMax_(z + 1 < sizeZ ? 1 : 0) {}

    /// True when column (x+dx, z+dz) lies in the box (dx, dz in -1..1).
    bool contains(int dx, int dz) const { return dx >= dxMin_ && dx <= dxMax_ && dz >= dzMin_ && dz <= dzMax_; }
    /// Index of column (x+dx, z+dz) within one layer (x fastest): x+dx + sizeX*(z+dz).
    std::int64_t column(int dx, int dz) const { return std::int64_t(x_ + dx) + std::int64_t(sizeX_) * (z_ + dz); }

    /// Calls visit(dx, dz) for the offsets around the centre (the centre skipped) whose column
    /// lies in the box, in one fixed order: dz from -1 to 1 outside, dx from -1 to 1 inside.
    /// The rules collect their slip candidates in this order, so every recorded state hash
    /// depends on it.
    template <class Visit> void forEachAround(Visit&& visit) const {
        walk(false, [&](int dx, int dz) {
            visit(dx, dz);
            return false;
        });
    }
    /// As forEachAround, with the centre (0, 0) visited in its place of the order.
    template <class Visit> void forEachWithCentre(Visit&& visit) const {
        walk(true, [&](int dx, int dz) {
            visit(dx, dz);
            return false;
        });
    }
    /// True when holds(dx, dz) for some offset of forEachWithCentre's; stops at the first.
    template <class Predicate> bool anyWithCentre(Predicate&& holds) const { return walk(true, holds); }

private:
    // The one 3x3 loop: stops and returns true as soon as visit returns true. Constant bounds
    // let the compiler unroll it into nine checks, faster in the sweep than a loop over the
    // clipped range.
    template <class Visit> bool walk(bool withCentre, Visit&& visit) const {
        for (int dz = -1; dz <= 1; ++dz) {
            if (dz < dzMin_ || dz > dzMax_) continue;
            for (int dx = -1; dx <= 1; ++dx) {
                if (dx < dxMin_ || dx > dxMax_ || (dx == 0 && dz == 0 && !withCentre)) continue;
                if (visit(dx, dz)) return true;
            }
        }
        return false;
    }

    int x_, z_, sizeX_;
    int dxMin_, dxMax_, dzMin_, dzMax_; // offsets that stay in the box
};

/// A cell's view of its grid by offsets: below(dx, dz) is the thesis's successor, above(dx, dz)
/// its predecessor, near(dx, dz) its neighbour in the same layer; forEachAround visits the
/// offsets that lie in the box.
class CellNeighbourhood : public LayerNeighbourhood {
public:
    /// The neighbourhood of cell (x, y, z) of grid.
    CellNeighbourhood(const CellGrid& grid, int x, int y, int z)
        : LayerNeighbourhood(x, z, grid.size().x, grid.size().z), cells_(grid.cells().data()),
          centre_(grid.index(x, y, z)), rowLength_(grid.size().x), layerSize_(grid.layerSize()), y_(y),
          sizeY_(grid.size().y) {}

    /// True when layer y+dy lies in the grid (dy = -1: there is a layer below).
    bool hasLayer(int dy) const { return y_ + dy >= 0 && y_ + dy < sizeY_; }

    /// Index of cell (x+dx, y+dy, z+dz); it must lie in the grid.
    std::uint32_t index(int dx, int dy, int dz) const {
        // Unsigned wrap-around adds a negative offset exactly; int64 keeps dy*layerSize from overflowing.
        return centre_ + std::uint32_t(std::int64_t(dy) * layerSize_ + std::int64_t(dz) * rowLength_ + dx);
    }
    CellValue at(int dx, int dy, int dz) const { return cells_[index(dx, dy, dz)]; } ///< content of (x+dx, y+dy, z+dz)
    CellValue below(int dx, int dz) const { return at(dx, -1, dz); } ///< successor (x+dx, y-1, z+dz)
    CellValue near(int dx, int dz) const { return at(dx, 0, dz); }   ///< same layer (x+dx, y, z+dz)
    CellValue above(int dx, int dz) const { return at(dx, 1, dz); }  ///< predecessor (x+dx, y+1, z+dz)

private:
    const CellValue* cells_;
    std::uint32_t centre_;
    int rowLength_; // cells in one row (sizeX)
    std::uint32_t layerSize_;
    int y_, sizeY_;
};

} // namespace sandcore
