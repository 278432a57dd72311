// SPDX-License-Identifier: MIT
// Moving bodies (sandcore/moving_body.hpp): placing, moving, turning and removing a body in the
// lower grid, and pushing the grains in its way. Every change is an edit between steps on the
// calling thread, made in one fixed order, so the threads and sleeping of the steps never see a
// difference (R5, R6).
//
// A move is split into unit moves of one cell along one axis. For each, the cells the body is
// entering are checked first: a wall (INVALID, which includes other bodies) or the grid's edge
// stops it before anything changes. Then each grain in an entering cell, from the top layer
// down, is pushed: a breadth-first search from its cell through the grains around it (never
// through a wall, the body or another entering cell) finds the nearest EMPTY cell, trying the
// direction of motion first, then the sides, then up, then down and back; the grains along the
// path found each shift one cell toward that EMPTY cell, so the grain leaves the body's way and
// the sand ahead bulges out where it has room. No grain is created, destroyed or left in the
// body, and ids stay with grains. A search that finds no EMPTY cell within kPushSearchCells
// cells stops the body (the grains pushed so far stay where they went).

#include "grid_sweep.hpp"
#include "push_search.hpp"
#include "sandcore/scene.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <iterator>
#include <stdexcept>

namespace sandcore {

namespace {

constexpr Int3 kUp{0, 1, 0};

Int3 plus(Int3 a, Int3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Int3 minus(Int3 a) { return {-a.x, -a.y, -a.z}; }
bool same(Int3 a, Int3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// The six directions in the order a push tries them: ahead, the sides (+x, -x, +z, -z that are
// neither ahead nor back), up, down, back (each once).
std::array<Int3, 6> searchOrder(Int3 ahead) {
    std::array<Int3, 6> order{};
    int count = 0;
    auto add = [&](Int3 d) {
        for (int i = 0; i < count; ++i)
            if (same(order[std::size_t(i)], d)) return;
        order[std::size_t(count++)] = d;
    };
    add(ahead);
    for (Int3 side : {Int3{1, 0, 0}, Int3{-1, 0, 0}, Int3{0, 0, 1}, Int3{0, 0, -1}})
        if (!same(side, ahead) && !same(side, minus(ahead))) add(side);
    add(kUp);
    add(minus(kUp));
    add(minus(ahead));
    return order;
}

// Which entering cells are pushed first: the top layer first (its grains find the surface at
// once and make room for those below), then by index; a fixed order, so the result is too.
void sortTopDown(std::vector<std::uint32_t>& cells, std::uint32_t layerSize) {
    std::sort(cells.begin(), cells.end(), [&](std::uint32_t a, std::uint32_t b) {
        const std::uint32_t la = a / layerSize, lb = b / layerSize;
        return la != lb ? la > lb : a < b;
    });
}

} // namespace

bool Scene::bodyCellsAt(const MovingBody& body, std::vector<std::uint32_t>& cells) const {
    cells.clear();
    for (Int3 offset : bodyOffsets(body.shape, body.quarterTurns)) {
        const Int3 c = plus(body.position, offset);
        if (!lower_.contains(c.x, c.y, c.z)) return false;
        cells.push_back(lower_.index(c));
    }
    std::sort(cells.begin(), cells.end());
    return true;
}

std::vector<std::uint32_t> Scene::bodyCells(std::size_t index) const {
    std::vector<std::uint32_t> cells;
    bodyCellsAt(bodies_.at(index), cells);
    return cells;
}

bool Scene::coveredByBody(std::uint32_t lowerCell) const {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const std::vector<std::uint32_t> cells = bodyCells(b);
        if (std::binary_search(cells.begin(), cells.end(), lowerCell)) return true;
    }
    return false;
}

std::int64_t Scene::addBody(MovingBody body) {
    if (kind_ == SceneKind::Hourglass) throw std::invalid_argument("a moving body needs a canvas or a sculpture");
    if (std::find(body.shape.inside.begin(), body.shape.inside.end(), std::uint8_t{1}) == body.shape.inside.end())
        throw std::invalid_argument("a moving body needs at least one cell");
    body.quarterTurns &= 3;
    MovingBody nowhere = body;
    nowhere.shape = InsideMask{}; // covers no cell: every cell of `body` is entered
    std::int64_t pushed = 0;
    if (!shiftBody(nowhere, body, kUp, pushed)) return -1;
    bodies_.push_back(std::move(body));
    grainsPushedTotal_ += pushed;
    return std::int64_t(bodies_.size()) - 1;
}

void Scene::removeBody(std::size_t index) {
    MovingBody& body = bodies_.at(index);
    MovingBody nowhere = body;
    nowhere.shape = InsideMask{};
    std::int64_t pushed = 0;
    shiftBody(body, nowhere, kUp, pushed); // enters no cell: cannot fail
    bodies_.erase(bodies_.begin() + std::ptrdiff_t(index));
}

BodyMove Scene::turnBody(std::size_t index, int quarterTurns) {
    MovingBody& body = bodies_.at(index);
    BodyMove result{body.position, 0, 0, false};
    if ((quarterTurns & 3) == body.quarterTurns) return result;
    MovingBody next = body;
    next.quarterTurns = quarterTurns & 3;
    if (shiftBody(body, next, kUp, result.grainsPushed)) result.cellsMoved = 1;
    else result.stopped = true;
    grainsPushedTotal_ += result.grainsPushed;
    return result;
}

BodyMove Scene::moveBody(std::size_t index, Int3 target, int maxCells) {
    MovingBody& body = bodies_.at(index);
    BodyMove result{body.position, 0, 0, false};
    const Int3 start = body.position;
    const int distance[3] = {std::abs(target.x - start.x), std::abs(target.y - start.y), std::abs(target.z - start.z)};
    const int sign[3] = {target.x < start.x ? -1 : 1, target.y < start.y ? -1 : 1, target.z < start.z ? -1 : 1};
    int done[3] = {0, 0, 0};
    while (result.cellsMoved < maxCells) {
        // Along the straight line: the axis furthest behind its share of the way goes next,
        // (done + 1/2) / distance smallest, ties to x, then y, then z.
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            if (done[a] == distance[a]) continue;
            if (axis < 0 || std::int64_t(2 * done[a] + 1) * distance[axis] < std::int64_t(2 * done[axis] + 1) * distance[a])
                axis = a;
        }
        if (axis < 0) break; // arrived
        Int3 ahead{};
        (axis == 0 ? ahead.x : axis == 1 ? ahead.y : ahead.z) = sign[axis];
        MovingBody next = body;
        next.position = plus(body.position, ahead);
        if (!shiftBody(body, next, ahead, result.grainsPushed)) {
            result.stopped = true;
            break;
        }
        ++done[axis];
        ++result.cellsMoved;
    }
    result.reached = body.position;
    grainsPushedTotal_ += result.grainsPushed;
    return result;
}

// Replaces `body`'s cells by `next`'s (see the top of this file); false when a wall, the grid's
// edge or a grain with no room stops it, with `body` where it was.
bool Scene::shiftBody(MovingBody& body, const MovingBody& next, Int3 ahead, std::int64_t& pushed) {
    std::vector<std::uint32_t> before, after, entering, leaving;
    if (!bodyCellsAt(body, before) || !bodyCellsAt(next, after)) return false;
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(entering));
    std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(leaving));
    for (std::uint32_t n : entering)
        if (lower_[n] == kInvalid) return false;

    if (!pushSearch_ || pushSearch_->stamp.size() != lower_.cellCount())
        pushSearch_ = std::make_unique<PushSearch>(lower_.cellCount());
    for (std::uint32_t n : entering) pushSearch_->entering[n] = 1;
    sortTopDown(entering, lower_.layerSize());
    // Each push takes one grain out of the entering cells (a path may pass through others, which
    // stay full), so passes over them until none holds a grain end after that many pushes.
    bool roomForAll = true, anyPushed = false;
    for (bool again = true; again && roomForAll;) {
        again = false;
        for (std::uint32_t n : entering) {
            if (lower_[n] < 0) continue;
            if (!pushOut(n, ahead)) {
                roomForAll = false;
                break;
            }
            anyPushed = again = true;
            ++pushed;
        }
    }
    for (std::uint32_t n : entering) pushSearch_->entering[n] = 0;
    if (anyPushed) dropPushedFromMoveList();
    if (!roomForAll) return false;

    GridSweep& sweep = sweepOf(GridLevel::Lower);
    for (std::uint32_t n : entering) {
        lower_[n] = kInvalid;
        sweep.cellBlocked(n);
    }
    // A body only ever covers cells the layout opens outside obstacles (it stops at INVALID).
    for (std::uint32_t n : leaving) {
        lower_[n] = kEmpty;
        const Int3 c = lower_.coordinate(n);
        sweep.wakeAroundEmptied(lower_, c.x, c.y, c.z);
    }
    body = next;
    return true;
}

// Finds the EMPTY cell nearest to the grain in `cell` and shifts the grains along the way one
// cell toward it; false (nothing changed) when none lies within kPushSearchCells cells.
bool Scene::pushOut(std::uint32_t cell, Int3 ahead) {
    PushSearch& search = *pushSearch_;
    const std::array<Int3, 6> order = searchOrder(ahead);
    const std::uint32_t stamp = search.nextStamp();
    // Each direction as a step of the cell index, so a visit costs no division.
    std::array<std::int64_t, 6> indexStep{};
    for (std::size_t d = 0; d < order.size(); ++d)
        indexStep[d] = order[d].x + std::int64_t(order[d].z) * lower_.size().x + std::int64_t(order[d].y) * lower_.layerSize();
    search.queue.clear();
    search.queue.push_back({cell, lower_.coordinate(cell)});
    search.stamp[cell] = stamp;
    std::int64_t found = -1;
    for (std::size_t head = 0; head < search.queue.size() && found < 0; ++head) {
        const auto [n, c] = search.queue[head];
        for (std::size_t d = 0; d < order.size(); ++d) {
            const Int3 m = plus(c, order[d]);
            if (!lower_.contains(m.x, m.y, m.z)) continue;
            const std::uint32_t neighbour = std::uint32_t(std::int64_t(n) + indexStep[d]);
            const CellValue value = lower_[neighbour];
            if (search.stamp[neighbour] == stamp || value == kInvalid) continue;
            // The body's way is no place to push to; its grains may be pushed along, later out.
            const bool entering = search.entering[neighbour] != 0;
            if (entering && value == kEmpty) continue;
            search.stamp[neighbour] = stamp;
            search.cameBy[neighbour] = std::uint8_t(d);
            if (value == kEmpty) {
                found = neighbour;
                break;
            }
            if (search.queue.size() >= std::size_t(kPushSearchCells)) continue;
            search.queue.push_back({neighbour, m});
        }
    }
    if (found < 0) return false;
    // Shift from the EMPTY end back to the pushed grain: each grain moves one cell into the cell
    // the one before it just left.
    std::uint32_t to = std::uint32_t(found);
    while (to != cell) {
        const Int3 c = lower_.coordinate(to);
        const Int3 from = plus(c, minus(order[search.cameBy[to]]));
        const std::uint32_t fromCell = lower_.index(from);
        moveGrainAside(fromCell, to);
        to = fromCell;
    }
    return true;
}

// One grain shifted by a push: as removing it from `from` and adding it at `to` (the same wakes),
// keeping its id, identity and colour. It lands at rest: the push is not a fall.
void Scene::moveGrainAside(std::uint32_t from, std::uint32_t to) {
    GridSweep& sweep = sweepOf(GridLevel::Lower);
    const std::uint32_t id = std::uint32_t(lower_[from]);
    FallState& fall = grains_.fallOf(id);
    if (fall.gatheringSince) sweep.sleepingFallRemoved();
    fall = FallState{};
    lower_[to] = CellValue(id);
    sweep.grainEntered(to);
    lower_[from] = kEmpty;
    const Int3 c = lower_.coordinate(from);
    sweep.wakeAroundEmptied(lower_, c.x, c.y, c.z);
    // Not a move of the last step: the display draws it at its new cell without a glide.
    grains_.recordMove(id, to, kNoMove, 0);
}

// The last step's list of moves names grains by where that step left them: a pushed grain is
// no longer there, and its record no longer says the step moved it (as restore() reads it).
void Scene::dropPushedFromMoveList() {
    std::erase_if(movedGrains_, [&](const GrainMove& move) {
        return grains_.place[move.grain].movedAtStep != counters_.stepsDone;
    });
}

} // namespace sandcore
