// SPDX-License-Identifier: MIT
#include "sandcore/hourglass_space.hpp"

#include "sandcore/cavity.hpp"
#include "sandcore/mesh_shells.hpp"
#include "neck_joint.hpp"
#include "space_grid.hpp"
#include "wall_cavities.hpp"
#include "wall_side_cells.hpp"

#include <algorithm>
#include <future>
#include <iterator>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sandcore {

const char* sandSpaceKindName(SandSpaceKind kind) {
    switch (kind) {
    case SandSpaceKind::Solid: return "solid";
    case SandSpaceKind::Cavity: return "cavity";
    case SandSpaceKind::OpenVessel: return "open";
    case SandSpaceKind::Model: return "model";
    }
    return "cavity";
}

namespace {

// Fewest cells a space needs to count (a 3x3x3 room): smaller ones are gaps between touching parts.
constexpr std::size_t kMinSpaceCells = 27;
// A space is an hourglass when its narrowest middle layer has at most this share of the smaller
// bulb's widest layer.
constexpr double kNeckRatio = 0.8;
// A space found only with wider gaps closed must be this much larger to replace one found with
// narrower gaps closed: the same space grown back differs by a few cells, a sealed leak by far more.
constexpr double kLargerSpace = 1.2;
// Modelled sand fills part of one bulb: on some axis it spans less than this share of the walls.
constexpr double kPartOfOneBulb = 0.55;
// A shell is glass when the sand space touches this share of its cells (a single wall, or the
// inner side of a glass modelled with thickness), or when it wraps the space and lies within
// kNearCells of it along most of its cells (the outer side of a glass made as two shells).
constexpr double kTouchingShare = 0.35;
constexpr double kNearShare = 0.5;
constexpr int kNearCells = 3;
// Two spaces are the two bulbs of one hourglass only when the smaller holds at least this share
// of the larger: a sliver in a wall or a post's inside is no bulb.
constexpr double kBulbShare = 0.2;

// A shell in the model's grid.
struct GridShell {
    CellList surface;           // cells its triangles touch
    CellList inside;            // cells whose centres it encloses (closed shells only)
    bool closed = false;
    std::array<double, 3> low{}, high{}; // bounds, cells
};

// The cells whose centres a grid-space mesh encloses, voxelized within its own bounds only: by
// parity when it is closed, by the robust vote when it is open (modelled sand or a glass with a hole).
CellList insideCells(const TriangleMesh& gridMesh, const Grid& grid, const GridShell& shell, int threads) {
    std::array<int, 3> from{}, sub{};
    for (std::size_t a = 0; a < 3; ++a) {
        from[a] = std::clamp(int(std::floor(shell.low[a])), 0, grid.length(int(a)));
        const int to = std::clamp(int(std::ceil(shell.high[a])), 0, grid.length(int(a)));
        sub[a] = to - from[a];
        if (sub[a] <= 0) return {};
    }
    TriangleMesh moved = gridMesh;
    for (Vec3& v : moved.vertices) v = {v.x - float(from[0]), v.y - float(from[1]), v.z - float(from[2])};
    VoxelizeSettings settings;
    settings.threads = threads;
    settings.robust = !shell.closed;
    const InsideMask part = voxelizeGridSpace(moved, {sub[0], sub[1], sub[2]}, settings);
    CellList cells;
    for (int y = 0; y < sub[1]; ++y)
        for (int z = 0; z < sub[2]; ++z)
            for (int x = 0; x < sub[0]; ++x)
                if (part.at(x, y, z)) cells.push_back(grid.index({x + from[0], y + from[1], z + from[2]}));
    return cells;
}

// Does a wall of another shell lie along all six axis rays from the cell?
bool enclosedByOthers(std::uint32_t cell, std::uint32_t shell, const std::vector<std::uint32_t>& owner, const Grid& grid) {
    const std::array<int, 3> start = grid.coordinates(cell);
    for (int axis = 0; axis < 3; ++axis)
        for (int step : {-1, 1}) {
            std::array<int, 3> c = start;
            bool hit = false;
            for (c[std::size_t(axis)] += step; !hit && c[std::size_t(axis)] >= 0 && c[std::size_t(axis)] < grid.length(axis);
                 c[std::size_t(axis)] += step) {
                const std::uint32_t o = owner[grid.index(c)];
                hit = o != UINT32_MAX && o != shell;
            }
            if (!hit) return false;
        }
    return true;
}

// Modelled sand (W1): a closed shell that the other shells enclose on every side and that fills
// only part of one bulb. A nested shell that spans the walls (a glass's inner surface) stays a wall.
bool looksLikeModelledSand(std::uint32_t s, const GridShell& shell, const std::vector<std::uint32_t>& owner,
                           const std::array<double, 3>& wallExtent, const Grid& grid) {
    if (shell.inside.empty()) return false;
    bool partial = false;
    for (std::size_t a = 0; a < 3; ++a) partial = partial || shell.high[a] - shell.low[a] < kPartOfOneBulb * wallExtent[a];
    if (!partial) return false;
    const std::size_t samples = std::min<std::size_t>(32, shell.inside.size());
    std::size_t enclosed = 0;
    for (std::size_t i = 0; i < samples; ++i)
        enclosed += enclosedByOthers(shell.inside[i * shell.inside.size() / samples], s, owner, grid) ? 1 : 0;
    return enclosed * 4 >= samples * 3;
}

// Do at least three quarters of the cells of `part` (a sample of them) lie in `space`? Both ascending.
bool mostlyWithin(const CellList& part, const CellList& space) {
    const std::size_t samples = std::min<std::size_t>(64, part.size());
    std::size_t within = 0;
    for (std::size_t i = 0; i < samples; ++i)
        within += std::binary_search(space.begin(), space.end(), part[i * part.size() / samples]) ? 1 : 0;
    return samples > 0 && within * 4 >= samples * 3;
}

struct Candidate {
    CellList cells;
    int source = 0;        // -1: a glass surface's inside; 0, 1, 2...: the walls' gaps closed by that many cells
    bool voted = false;    // the inside of an open glass surface, by the robust vote
    bool neckOpened = false;
    int jointAxis = -1;    // an opened neck: the axis of the column cut through the wall
    int jointLow = 0, jointHigh = 0; // ... and the layers it spans
    CellList joint;        // the cells cut through the wall
    NeckProfile neck;      // along neckAxis
    int neckAxis = -1;     // -1: no neck between two bulbs
};

// The narrowest neck of the cells along x, y or z (y first: ties keep the model's own up).
void findNeck(Candidate& candidate, const Grid& grid) {
    std::array<std::vector<std::int64_t>, 3> area;
    for (int a = 0; a < 3; ++a) area[std::size_t(a)].assign(std::size_t(grid.length(a)), 0);
    for (std::uint32_t n : candidate.cells) {
        const std::array<int, 3> c = grid.coordinates(n);
        for (std::size_t a = 0; a < 3; ++a) ++area[a][std::size_t(c[a])];
    }
    for (int axis : {1, 0, 2}) {
        const NeckProfile profile = neckOfAreas(area[std::size_t(axis)]);
        // Two spaces joined through a wall are one hourglass only when the cut is its neck (not a
        // bulb joined to the inside of a plate).
        const bool atJoint = candidate.jointAxis < 0 || (axis == candidate.jointAxis && profile.neckLayer >= candidate.jointLow - 1 &&
                                                         profile.neckLayer <= candidate.jointHigh + 1);
        if (atJoint && profile.hasNeck && profile.ratio <= kNeckRatio && (candidate.neckAxis < 0 || profile.ratio < candidate.neck.ratio)) {
            candidate.neck = profile;
            candidate.neckAxis = axis;
        }
    }
}

// The spaces of one source with the necks under a cell between their largest ones opened.
// `closedWalls` are the walls with the source's gaps closed (`walls` for a glass's inside and
// for closing 0): with gaps of up to 2 * source cells closed, the gap two open bulbs leave
// between them at the neck is wall as well.
void addCandidates(std::vector<CellList> spaces, int source, const MaskCells& closedWalls, const Grid& grid,
                   std::vector<Candidate>& out) {
    std::erase_if(spaces, [](const CellList& c) { return c.size() < kMinSpaceCells; });
    std::stable_sort(spaces.begin(), spaces.end(), [](const CellList& p, const CellList& q) { return p.size() > q.size(); });
    const std::size_t largest = std::min<std::size_t>(spaces.size(), 4);
    std::vector<ColumnSpans> spans(largest);
    for (std::size_t i = 0; i < largest; ++i)
        for (std::size_t j = i + 1; j < largest; ++j) {
            if (double(spaces[j].size()) < kBulbShare * double(spaces[i].size())) continue;
            if (spans[i].low[0].empty()) spans[i] = columnSpansOf(spaces[i], grid);
            if (spans[j].low[0].empty()) spans[j] = columnSpansOf(spaces[j], grid);
            const std::optional<NeckJoint> joint = jointAcrossNeck(spans[i], spans[j], closedWalls, grid);
            if (!joint) continue;
            Candidate joined;
            joined.source = source;
            joined.neckOpened = true;
            joined.jointAxis = joint->axis;
            joined.jointLow = joint->low;
            joined.jointHigh = joint->high;
            joined.joint = joint->cells;
            CellList bulbs;
            bulbs.reserve(spaces[i].size() + spaces[j].size());
            std::merge(spaces[i].begin(), spaces[i].end(), spaces[j].begin(), spaces[j].end(), std::back_inserter(bulbs));
            joined.cells.reserve(bulbs.size() + joined.joint.size());
            std::merge(bulbs.begin(), bulbs.end(), joined.joint.begin(), joined.joint.end(), std::back_inserter(joined.cells));
            out.push_back(std::move(joined));
        }
    for (CellList& cells : spaces) {
        Candidate candidate;
        candidate.source = source;
        candidate.cells = std::move(cells);
        out.push_back(std::move(candidate));
    }
}

// Of each source the largest space with a neck; a later source (wider gaps closed, or an open
// glass's inside by the vote) replaces an earlier one only when its space is clearly larger (a
// leak sealed, not a few cells regained).
// Necks are looked for from the largest space of a source down, until one has a neck.
const Candidate* bestHourglass(std::vector<Candidate>& candidates, const Grid& grid) {
    const Candidate* best = nullptr;
    for (std::size_t first = 0; first < candidates.size();) {
        std::size_t end = first;
        while (end < candidates.size() && candidates[end].source == candidates[first].source) ++end;
        std::vector<Candidate*> bySize;
        for (std::size_t i = first; i < end; ++i) bySize.push_back(&candidates[i]);
        std::stable_sort(bySize.begin(), bySize.end(), [](const Candidate* p, const Candidate* q) { return p->cells.size() > q->cells.size(); });
        for (Candidate* c : bySize) {
            if (best && double(c->cells.size()) <= kLargerSpace * double(best->cells.size())) break;
            findNeck(*c, grid);
            if (c->neckAxis >= 0) {
                best = c;
                break;
            }
        }
        first = end;
    }
    return best;
}

InsideMask maskOf(const CellList& cells, Int3 size) {
    InsideMask mask = InsideMask::empty(size);
    for (std::uint32_t n : cells) mask.inside[n] = 1;
    return mask;
}

UpAxis upAlong(int axis, bool plus) {
    static constexpr UpAxis kPlus[3] = {UpAxis::PlusX, UpAxis::PlusY, UpAxis::PlusZ};
    static constexpr UpAxis kMinus[3] = {UpAxis::MinusX, UpAxis::MinusY, UpAxis::MinusZ};
    return plus ? kPlus[axis] : kMinus[axis];
}

// The largest cell list and its index.
template <class Lists> std::size_t largestOf(const Lists& lists) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < lists.size(); ++i)
        if (lists[i].size() > lists[best].size()) best = i;
    return best;
}

} // namespace

HourglassSpace findHourglassSpace(const std::vector<ModelShell>& shells, const HourglassSpaceSettings& settings) {
    if (shells.empty()) throw std::invalid_argument("the model has no triangles");
    TriangleMesh merged;
    for (const ModelShell& shell : shells) merged.append(shell.mesh);
    HourglassSpace out;
    out.placement = placeInGrid(merged, settings.voxelize);
    const Grid grid{out.placement.size};
    const int threads = std::max(1, settings.voxelize.threads);

    // Every shell's cells, and which shell owns each wall cell (UINT32_MAX - 1 where several meet).
    std::vector<GridShell> inGrid(shells.size());
    std::vector<TriangleMesh> gridMeshes(shells.size());
    std::vector<std::uint32_t> owner(grid.cells(), UINT32_MAX);
    std::array<double, 3> wallLow, wallHigh;
    wallLow.fill(std::numeric_limits<double>::infinity());
    wallHigh.fill(-std::numeric_limits<double>::infinity());
    for (std::size_t s = 0; s < shells.size(); ++s) {
        if (shells[s].mesh.triangles.empty()) continue;
        gridMeshes[s] = toGridSpace(shells[s].mesh, out.placement);
        const TriangleMesh& gridMesh = gridMeshes[s];
        GridShell& shell = inGrid[s];
        const MeshBounds bounds = boundsOf(gridMesh);
        shell.low = bounds.min;
        shell.high = bounds.max;
        for (std::size_t a = 0; a < 3; ++a) {
            wallLow[a] = std::min(wallLow[a], bounds.min[a]);
            wallHigh[a] = std::max(wallHigh[a], bounds.max[a]);
        }
        appendSurfaceCells(gridMesh, grid.size, shell.surface, threads);
        for (std::uint32_t n : shell.surface) owner[n] = owner[n] == UINT32_MAX ? std::uint32_t(s) : UINT32_MAX - 1;
        shell.closed = shells[s].closed ? *shells[s].closed : closednessOf(shells[s].mesh).closed;
        // Modelled sand fills part of one bulb: a shell as long as the model on every axis is none.
        const double longest = std::max({out.placement.size.x, out.placement.size.y, out.placement.size.z});
        bool partial = false;
        for (std::size_t a = 0; a < 3; ++a) partial = partial || shell.high[a] - shell.low[a] < kPartOfOneBulb * longest;
        const bool mayBeSand = (!shells[s].roleFixed && partial) || shells[s].role == ShellRole::Sand;
        const bool mayBeVessel = !shells[s].roleFixed || shells[s].role == ShellRole::Glass;
        // A closed frame part (a plate, a post) is solid: its inside is wall, never a space.
        const bool solidFrame = shells[s].roleFixed && shells[s].role == ShellRole::Frame && shell.closed;
        if (mayBeVessel || mayBeSand || solidFrame) shell.inside = insideCells(gridMesh, grid, shell, threads);
    }
    std::array<double, 3> wallExtent;
    for (std::size_t a = 0; a < 3; ++a) wallExtent[a] = wallHigh[a] - wallLow[a];

    // W1: roles. Fixed ones stay; modelled sand is found among the rest.
    out.roles.resize(shells.size());
    for (std::size_t s = 0; s < shells.size(); ++s) {
        out.roles[s] = shells[s].role;
        if (!shells[s].roleFixed)
            out.roles[s] = looksLikeModelledSand(std::uint32_t(s), inGrid[s], owner, wallExtent, grid) ? ShellRole::Sand
                                                                                                       : ShellRole::Glass;
    }
    // The walls, and which wall shell owns each wall cell (UINT32_MAX - 1 where several meet).
    MaskCells walls(grid.cells(), 0);
    std::vector<std::uint32_t> wallOwner(grid.cells(), UINT32_MAX);
    for (std::size_t s = 0; s < shells.size(); ++s)
        if (out.roles[s] != ShellRole::Sand) {
            for (std::uint32_t n : inGrid[s].surface) {
                walls[n] = 1;
                wallOwner[n] = wallOwner[n] == UINT32_MAX ? std::uint32_t(s) : UINT32_MAX - 1;
            }
            if (shells[s].roleFixed && out.roles[s] == ShellRole::Frame)
                for (std::uint32_t n : inGrid[s].inside) walls[n] = 1;
        }

    // S8, W2: the candidates. A closed glass surface that holds no other wall encloses its sand
    // directly (its inside, as parity gives it); then the spaces the walls enclose, with ever wider
    // gaps closed; last, as the robust vote gives it, the inside of an open glass surface (one with
    // holes cut into it wider than the closings close).
    std::vector<Candidate> candidates, voted;
    for (std::size_t s = 0; s < shells.size(); ++s) {
        const GridShell& shell = inGrid[s];
        if (out.roles[s] != ShellRole::Glass || shell.inside.empty()) continue;
        // The outer surface of a glass with thickness wraps its inner surface: its inside is no sand space.
        bool wraps = false;
        for (std::size_t o = 0; o < shells.size() && !wraps; ++o) {
            if (o == s || out.roles[o] == ShellRole::Sand || inGrid[o].surface.empty()) continue;
            bool within = true;
            for (std::size_t a = 0; a < 3; ++a)
                within = within && inGrid[o].low[a] >= shell.low[a] && inGrid[o].high[a] <= shell.high[a];
            // Within its bounds is not enough: a post beside a round glass lies within them too.
            wraps = within && mostlyWithin(inGrid[o].surface, shell.inside);
        }
        if (wraps) continue;
        CellList free;
        for (std::uint32_t n : shell.inside)
            if (!walls[n] || wallOwner[n] == s) free.push_back(n);
        addCandidates(componentsOf(free, grid.size), -1, walls, grid, shell.closed ? candidates : voted);
    }
    for (Candidate& c : voted) c.voted = true;
    // Each closing is independent of the others: with threads to spare they run side by side.
    // The walls grown by each closing serve the joints and the wall cells' band as well.
    const int closingCount = std::max(settings.maxClosingCells + 1, 0);
    std::vector<MaskCells> grownWalls(static_cast<std::size_t>(closingCount));
    auto closedBy = [&](int closing) -> const MaskCells& { return closing > 0 ? grownWalls[std::size_t(closing)] : walls; };
    std::vector<std::future<std::vector<CellList>>> closings;
    for (int closing = 0; closing < closingCount; ++closing)
        closings.push_back(std::async(threads > 1 ? std::launch::async : std::launch::deferred, [&, closing] {
            if (closing > 0) grownWalls[std::size_t(closing)] = grownBy(walls, grid.size, closing);
            return enclosedRegions(walls, closedBy(closing), grid.size, closing);
        }));
    for (int closing = 0; closing < closingCount; ++closing)
        addCandidates(closings[std::size_t(closing)].get(), closing, closedBy(closing), grid, candidates);
    std::move(voted.begin(), voted.end(), std::back_inserter(candidates));
    const Candidate* chosen = bestHourglass(candidates, grid);
    int axis = 1;
    bool plus = true;
    if (chosen) {
        out.isHourglass = true;
        out.kind = chosen->source < 0 ? SandSpaceKind::Solid : SandSpaceKind::Cavity;
        out.closingCells = std::max(0, chosen->source);
        out.neckOpened = chosen->neckOpened;
        axis = chosen->neckAxis;
    } else {
        // W5: no hourglass. The largest enclosed space, else the inside of an open vessel, else the model.
        std::size_t largest = candidates.size();
        for (std::size_t i = 0; i < candidates.size(); ++i) {
            // A column through a wall joins bulbs only; the vote's inside of an open surface is no
            // closed space: a funnel's would hold its sand.
            if (candidates[i].neckOpened || candidates[i].voted) continue;
            if (largest == candidates.size() || candidates[i].cells.size() > candidates[largest].cells.size()) largest = i;
        }
        if (largest < candidates.size()) {
            chosen = &candidates[largest];
            out.kind = chosen->source < 0 ? SandSpaceKind::Solid : SandSpaceKind::Cavity;
            out.closingCells = std::max(0, chosen->source);
            out.note = "no hourglass found: the largest space the model encloses has no neck between two bulbs; it is filled "
                       "and runs out of its bottom onto the floor below";
        }
    }
    CellList open;
    if (!chosen) {
        std::size_t bestSize = 0;
        for (int a = 0; a < 3; ++a) {
            std::vector<CellList> parts = componentsOf(laterallyEnclosed(walls, grid.size, a), grid.size);
            if (parts.empty()) continue;
            CellList& part = parts[largestOf(parts)];
            if (part.size() >= kMinSpaceCells && part.size() > bestSize) {
                bestSize = part.size();
                axis = a;
                open = std::move(part);
            }
        }
    }

    if (chosen) {
        CellList cells = chosen->cells;
        if (chosen->source >= 0) {
            std::vector<TriangleMesh> wallMeshes;
            for (std::size_t s = 0; s < shells.size(); ++s)
                if (out.roles[s] != ShellRole::Sand) wallMeshes.push_back(gridMeshes[s]);
            MaskCells band;
            if (chosen->source > 0) {
                band = closedBy(chosen->source);
                for (std::size_t n = 0; n < band.size(); ++n) band[n] = band[n] && !walls[n];
            }
            addCentresOnTheSpaceSide(cells, chosen->joint, band, walls, wallMeshes, grid);
        }
        out.space = maskOf(cells, grid.size);
    } else if (!open.empty()) {
        out.kind = SandSpaceKind::OpenVessel;
        out.space = maskOf(open, grid.size);
        // The wide end up, as a funnel stands.
        std::vector<std::int64_t> area(std::size_t(grid.length(axis)), 0);
        for (std::uint32_t n : open) ++area[std::size_t(grid.coordinates(n)[std::size_t(axis)])];
        int low = 0, high = int(area.size()) - 1;
        while (area[std::size_t(low)] == 0) ++low;
        while (area[std::size_t(high)] == 0) --high;
        const int quarter = std::max(1, (high - low + 1) / 4);
        std::int64_t bottom = 0, top = 0;
        for (int i = 0; i < quarter; ++i) bottom += area[std::size_t(low + i)], top += area[std::size_t(high - i)];
        plus = top >= bottom;
        out.note = std::string("no hourglass found: the model encloses no space; the inside of its open vessel along ") +
                   upAxisName(upAlong(axis, plus)) + " is filled and runs out of its bottom onto the floor below";
    } else {
        out.kind = SandSpaceKind::Model;
        VoxelizeSettings solid = settings.voxelize;
        solid.robust = solid.robust || !closednessOf(merged).closed;
        out.space = voxelize(merged, solid).mask;
        out.note = "no hourglass found: the model encloses no space and holds no vessel; its own inside is used as a solid vessel";
    }
    // Modelled sand: the sand shells' insides within the space.
    out.modelledSand = InsideMask::empty(grid.size);
    std::int64_t sandAbove = 0, sandBelow = 0;
    for (std::size_t s = 0; s < shells.size(); ++s) {
        if (out.roles[s] != ShellRole::Sand) continue;
        // All of its cells, also those it shares with the glass's wall: the scene pours what the
        // space cannot hold where it was modelled elsewhere in the bulb, and never outside the space.
        for (std::uint32_t n : inGrid[s].inside) {
            out.modelledSand.inside[n] = 1;
            if (chosen && chosen->neckAxis >= 0) {
                const int layer = grid.coordinates(n)[std::size_t(axis)];
                sandAbove += layer > chosen->neck.neckLayer ? 1 : 0;
                sandBelow += layer < chosen->neck.neckLayer ? 1 : 0;
            }
        }
    }
    // A real hourglass stands with its sand on top, ready to run.
    if (out.isHourglass) plus = sandAbove >= sandBelow;
    if (settings.up) {
        out.up = *settings.up;
    } else {
        out.up = upAlong(axis, plus);
        out.upFound = true;
    }

    // Shells left to decide: glass or frame, by how the sand space lies along them.
    const MaskCells near = grownBy(out.space.inside, grid.size, kNearCells);
    std::array<int, 3> spaceLow{INT32_MAX, INT32_MAX, INT32_MAX}, spaceHigh{-1, -1, -1};
    for (std::size_t n = 0; n < out.space.inside.size(); ++n)
        if (out.space.inside[n]) {
            const std::array<int, 3> c = grid.coordinates(std::uint32_t(n));
            for (std::size_t a = 0; a < 3; ++a) spaceLow[a] = std::min(spaceLow[a], c[a]), spaceHigh[a] = std::max(spaceHigh[a], c[a]);
        }
    const bool spaceEmpty = spaceHigh[0] < 0;
    for (std::size_t s = 0; s < shells.size() && !spaceEmpty; ++s) {
        const GridShell& shell = inGrid[s];
        if (shells[s].roleFixed || out.roles[s] == ShellRole::Sand || shell.surface.empty()) continue;
        const double cells = double(shell.surface.size());
        std::size_t close = 0;
        for (std::uint32_t n : shell.surface) close += near[n] ? 1 : 0;
        bool wraps = true;
        for (std::size_t a = 0; a < 3; ++a) wraps = wraps && shell.low[a] <= spaceLow[a] + 1 && shell.high[a] >= spaceHigh[a];
        const bool touched = double(cellsTouching(shell.surface, out.space.inside, grid.size)) >= kTouchingShare * cells;
        out.roles[s] = touched || (wraps && double(close) >= kNearShare * cells) ? ShellRole::Glass : ShellRole::Frame;
    }

    for (const Candidate& c : candidates)
        out.enclosedSpaces += c.source == 0 && !c.neckOpened ? 1 : 0;
    out.space = turnToUp(out.space, out.up);
    out.modelledSand = turnToUp(out.modelledSand, out.up);
    return out;
}

Scene makeHourglassScene(const HourglassSpace& space, HourglassSettings hourglass, const StepSettings& step) {
    hourglass.fitLowerBulb = true; // a model's bulbs were not made to fit this program's piles
    if (space.modelledSand.countInside() == 0) return makeHourglassScene(space.space, hourglass, step);
    return makeHourglassScene(space.space, space.modelledSand, hourglass, step);
}

Scene makeHourglassFromMesh(const TriangleMesh& mesh, int resolution, const HourglassSettings& hourglass,
                            const StepSettings& step) {
    std::vector<ModelShell> shells;
    for (TriangleMesh& shell : splitIntoShells(weldVertices(mesh))) shells.push_back({std::move(shell)});
    HourglassSpaceSettings settings;
    settings.voxelize.resolution = resolution;
    settings.voxelize.threads = step.threads;
    return makeHourglassScene(findHourglassSpace(shells, settings), hourglass, step);
}

} // namespace sandcore
