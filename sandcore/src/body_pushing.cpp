// SPDX-License-Identifier: MIT
// Moving bodies (sandcore/moving_body.hpp): placing, moving, turning and removing a body in the
// lower grid, and pushing the grains in its way. Every change is an edit between steps on the
// calling thread, made in one fixed order, so the threads and sleeping of the steps never see a
// difference (R5, R6).
//
// A move is split into unit moves of one cell along one axis. For each, the cells the body is
// entering are checked first: a wall (INVALID, which includes other bodies) or the grid's edge
// stops it before anything changes. Then each grain in an entering cell, from the top layer
// down, is pushed: the shortest straight way out of its cell (StraightWayFinder: up, along its
// layer and up, or under a wall or the body and up, through grains only) to an EMPTY cell
// outside the body's way, or where there is none, a breadth-first search through the grains
// around it for the nearest EMPTY cell. The grains along the way found each shift one cell
// toward its EMPTY end, so the grain leaves the body's way and the sand ahead bulges out where
// it has room. No grain is created, destroyed or left in the body, and ids stay with grains. A
// search that finds no EMPTY cell within kPushSearchCells cells stops the body (the grains
// pushed so far stay where they went).

#include "grid_sweep.hpp"
#include "push_search.hpp"
#include "sandcore/scene.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdlib>
#include <iterator>
#include <optional>
#include <stdexcept>

namespace sandcore {

namespace {

constexpr Int3 kUp{0, 1, 0};

Int3 plus(Int3 a, Int3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Int3 minus(Int3 a) { return {-a.x, -a.y, -a.z}; }

// The six directions in the order a push tries them: ahead, the sides (+x, -x, +z, -z that are
// neither ahead nor back), up, down, back (each once).
std::array<Int3, 6> searchOrder(Int3 ahead) {
    std::array<Int3, 6> order{};
    int count = 0;
    auto add = [&](Int3 d) {
        for (int i = 0; i < count; ++i)
            if (order[std::size_t(i)] == d) return;
        order[std::size_t(count++)] = d;
    };
    add(ahead);
    for (Int3 side : {Int3{1, 0, 0}, Int3{-1, 0, 0}, Int3{0, 0, 1}, Int3{0, 0, -1}})
        if (side != ahead && side != minus(ahead)) add(side);
    add(kUp);
    add(minus(kUp));
    add(minus(ahead));
    return order;
}

// Which entering cells are pushed first: the top layer first (its grains find the surface at
// once and make room for those below), then by index; a fixed order, so the result is too.
// `cells` come in ascending order, layer by layer, so this only turns the layers' order over.
void orderTopDown(std::vector<std::uint32_t>& cells, std::uint32_t layerSize, std::vector<std::uint32_t>& scratch) {
    scratch.clear();
    for (std::size_t end = cells.size(); end > 0;) {
        const std::uint32_t layer = cells[end - 1] / layerSize;
        std::size_t begin = end - 1;
        while (begin > 0 && cells[begin - 1] / layerSize == layer) --begin;
        scratch.insert(scratch.end(), cells.begin() + std::ptrdiff_t(begin), cells.begin() + std::ptrdiff_t(end));
        end = begin;
    }
    cells.swap(scratch);
}

// A way out of the shape most pushes take: `descent` cells straight down, `walk` cells straight
// along `step` (a horizontal direction), `climb` cells straight up, through grains only (the
// body's way included where it still holds them), ending in an EMPTY cell outside the body's way.
struct StraightWay {
    int descent = 0;
    int walk = 0;
    int climb = 0;
    Int3 step{};
    int length() const { return descent + walk + climb; }
};

// What a push needs to know of the grid: its cells, and which of them are the body's way.
struct PushGrid {
    const CellGrid& cells;
    const std::vector<std::uint8_t>& inWay; // 1 for the cells the body enters in this unit move
    Int3 ahead;                             // the unit move's direction
};

// The shortest straight way out of a grain's cell, from a few dozen cells instead of a search
// through the sand around it:
// - up: straight up its own column, as when the body rises under sand;
// - along and up: 1 to kPushReach cells along its layer in one of the four horizontal
//   directions, then up that column: the sand rises onto the lowest column near the body's face,
//   ahead, or beside it at the body's edges;
// - down, along and up, in a direction where a wall or a body (INVALID) stopped the walk along
//   the layer: under it and up on its far side, as sand flows under a blade into the trench
//   behind it.
// Among ways of one length the winner is the one a breadth-first search in searchOrder would
// reach first: by its first step (ahead, the sides, up, down, back), then its walk's direction,
// then the longer walk, so sand runs down a heap's slope to its foot instead of piling up at the
// body's face.
class StraightWayFinder {
public:
    explicit StraightWayFinder(const PushGrid& grid) : grid_(grid), order_(searchOrder(grid.ahead)) {}

    std::optional<StraightWay> find(std::uint32_t cell) {
        start_ = grid_.cells.coordinate(cell);
        best_.reset();
        std::array<bool, 6> stoppedByWall{};
        offerClimb({}, start_);
        for (std::size_t d = 0; d < order_.size(); ++d)
            if (order_[d].y == 0) stoppedByWall[d] = walkAlong({0, 0, 0, order_[d]}, start_);
        for (int descent = 1; descent <= budget(); ++descent) {
            const Int3 below{start_.x, start_.y - descent, start_.z};
            const Pass pass = passAt(below);
            if (pass == Pass::Shut) break;
            if (pass == Pass::Open) {
                offer({descent, 0, 0, {}});
                break;
            }
            for (std::size_t d = 0; d < order_.size(); ++d)
                if (stoppedByWall[d]) walkAlong({descent, 0, 0, order_[d]}, below);
        }
        return best_;
    }

private:
    enum class Pass { Grain, Open, Shut }; // Open: EMPTY outside the body's way, where a way ends

    Pass passAt(Int3 c) const {
        if (!grid_.cells.contains(c.x, c.y, c.z)) return Pass::Shut;
        const std::uint32_t n = grid_.cells.index(c);
        const CellValue value = grid_.cells[n];
        if (value == kInvalid) return Pass::Shut;
        if (value == kEmpty) return grid_.inWay[n] ? Pass::Shut : Pass::Open;
        return Pass::Grain;
    }
    bool isWall(Int3 c) const { return grid_.cells.contains(c.x, c.y, c.z) && grid_.cells[grid_.cells.index(c)] == kInvalid; }

    // How many more cells a way may take and still tie with the best found.
    int budget() const { return best_ ? best_->length() : INT_MAX / 2; }

    // Walks `way.step` from `from` (the way so far ends there), offering each column's climb; true
    // when a wall or a body stopped it (the edge of the grid or the body's way do not count).
    bool walkAlong(StraightWay way, Int3 from) {
        for (way.walk = 1; way.walk <= Scene::kPushReach && way.descent + way.walk <= budget(); ++way.walk) {
            const Int3 at{from.x + way.walk * way.step.x, from.y, from.z + way.walk * way.step.z};
            const Pass pass = passAt(at);
            if (pass == Pass::Shut) return isWall(at);
            if (pass == Pass::Open) {
                offer(way);
                return false;
            }
            offerClimb(way, at);
        }
        return false;
    }

    // Offers `way` (which ends at the grain in `from`) climbing on to the first EMPTY cell above.
    void offerClimb(StraightWay way, Int3 from) {
        for (way.climb = 1; way.length() <= budget(); ++way.climb) {
            const Pass pass = passAt({from.x, from.y + way.climb, from.z});
            if (pass == Pass::Shut) return;
            if (pass == Pass::Open) {
                offer(way);
                return;
            }
        }
    }

    int rank(Int3 direction) const {
        for (std::size_t d = 0; d < order_.size(); ++d)
            if (order_[d] == direction) return int(d);
        return int(order_.size());
    }
    std::array<int, 4> key(const StraightWay& way) const {
        const int firstStep = rank(way.descent > 0 ? minus(kUp) : way.walk > 0 ? way.step : kUp);
        return {way.length(), firstStep, way.walk > 0 ? rank(way.step) : 0, -way.walk};
    }
    void offer(const StraightWay& way) {
        if (!best_ || key(way) < key(*best_)) best_ = way;
    }

    PushGrid grid_;
    std::array<Int3, 6> order_;
    Int3 start_{};
    std::optional<StraightWay> best_;
};

} // namespace

bool Scene::bodyCellsAt(const MovingBody& body, std::vector<std::uint32_t>& cells) const {
    cells.clear();
    for (Int3 offset : bodyOffsets(body.shape, body.quarterTurns)) {
        const Int3 c = plus(body.position, offset);
        if (!lower_.contains(c.x, c.y, c.z)) return false;
        cells.push_back(lower_.index(c));
    }
    if (!std::is_sorted(cells.begin(), cells.end())) std::sort(cells.begin(), cells.end()); // a turned body's are not
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
    if (!shape_.takesBodies) throw std::invalid_argument("a moving body needs a scene that takes bodies (a canvas or a sculpture)");
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
    if (!pushSearch_ || pushSearch_->stamp.size() != lower_.cellCount())
        pushSearch_ = std::make_unique<PushSearch>(lower_.cellCount());
    PushSearch& search = *pushSearch_;
    std::vector<std::uint32_t>&before = search.before, &after = search.after, &entering = search.entering, &leaving = search.leaving;
    if (!bodyCellsAt(body, before) || !bodyCellsAt(next, after)) return false;
    entering.clear();
    leaving.clear();
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(entering));
    std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(leaving));
    for (std::uint32_t n : entering)
        if (lower_[n] == kInvalid) return false;

    for (std::uint32_t n : entering) search.inWay[n] = 1;
    orderTopDown(entering, lower_.layerSize(), search.before); // `before` is done with
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
    for (std::uint32_t n : entering) search.inWay[n] = 0;
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

// Finds a way out for the grain in `cell` (straightWayOut, else nearestWayOut) and shifts the grains
// along it one cell toward its EMPTY end; false (nothing changed) when there is none.
bool Scene::pushOut(std::uint32_t cell, Int3 ahead) {
    std::vector<std::uint32_t>& way = pushSearch_->way;
    if (!straightWayOut(cell, ahead) && !nearestWayOut(cell, ahead)) return false;
    // From the EMPTY end back to the pushed grain: each grain moves one cell into the cell the
    // one after it just left, so every cell but the two ends stays as full as it was.
    for (std::size_t i = way.size() - 1; i > 0; --i) moveGrainAside(way[i - 1], way[i]);
    return true;
}

// The way out most pushes take, found by looking at a few dozen cells (see StraightWayFinder).
bool Scene::straightWayOut(std::uint32_t cell, Int3 ahead) {
    PushSearch& search = *pushSearch_;
    const std::optional<StraightWay> way = StraightWayFinder({lower_, search.inWay, ahead}).find(cell);
    if (!way) return false;
    const Int3 start = lower_.coordinate(cell);
    search.way.assign(1, cell);
    Int3 at = start;
    for (int i = 0; i < way->descent; ++i) search.way.push_back(lower_.index(at = plus(at, minus(kUp))));
    for (int i = 0; i < way->walk; ++i) search.way.push_back(lower_.index(at = plus(at, way->step)));
    for (int i = 0; i < way->climb; ++i) search.way.push_back(lower_.index(at = plus(at, kUp)));
    return true;
}

// The way out when there is no straight one (a body sunk into sand from above, a grain walled
// in): a breadth-first search from the grain through the grains around it for the nearest EMPTY
// cell, trying the directions in searchOrder; false when none lies within kPushSearchCells cells.
bool Scene::nearestWayOut(std::uint32_t cell, Int3 ahead) {
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
            const bool entering = search.inWay[neighbour] != 0;
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
    search.way.clear();
    for (std::uint32_t n = std::uint32_t(found); n != cell; n = std::uint32_t(std::int64_t(n) - indexStep[search.cameBy[n]]))
        search.way.push_back(n);
    search.way.push_back(cell);
    std::reverse(search.way.begin(), search.way.end());
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
