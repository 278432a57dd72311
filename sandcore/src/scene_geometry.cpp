// SPDX-License-Identifier: MIT
#include "sandcore/scene_geometry.hpp"

#include "sandcore/cell_grid.hpp"
#include "sandcore/grain_store.hpp"
#include "sandcore/inside_mask.hpp"

#include <bit>
#include <limits>

namespace sandcore {

namespace {

template <class Vector> constexpr std::uint64_t elementBytes() { return sizeof(typename Vector::value_type); }

// What the library allocates, per unit. The estimates below are built from these so that they
// follow the library when its records change; the static_asserts hold them at the numbers the
// application's memory check has always used, so a change there is a deliberate one.

// Each grid cell: the live cell, a bit of the layout that reset returns to, and the sweep's
// awake, occupied and (granular) in-motion bits, rounded up to a whole byte.
constexpr std::uint64_t kBytesPerGridCell = sizeof(CellValue) + 1;
// One grain's record across GrainStore's arrays (41 bytes today: 25 of place and look, 8 of fall
// state in each grid's array), rounded up to whole 8 bytes (the scenes reserve their grains).
constexpr std::uint64_t kBytesPerGrain =
    (elementBytes<decltype(GrainStore::level)>() + elementBytes<decltype(GrainStore::place)>() +
     elementBytes<decltype(GrainStore::identity)>() + elementBytes<decltype(GrainStore::color)>() +
     2 * elementBytes<FallStates>() + 7) / 8 * 8;
// A grain's entry in the scene's fill list (the upper-grid cells that reset fills).
constexpr std::uint64_t kBytesPerFillEntry = sizeof(std::uint32_t);
// The voxelizer's inside flag and, in robust mode, its vote count per cell.
constexpr std::uint64_t kMaskBytesPerCell = elementBytes<decltype(InsideMask::inside)>() + sizeof(std::uint8_t);
// The canvas starts empty; it keeps room for one poured grain per 8 cells.
constexpr std::uint64_t kCanvasCellsPerGrain = 8;

static_assert(kBytesPerGridCell == 5 && kBytesPerGrain == 48 && kBytesPerFillEntry == 4 && kMaskBytesPerCell == 2,
              "the memory estimates changed: check the application's memory limits and their tests");

// Products saturate instead of wrapping, so an absurd size gives an absurd estimate, never a small one.
std::uint64_t times(std::uint64_t a, std::uint64_t b) {
    if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) return std::numeric_limits<std::uint64_t>::max();
    return a * b;
}
std::uint64_t plus(std::uint64_t a, std::uint64_t b) {
    return b > std::numeric_limits<std::uint64_t>::max() - a ? std::numeric_limits<std::uint64_t>::max() : a + b;
}

std::uint64_t cellsOf(Int3 size) {
    if (size.x <= 0 || size.y <= 0 || size.z <= 0) return 0;
    return times(times(std::uint64_t(size.x), std::uint64_t(size.y)), std::uint64_t(size.z));
}

// Twice n, saturating at the largest int: validateGridSize then refuses it with a message.
int twice(int n) { return n > std::numeric_limits<int>::max() / 2 ? std::numeric_limits<int>::max() : 2 * n; }

} // namespace

CanvasSettings canvasSettingsForWidth(int width) {
    return {{width, canvasReleaseHeight(width), width}, {width, canvasBoxHeight(width), width}};
}

SceneGridSizes sceneGridSizes(SceneKind kind, Int3 maskSize) {
    switch (kind) {
    case SceneKind::Hourglass: return {maskSize, maskSize};
    // thesis footnote 9: room around the model for the heap it collapses into.
    case SceneKind::Sculpture:
        return {{twice(maskSize.x), maskSize.y, twice(maskSize.z)}, {twice(maskSize.x), twice(maskSize.y), twice(maskSize.z)}};
    case SceneKind::Canvas: {
        const CanvasSettings canvas = canvasSettingsForWidth(maskSize.x);
        return {canvas.upperSize, canvas.lowerSize};
    }
    }
    return {maskSize, maskSize};
}

void validateSceneGridSizes(SceneKind kind, Int3 maskSize) {
    const SceneGridSizes sizes = sceneGridSizes(kind, maskSize);
    validateGridSize(sizes.upper);
    validateGridSize(sizes.lower);
}

std::uint64_t estimateSceneBytes(SceneKind kind, Int3 maskSize) {
    const std::uint64_t maskCells = cellsOf(maskSize);
    if (kind == SceneKind::Canvas ? maskSize.x <= 0 : maskCells == 0) return 0;
    const SceneGridSizes sizes = sceneGridSizes(kind, maskSize);
    const std::uint64_t gridCells = plus(cellsOf(sizes.upper), cellsOf(sizes.lower));
    const std::uint64_t grids = times(gridCells, kBytesPerGridCell);
    // The sweep's flag per row fits in the slack below.
    switch (kind) {
    // Grids at their upper bound (two mask volumes, where the split makes them about one) and a
    // grain for every mask cell (where at most the upper bulb fills): the slack holds the fill
    // list and the masks the split makes. 42 bytes per mask cell.
    case SceneKind::Hourglass: return plus(grids, times(maskCells, kBytesPerGrain));
    // Exact grids (12 mask volumes) and a grain and fill entry for every mask cell: 96 bytes per mask cell.
    case SceneKind::Sculpture: return plus(grids, times(maskCells, kBytesPerGrain + kBytesPerFillEntry));
    // The grids and room for the sand a user pours: 9 bytes per grid cell.
    case SceneKind::Canvas: return plus(grids, times(gridCells, kBytesPerGrain / kCanvasCellsPerGrain));
    }
    return grids;
}

std::uint64_t estimateMaskBytes(Int3 maskSize) { return times(cellsOf(maskSize), kMaskBytesPerCell); }

} // namespace sandcore
