// SPDX-License-Identifier: MIT
#include "neck_joint.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>

namespace sandcore {

namespace {

// A neck narrower than a cell fills with its own wall cells over its length: bulbs up to this
// many cells apart along an axis are joined through one column, or a sixth of the grid's
// longest side where that is more (the same long thin neck spans more cells at a finer grid;
// the longest such neck of the generated corpus spans 9 layers at res 64, where an eighth
// reached 8).
constexpr int kMaxNeckWall = 8;
int maxNeckWall(const Grid& grid) { return std::max(kMaxNeckWall, std::max({grid.size.x, grid.size.y, grid.size.z}) / 6); }

} // namespace

std::array<int, 2> planeOf(int axis) { return {axis == 0 ? 1 : 0, axis == 2 ? 1 : 2}; }

ColumnSpans columnSpansOf(const CellList& cells, const Grid& grid) {
    ColumnSpans spans;
    for (int axis = 0; axis < 3; ++axis) {
        const auto [u, v] = planeOf(axis);
        const std::size_t plane = std::size_t(grid.length(u)) * std::size_t(grid.length(v));
        spans.low[std::size_t(axis)].assign(plane, INT32_MAX);
        spans.high[std::size_t(axis)].assign(plane, -1);
    }
    for (std::uint32_t n : cells) {
        const std::array<int, 3> c = grid.coordinates(n);
        for (int axis = 0; axis < 3; ++axis) {
            const auto [u, v] = planeOf(axis);
            const std::size_t column = std::size_t(c[std::size_t(u)]) + std::size_t(grid.length(u)) * std::size_t(c[std::size_t(v)]);
            int& low = spans.low[std::size_t(axis)][column];
            int& high = spans.high[std::size_t(axis)][column];
            low = std::min(low, c[std::size_t(axis)]);
            high = std::max(high, c[std::size_t(axis)]);
            spans.centreU[std::size_t(axis)] += c[std::size_t(u)];
            spans.centreV[std::size_t(axis)] += c[std::size_t(v)];
        }
    }
    for (std::size_t a = 0; a < 3; ++a) spans.centreU[a] /= double(cells.size()), spans.centreV[a] /= double(cells.size());
    return spans;
}

// W2: two bulbs that a wall of at most maxNeckWall() cells separates along an axis (a neck narrower
// than a cell, sealed by its own surface cells) joined through one column of cells: the column
// where they come closest, nearest their common centre.
std::optional<NeckJoint> jointAcrossNeck(const ColumnSpans& spansA, const ColumnSpans& spansB, const MaskCells& walls,
                                         const Grid& grid) {
    const int maxWall = maxNeckWall(grid);
    struct Best { int gap = INT_MAX; int axis = -1; std::array<int, 3> from{}; double offCentre = 0.0; } best;
    for (int axis = 0; axis < 3; ++axis) {
        const auto [u, v] = planeOf(axis);
        const auto width = std::size_t(grid.length(u));
        const std::vector<int>& lowA = spansA.low[std::size_t(axis)];
        const std::vector<int>& highA = spansA.high[std::size_t(axis)];
        const std::vector<int>& lowB = spansB.low[std::size_t(axis)];
        const std::vector<int>& highB = spansB.high[std::size_t(axis)];
        const double centreU = 0.5 * (spansA.centreU[std::size_t(axis)] + spansB.centreU[std::size_t(axis)]);
        const double centreV = 0.5 * (spansA.centreV[std::size_t(axis)] + spansB.centreV[std::size_t(axis)]);
        for (std::size_t column = 0; column < lowA.size(); ++column) {
            if (highA[column] < 0 || highB[column] < 0) continue;
            int gap = 0, start = 0;
            if (highB[column] < lowA[column]) gap = lowA[column] - highB[column] - 1, start = highB[column] + 1;
            else if (highA[column] < lowB[column]) gap = lowB[column] - highA[column] - 1, start = highA[column] + 1;
            else continue;
            if (gap < 1 || gap > maxWall) continue;
            // Only a wall is cut: open air between two vessels, or another hollow, is no neck.
            std::array<int, 3> c{};
            c[std::size_t(axis)] = start;
            c[std::size_t(u)] = int(column % width);
            c[std::size_t(v)] = int(column / width);
            bool allWall = true;
            for (int i = 0; i < gap && allWall; ++i, ++c[std::size_t(axis)]) allWall = walls[grid.index(c)] != 0;
            if (!allWall) continue;
            const double du = double(column % width) - centreU, dv = double(column / width) - centreV;
            const double offCentre = du * du + dv * dv;
            if (gap < best.gap || (gap == best.gap && offCentre < best.offCentre)) {
                best.gap = gap;
                best.axis = axis;
                best.offCentre = offCentre;
                best.from[std::size_t(axis)] = start;
                best.from[std::size_t(u)] = int(column % width);
                best.from[std::size_t(v)] = int(column / width);
            }
        }
    }
    if (best.axis < 0) return std::nullopt;
    NeckJoint joint;
    std::array<int, 3> c = best.from;
    for (int i = 0; i < best.gap; ++i, ++c[std::size_t(best.axis)]) joint.cells.push_back(grid.index(c));
    std::sort(joint.cells.begin(), joint.cells.end());
    joint.axis = best.axis;
    joint.low = best.from[std::size_t(best.axis)];
    joint.high = joint.low + best.gap - 1;
    return joint;
}

} // namespace sandcore
