// SPDX-License-Identifier: MIT
// SurfaceUpkeep, part two: the cells a step's moves filled and left, into the grain bits, and
// the net changes they make (surface_upkeep.hpp).
#include "sandcore/surface_upkeep.hpp"

#include "surface_bits.hpp"
#include "surface_shares.hpp"

#include <cstdint>
#include <span>

namespace sandcore {

using surface::kPlaceListed;
using surface::prefetch;

namespace {

// How far ahead in the moved list the cells and records are fetched: the grains a step moves lie
// all over the grids and the id range, and waiting for each cache line in turn costs more than
// all the rest.
constexpr std::size_t kFetchAhead = 16;
// The same for the net changes' hide bits (each a few cache lines).
constexpr std::size_t kNetFetchAhead = 6;

} // namespace

// The moved grains' cells into the bits, without reading the grids. A cell changed when it was
// filled or left but not both: a step fills each cell at most once (one grain ends in it) and
// leaves it at most once (one grain started in it). So two passes over the step's list of moves
// flip the grain bit of every cell a move fills, then of every cell a move leaves, and each flip
// says at once whether it is a net change: a filled cell whose bit was clear was EMPTY before the
// step (no leave has been flipped yet); a left cell whose bit is still set was not refilled (a
// refill flipped it clear in the first pass). The bits end as the grids' occupancy, and the net
// changes are found from the list and the bits alone, where reading the grid cost a cache miss a
// move. The net changes are then flipped back and applied one by one (hides, inner count, the
// change list), as a consistent sequence of single changes: the order does not matter, the inner
// count's steps add up to the change of the whole update.
// Every move goes down within one grid, except that a grain enters the lower grid's top row (the
// shared row) from the upper grid, resting there (no move) or after a move in the same step. The
// shared row is in both grids and the upper grid's bottom row is where grains wait for the neck,
// filled and left within one step unlisted: cells there are synced from the grid (syncCell) after
// the flips, and never flipped. The places themselves are not copied: the list is the scene's,
// read until its next step (retainMoves).
void SurfaceUpkeep::syncMovedGrains(const Scene& scene, WorkerPool* pool) {
    latestMoves_ = scene.movedGrains();
    // Every grain a step lists moved in that step (its movedAtStep): not read, one cache miss less.
    latestStep_ = std::uint32_t(scene.counters().stepsDone);
    // On two threads, one grid each: a grid's flips, its net changes and their inner counts away
    // from faces and seam read and write only that grid's bits. What reads both grids is done
    // afterwards on one: a cell a move left in the other grid, a net change near a face or the
    // seam, the shared rows.
    const int shareCount = pool != nullptr ? 2 : 1;
    for (GridShare& share : shares_) {
        share.net.clear();
        share.fromGrid.clear();
        share.otherLeaves.clear();
        share.changed.clear();
        share.nearEdge.clear();
        share.innerChange = 0;
    }
    forEachShare(pool, [&](GridShare& share) { flipMoves(scene, share); });
    for (int s = 0; s < shareCount; ++s)
        for (const CellRef& ref : shares_[std::size_t(s)].otherLeaves)
            flipLeft(*bits_, ref.level, ref.cell, shares_[shareCount == 2 ? index(ref.level) : 0]);
    forEachShare(pool, [&](GridShare& share) { applyNetChanges(share); });
    for (int s = 0; s < shareCount; ++s) {
        const GridShare& share = shares_[std::size_t(s)];
        innerCount_ += share.innerChange;
        changedCells_.insert(changedCells_.end(), share.changed.begin(), share.changed.end());
    }
    for (int s = 0; s < shareCount; ++s) {
        for (const NetCell& net : shares_[std::size_t(s)].nearEdge) changeCell(net.ref.level, net.ref.cell, net.filled);
        for (const CellRef& ref : shares_[std::size_t(s)].fromGrid) syncCell(scene, ref.level, ref.cell);
    }
}

// The lower grid's top row and the upper grid's bottom row: synced from the grid, not flipped.
bool SurfaceUpkeep::inSharedRow(const Bits& kept, GridLevel level, std::uint32_t cell) {
    const GridShape& lower = kept.shapes[index(GridLevel::Lower)];
    return level == GridLevel::Lower ? cell >= lower.layer * std::uint32_t(lower.size.y - 1)
                                     : cell < kept.shapes[index(GridLevel::Upper)].layer;
}

// The two passes of flips for the moves in the grids a share owns.
void SurfaceUpkeep::flipMoves(const Scene& scene, GridShare& share) {
    if (share.levels == 1u) return flipMovesOf<0>(scene, share);
    if (share.levels == 2u) return flipMovesOf<1>(scene, share);
    flipMovesOf<-1>(scene, share);
}

// Only: the one grid the share owns (0 lower, 1 upper), or -1 for both; known when compiled, so
// a share of one grid tests each move's grid once and nothing else about ownership.
template <int Only> void SurfaceUpkeep::flipMovesOf(const Scene& scene, GridShare& share) {
    Bits& kept = *bits_; // one load of the pointer, not one per cell
    const std::span<const GrainMove> moved = latestMoves_;
    const GridShape& lowerShape = kept.shapes[index(GridLevel::Lower)];
    const std::uint32_t lowerTopFirst = lowerShape.layer * std::uint32_t(lowerShape.size.y - 1);
    auto owns = [](GridLevel level) { return Only < 0 || int(index(level)) == Only; };
    auto withinGrid = [&](const GrainMove& move) {
        return move.cameFrom != kNoMove && (move.level != GridLevel::Lower || move.cell < lowerTopFirst);
    };
    auto leftCell = [&](const GrainMove& move) {
        const GridShape& shape = kept.shapes[index(move.level)];
        const MoveCode from = move.cameFrom;
        return std::uint32_t(std::int64_t(move.cell) + moveDx(from) + std::int64_t(shape.row) * moveDz(from) +
                             std::int64_t(shape.layer) * moveDy(from));
    };
    auto worldOf = [&](const GrainMove& move) {
        const Int3 c = kept.shapes[index(move.level)].coordinate(move.cell);
        const Int3 o = origins_[index(move.level)];
        return Int3{c.x + o.x, c.y + o.y, c.z + o.z};
    };
    // A world cell in every grid that holds it: f(level, cell).
    auto forEachGridCell = [&](Int3 world, auto&& f) {
        for (GridLevel level : {GridLevel::Lower, GridLevel::Upper}) {
            const Int3 o = origins_[index(level)];
            const int x = world.x - o.x, y = world.y - o.y, z = world.z - o.z;
            if (scene.grid(level).contains(x, y, z)) f(level, scene.grid(level).index(x, y, z));
        }
    };
    // First pass: the cells the moves fill.
    for (std::size_t i = 0; i < moved.size(); ++i) {
        if (i + kFetchAhead < moved.size()) {
            const GrainMove& ahead = moved[i + kFetchAhead];
            if (trackFlags_) prefetch(&grains_[ahead.grain]);
            if (owns(ahead.level)) prefetch(kept.grain[index(ahead.level)].byteOf(ahead.cell));
        }
        const GrainMove& move = moved[i];
        if (!owns(move.level)) continue;
        if (trackFlags_) list(move.grain, kPlaceListed, changedPlace_);
        if (!withinGrid(move)) {
            forEachGridCell(worldOf(move), [&](GridLevel level, std::uint32_t cell) { share.fromGrid.push_back({level, cell}); });
            continue;
        }
        if (inSharedRow(kept, move.level, move.cell)) {
            share.fromGrid.push_back({move.level, move.cell});
            continue;
        }
        CellBits& bits = kept.grain[index(move.level)];
        if (!bits.test(move.cell)) share.net.push_back({{move.level, move.cell}, true});
        bits.flip(move.cell);
    }
    // Second pass: the cells they left, mostly the cells the first pass filled (a falling column):
    // their bits were just read and are still in cache, so nothing is fetched ahead.
    auto leave = [&](GridLevel level, std::uint32_t cell) {
        if (owns(level)) flipLeft(kept, level, cell, share);
        else share.otherLeaves.push_back({level, cell});
    };
    for (const GrainMove& move : moved) {
        if (!owns(move.level)) continue;
        if (withinGrid(move)) {
            flipLeft(kept, move.level, leftCell(move), share);
        } else if (move.cameFrom != kNoMove) {
            const Int3 world = worldOf(move);
            const MoveCode from = move.cameFrom;
            forEachGridCell({world.x + moveDx(from), world.y + moveDy(from), world.z + moveDz(from)}, leave);
        }
    }
}

// A cell a move left, after every fill of the step: a net change when its bit is still set.
void SurfaceUpkeep::flipLeft(Bits& kept, GridLevel level, std::uint32_t cell, GridShare& share) {
    if (inSharedRow(kept, level, cell)) {
        share.fromGrid.push_back({level, cell});
        return;
    }
    CellBits& bits = kept.grain[index(level)];
    if (bits.test(cell)) share.net.push_back({{level, cell}, false});
    bits.flip(cell);
}

// Back to the bits before the step, then the net changes one at a time; those near a face or
// the seam, whose inner count reads the other grid, are left for changeCell.
void SurfaceUpkeep::applyNetChanges(GridShare& share) {
    Bits& kept = *bits_; // one load of the pointer, not one per cell
    for (const NetCell& net : share.net) kept.grain[index(net.ref.level)].flip(net.ref.cell);
    for (std::size_t i = 0; i < share.net.size(); ++i) {
        if (!trackFlags_ && i + kNetFetchAhead < share.net.size()) {
            // The hide bits innerChangeInside reads lie in 7 cache lines that the flips did not touch.
            const CellRef ahead = share.net[i + kNetFetchAhead].ref;
            const GridShape& shape = kept.shapes[index(ahead.level)];
            const CellBits& hides = kept.hide[index(ahead.level)];
            const std::uint32_t reach = 2 * shape.layer + 2 * shape.row + 2;
            if (ahead.cell >= reach && ahead.cell + reach < hides.wordCount() * 32u) {
                for (std::uint32_t r = ahead.cell - 2 * shape.row - 2; r <= ahead.cell + 2 * shape.row + 2; r += 2 * shape.row)
                    prefetch(hides.byteOf(r));
                prefetch(hides.byteOf(ahead.cell - 2 * shape.layer));
                prefetch(hides.byteOf(ahead.cell - shape.layer));
                prefetch(hides.byteOf(ahead.cell + shape.layer));
                prefetch(hides.byteOf(ahead.cell + 2 * shape.layer));
            }
        }
        const auto [level, cell] = share.net[i].ref;
        const NetCell& net = share.net[i];
        if (!trackFlags_) {
            const GridShape& shape = kept.shapes[index(level)];
            const Int3 c = shape.coordinate(cell);
            if (!(c.x >= 2 && c.z >= 2 && c.y >= 2 && c.x + 2 < shape.size.x && c.z + 2 < shape.size.z &&
                  c.y + 2 < shape.size.y)) {
                share.nearEdge.push_back(net);
                continue;
            }
            // Two cells from every face and the seam: all the flags involved lie in this grid.
            const std::int64_t inner = innerChangeInside(level, cell);
            share.innerChange += net.filled ? inner : -inner;
        }
        setCell(level, cell, net.filled);
        share.changed.push_back(net.ref);
    }
}

} // namespace sandcore
