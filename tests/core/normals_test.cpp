// SPDX-License-Identifier: MIT
// R12: both normal estimates on known slopes.
#include "sandcore/normals.hpp"

#include "support/height_field.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

using namespace sandcore;

namespace {
double angleBetweenDegrees(Vec3 a, Vec3 b) {
    const double dot = double(a.x) * b.x + double(a.y) * b.y + double(a.z) * b.z;
    const double la = std::sqrt(double(a.x) * a.x + double(a.y) * a.y + double(a.z) * a.z);
    const double lb = std::sqrt(double(b.x) * b.x + double(b.y) * b.y + double(b.z) * b.z);
    return std::acos(std::min(1.0, dot / (la * lb))) * 180.0 / M_PI;
}

// Top grain of column (x, z).
std::uint32_t topCell(const CellGrid& grid, int x, int z) {
    for (int y = grid.size().y - 1; y >= 0; --y)
        if (grid.at(x, y, z) >= 0) return grid.index(x, y, z);
    FAIL("empty column");
    return 0;
}
} // namespace

TEST_CASE("flat floor: both methods give (0, 1, 0)") {
    const CellGrid grid = support::heightField({9, 6, 9}, [](int, int) { return 3; });
    const auto heights = columnHeights(grid);
    CHECK(heights[4 + 9 * 4] == 3);
    CHECK(columnNormal(heights, grid.size(), 4, 4) == Vec3{0.0f, 1.0f, 0.0f});
    CHECK(gradientNormal(grid, topCell(grid, 4, 4)) == Vec3{0.0f, 1.0f, 0.0f});
}

TEST_CASE("45-degree ramp along x: the gradient is exact, the thesis's column method within 15 degrees") {
    const CellGrid grid = support::heightField({12, 14, 9}, [](int x, int) { return x + 1; });
    const Vec3 ramp{-float(M_SQRT1_2), float(M_SQRT1_2), 0.0f};
    const Vec3 gradient = gradientNormal(grid, topCell(grid, 5, 4));
    CHECK(gradient.x == doctest::Approx(ramp.x).epsilon(1e-6));
    CHECK(gradient.y == doctest::Approx(ramp.y).epsilon(1e-6));
    CHECK(gradient.z == doctest::Approx(0.0).epsilon(1e-6));
    const Vec3 column = columnNormal(columnHeights(grid), grid.size(), 5, 4);
    // The thesis's table averages 8 unit face normals: 3 tilt towards -x, 3 towards -x, 2 are
    // flat, so the estimate leans 12.0 degrees towards the vertical (atan(3.72 / 5.72) = 33.0).
    CHECK(angleBetweenDegrees(column, ramp) == doctest::Approx(12.0).epsilon(0.01));
    CHECK(column.x < 0.0f);
    CHECK(column.z == doctest::Approx(0.0));
}

TEST_CASE("diagonal ramp: the gradient within 1 degree, the column method with its known bias") {
    const CellGrid grid = support::heightField({12, 26, 12}, [](int x, int z) { return x + z + 1; });
    const Vec3 ramp{-0.57735026f, 0.57735026f, -0.57735026f};
    const Vec3 gradient = gradientNormal(grid, topCell(grid, 5, 5));
    CHECK(angleBetweenDegrees(gradient, ramp) < 1.0);
    const Vec3 column = columnNormal(columnHeights(grid), grid.size(), 5, 5);
    CHECK(column.x == doctest::Approx(column.z));
    // The column method's known bias is larger here: it leans 23.5 degrees towards the vertical.
    CHECK(angleBetweenDegrees(column, ramp) == doctest::Approx(23.47).epsilon(0.01));
}

TEST_CASE("the gradient works on a vessel wall where the column method cannot") {
    // Sand against a wall at x = 0..2: the exposed face at x = 3 looks along +x.
    CellGrid grid({8, 8, 8});
    CellValue id = 0;
    for (int y = 0; y < 8; ++y)
        for (int z = 0; z < 8; ++z)
            for (int x = 0; x < 3; ++x) grid[grid.index(x, y, z)] = id++;
    const Vec3 n = gradientNormal(grid, grid.index(2, 4, 4));
    CHECK(n.x == doctest::Approx(1.0));
    CHECK(n.y == doctest::Approx(0.0));
}

TEST_CASE("column normals inside the grid are the thesis's sum of face normals, bit for bit") {
    // The direct computation, written out here: columnNormal looks inner columns up in a table.
    auto unit = [](float x, float y, float z) {
        const float length = std::sqrt(x * x + y * y + z * z);
        return Vec3{x / length, y / length, z / length};
    };
    const Int3 size{11, 1, 9};
    std::vector<int> heights(std::size_t(size.x * size.z));
    std::uint32_t state = 12345;
    for (int round = 0; round < 40; ++round) {
        for (int& h : heights) {
            state = state * 1664525u + 1013904223u;
            h = int(state >> 29); // 0..7: many ties, so all three sides occur
        }
        for (int z = 0; z < size.z; ++z)
            for (int x = 0; x < size.x; ++x) {
                const int here = heights[std::size_t(x + size.x * z)];
                float sx = 0, sy = 0, sz = 0;
                for (int dz = -1; dz <= 1; ++dz)
                    for (int dx = -1; dx <= 1; ++dx) {
                        if ((dx == 0 && dz == 0) || x + dx < 0 || z + dz < 0 || x + dx >= size.x || z + dz >= size.z) continue;
                        const int there = heights[std::size_t(x + dx + size.x * (z + dz))];
                        const float side = there > here ? -1.0f : there < here ? 1.0f : 0.0f;
                        const Vec3 face = unit(side * float(dx), 1.0f, side * float(dz));
                        sx += face.x;
                        sy += face.y;
                        sz += face.z;
                    }
                const Vec3 expected = unit(sx, sy, sz);
                const Vec3 got = columnNormal(heights, size, x, z);
                CHECK(got.x == expected.x);
                CHECK(got.y == expected.y);
                CHECK(got.z == expected.z);
            }
    }
}
