// SPDX-License-Identifier: MIT
// SPEC S8 (cavities enclosed by walls, thin walls sealed by their surface cells) and S9 (quarter
// turns of a mask, the up axis found from its neck).
#include "sandcore/cavity.hpp"
#include "sandcore/mesh_shapes.hpp"
#include "sandcore/procedural_shapes.hpp"
#include "sandcore/up_axis.hpp"

#include <doctest/doctest.h>

using namespace sandcore;

namespace {

// A hollow box: walls one cell thick around an inner room, in a grid with one empty cell around.
InsideMask boxShell(Int3 grid, Int3 lo, Int3 hi) {
    InsideMask mask = InsideMask::empty(grid);
    for (int y = lo.y; y <= hi.y; ++y)
        for (int z = lo.z; z <= hi.z; ++z)
            for (int x = lo.x; x <= hi.x; ++x) {
                const bool wall = x == lo.x || x == hi.x || y == lo.y || y == hi.y || z == lo.z || z == hi.z;
                mask.set(x, y, z, wall);
            }
    return mask;
}

} // namespace

TEST_CASE("the room inside a closed shell is a cavity, the cells around it are outside") {
    const InsideMask shell = boxShell({10, 10, 10}, {1, 1, 1}, {8, 8, 8});
    const CavitySearch search = findCavities(shell);
    CHECK(search.cavities == 1);
    CHECK(search.largestCells == 6 * 6 * 6);
    CHECK(search.largest.at(4, 4, 4));
    CHECK(!search.largest.at(1, 4, 4)); // the wall
    CHECK(!search.largest.at(0, 0, 0)); // outside
    CHECK(search.outsideCells == 10 * 10 * 10 - 8 * 8 * 8);
}

TEST_CASE("a shell with a hole has no cavity, and of two cavities the larger is the sand space") {
    InsideMask shell = boxShell({10, 10, 10}, {1, 1, 1}, {8, 8, 8});
    shell.set(4, 8, 4, false); // one cell open in the top wall
    CHECK(findCavities(shell).cavities == 0);
    InsideMask two = boxShell({12, 12, 12}, {0, 0, 0}, {11, 11, 11}); // touches the border
    for (int z = 0; z < 12; ++z)
        for (int x = 0; x < 12; ++x) two.set(x, 4, z, true); // a floor splits it: 3 layers below, 6 above
    const CavitySearch search = findCavities(two);
    CHECK(search.cavities == 2);
    CHECK(search.largestCells == 10 * 10 * 6);
    CHECK(search.largest.at(5, 7, 5));
    CHECK(!search.largest.at(5, 2, 5));
}

TEST_CASE("a wall thinner than a cell encloses its cavity through the cells its surface touches") {
    // Two nested closed boxes 0.3 cells apart, both surfaces between cell centres: ray parity
    // finds no wall cell at all, so only the surface cells can seal the room.
    TriangleMesh walls = makeBoxMesh({2.1f, 2.1f, 2.1f}, {13.9f, 13.9f, 13.9f});
    walls.append(makeBoxMesh({2.4f, 2.4f, 2.4f}, {13.6f, 13.6f, 13.6f}));
    const Int3 size{16, 16, 16};
    const InsideMask parity = voxelizeGridSpace(walls, size, {});
    CHECK(parity.countInside() == 0);
    const InsideMask surface = surfaceCells(walls, size);
    CHECK(surface.at(2, 8, 8));
    CHECK(surface.at(13, 8, 8));
    CHECK(!surface.at(8, 8, 8));
    CHECK(!surface.at(1, 8, 8));
    const CavitySearch search = findCavities(surface);
    CHECK(search.cavities == 1);
    CHECK(search.largestCells == 10 * 10 * 10); // cells 3..12
}

TEST_CASE("toGridSpace places a mesh as voxelize does") {
    const TriangleMesh box = makeBoxMesh({-1, -1, -1}, {1, 3, 1});
    VoxelizeSettings settings;
    settings.resolution = 16;
    const VoxelizeResult result = voxelize(box, settings);
    const TriangleMesh grid = toGridSpace(box, result.placement);
    const InsideMask again = voxelizeGridSpace(grid, result.placement.size, settings);
    CHECK(again.inside == result.mask.inside);
}

TEST_CASE("turning a mask maps the named axis onto +y without mirroring") {
    InsideMask mask = InsideMask::empty({3, 4, 5});
    mask.set(2, 0, 0, true); // the +x end
    mask.set(0, 3, 0, true); // the +y end
    mask.set(0, 0, 4, true); // the +z end
    const InsideMask zUp = turnToUp(mask, UpAxis::PlusZ);
    CHECK(zUp.size == Int3{3, 5, 4});
    CHECK(zUp.at(0, 4, 3)); // +z is now the top
    CHECK(zUp.at(2, 0, 3)); // x unchanged
    CHECK(zUp.at(0, 0, 0)); // +y now points to -z
    const InsideMask xUp = turnToUp(mask, UpAxis::PlusX);
    CHECK(xUp.size == Int3{4, 3, 5});
    CHECK(xUp.at(3, 2, 0)); // +x on top; the old y runs along -x
    CHECK(xUp.countInside() == 3);
    for (UpAxis axis : {UpAxis::MinusX, UpAxis::MinusY, UpAxis::MinusZ, UpAxis::PlusZ}) {
        // Turning twice about the same axis by opposite quarter turns would give the mask back;
        // here: every turn keeps the count of cells and only permutes the sizes.
        const InsideMask turned = turnToUp(mask, axis);
        CHECK(turned.countInside() == 3);
        CHECK(turned.size.x * turned.size.y * turned.size.z == 60);
    }
    CHECK(turnToUp(turnToUp(mask, UpAxis::MinusY), UpAxis::MinusY).inside == mask.inside);
    CHECK(parseUpAxis("+z") == UpAxis::PlusZ);
    CHECK(parseUpAxis("-x") == UpAxis::MinusX);
    CHECK(parseUpAxis("y") == UpAxis::PlusY);
    CHECK(!parseUpAxis("up").has_value());
}

TEST_CASE("the up axis of an hourglass lying on its side is found from its neck") {
    const InsideMask standing = makeHourglassMask({48, 2.0f, 0.0f});
    CHECK(findUpAxis(standing) == UpAxis::PlusY);
    // Laid down: its axis along z, then along x.
    const InsideMask onZ = turnToUp(standing, UpAxis::PlusZ);
    CHECK(findUpAxis(onZ) != UpAxis::PlusY);
    CHECK(neckAlong(onZ, 2).hasNeck);
    CHECK(findUpAxis(onZ) == UpAxis::PlusZ);
    CHECK(turnToUp(onZ, findUpAxis(onZ)).size == standing.size);
    const InsideMask onX = turnToUp(standing, UpAxis::MinusX);
    CHECK(findUpAxis(onX) == UpAxis::PlusX);
    // A ball has no neck along any axis: +y stays.
    CHECK(findUpAxis(makeSphereMask(24)) == UpAxis::PlusY);
    CHECK(neckAlong(standing, 1).ratio < 0.1);
}

namespace {

// The cavities by the definition: a label per 6-connected component of empty cells, one cell
// at a time, for comparison with the run-by-run fill of findCavities.
CavitySearch cavitiesCellByCell(const InsideMask& solid) {
    const Int3 s = solid.size;
    std::vector<int> label(solid.inside.size(), -1); // -1 unvisited; 0 outside; k > 0 the k-th cavity
    std::vector<std::int64_t> sizes{0};
    CavitySearch result;
    std::vector<std::size_t> stack;
    auto fill = [&](std::size_t seed, int mark) {
        std::int64_t count = 0;
        stack.assign(1, seed);
        label[seed] = mark;
        while (!stack.empty()) {
            const std::size_t n = stack.back();
            stack.pop_back();
            ++count;
            const int x = int(n % std::size_t(s.x)), z = int(n / std::size_t(s.x) % std::size_t(s.z)),
                      y = int(n / (std::size_t(s.x) * std::size_t(s.z)));
            const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
            for (const auto& d : step) {
                const int nx = x + d[0], ny = y + d[1], nz = z + d[2];
                if (nx < 0 || ny < 0 || nz < 0 || nx >= s.x || ny >= s.y || nz >= s.z) continue;
                const std::size_t m = solid.indexOf(nx, ny, nz);
                if (solid.inside[m] == 0 && label[m] < 0) label[m] = mark, stack.push_back(m);
            }
        }
        return count;
    };
    for (int y = 0; y < s.y; ++y)
        for (int z = 0; z < s.z; ++z)
            for (int x = 0; x < s.x; ++x) {
                const std::size_t n = solid.indexOf(x, y, z);
                const bool border = x == 0 || y == 0 || z == 0 || x == s.x - 1 || y == s.y - 1 || z == s.z - 1;
                if (border && solid.inside[n] == 0 && label[n] < 0) result.outsideCells += fill(n, 0);
            }
    int largest = 0;
    for (std::size_t n = 0; n < label.size(); ++n)
        if (solid.inside[n] == 0 && label[n] < 0) {
            const std::int64_t cells = fill(n, ++result.cavities);
            result.cavityCells += cells;
            if (cells > result.largestCells) result.largestCells = cells, largest = result.cavities;
        }
    result.largest = InsideMask::empty(s);
    for (std::size_t n = 0; n < label.size(); ++n) result.largest.inside[n] = largest > 0 && label[n] == largest;
    return result;
}

} // namespace

TEST_CASE("the cavities of random solids match a cell-by-cell flood fill") {
    std::uint64_t state = 12345;
    auto chance = [&](double p) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) * 0x1p-53 < p;
    };
    int withCavities = 0;
    for (int round = 0; round < 40; ++round) {
        CAPTURE(round);
        // Dense walls make many small, oddly shaped cavities; sparse ones a few large ones.
        const double density = 0.35 + 0.01 * round;
        InsideMask solid = InsideMask::empty({9 + round % 5, 7 + round % 4, 8 + round % 3});
        for (auto& cell : solid.inside) cell = chance(density) ? 1 : 0;
        const CavitySearch fast = findCavities(solid), reference = cavitiesCellByCell(solid);
        CHECK(fast.outsideCells == reference.outsideCells);
        CHECK(fast.cavities == reference.cavities);
        CHECK(fast.cavityCells == reference.cavityCells);
        CHECK(fast.largestCells == reference.largestCells);
        CHECK(fast.largest.inside == reference.largest.inside);
        withCavities += fast.cavities > 1;
    }
    CHECK(withCavities > 10); // the solids had cavities of several shapes to find
}
