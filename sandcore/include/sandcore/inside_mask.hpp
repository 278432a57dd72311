// SPDX-License-Identifier: MIT
#pragma once
// A voxel mask: which cells of a box lie inside a shape. Scenes are built from masks (R10);
// masks come from procedural shapes (procedural_shapes.hpp) or from a voxelized model.

#include "sandcore/large_pages.hpp"
#include "sandcore/vec3.hpp"

#include <cstdint>
#include <vector>

namespace sandcore {

/// A mask's flags: a model at 256 cells is 16 MiB, so in huge pages, reused once freed.
/// Sized without a value (`MaskCells(n)`, `resize(n)`) the flags are unset until written, so a
/// pass that writes every flag (in parallel) touches each page once; give a value to clear them.
using MaskCells = std::vector<std::uint8_t, FillLaterAllocator<std::uint8_t>>;

/// Inside flags for a box of cells, in CellGrid's index layout (x fastest, then z, then y).
struct InsideMask {
    Int3 size;                       ///< cells per axis
    MaskCells inside;                ///< 1 = inside the shape, 0 = outside; size.x*size.y*size.z entries

    /// An all-outside mask; throws std::invalid_argument for an invalid size (see validateGridSize).
    static InsideMask empty(Int3 size);

    /// Index of (x, y, z) in `inside`.
    std::size_t indexOf(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(size.x) * (std::size_t(z) + std::size_t(size.z) * std::size_t(y));
    }
    bool at(int x, int y, int z) const { return inside[indexOf(x, y, z)] != 0; } ///< inside at (x, y, z)
    void set(int x, int y, int z, bool value) { inside[indexOf(x, y, z)] = value ? 1 : 0; } ///< mark a cell
    /// Number of inside cells.
    std::int64_t countInside() const;
    /// Number of inside cells in layer y.
    std::int64_t countInsideLayer(int y) const;
};

} // namespace sandcore
