// SPDX-License-Identifier: MIT
#include "view/render/hull_mesh.hpp"

#include <array>
#include <cmath>
#include <cstdint>

namespace sandglass {

using sandcore::GridLevel;
using sandcore::Int3;

namespace {

// Both grids seen as one world-space box: the upper grid owns the rows from its origin up,
// including the shared row (its layout equals the lower grid's top row there).
class WorldCells {
public:
    WorldCells(const sandcore::Scene& scene, bool outsideIsWall)
        : scene_(scene), upperOrigin_(scene.gridOrigin(GridLevel::Upper)),
          lowerSize_(scene.grid(GridLevel::Lower).size()), outsideIsWall_(outsideIsWall) {
        // A moving body's cells are INVALID while it stands there, but it is no part of the
        // vessel: it is drawn as a solid of its own and moves on.
        for (std::size_t body = 0; body < scene.bodies().size(); ++body)
            for (std::uint32_t cell : scene.bodyCells(body)) {
                if (bodyCells_.empty()) bodyCells_.assign(scene.grid(GridLevel::Lower).cellCount(), false);
                bodyCells_[cell] = true;
            }
    }

    Int3 size() const {
        const Int3 upper = scene_.grid(GridLevel::Upper).size();
        return {lowerSize_.x, upperOrigin_.y + upper.y, lowerSize_.z};
    }

    // True for a cell sand may occupy; false for INVALID cells and for the outside where that is a wall.
    bool fillable(int x, int y, int z) const {
        const sandcore::CellGrid* grid = nullptr;
        Int3 local{x, y, z};
        if (y >= upperOrigin_.y) {
            grid = &scene_.grid(GridLevel::Upper);
            local = {x - upperOrigin_.x, y - upperOrigin_.y, z - upperOrigin_.z};
        } else {
            grid = &scene_.grid(GridLevel::Lower);
        }
        if (!grid->contains(local.x, local.y, local.z)) return !outsideIsWall_;
        if (grid->at(local.x, local.y, local.z) != sandcore::kInvalid) return true;
        return grid == &scene_.grid(GridLevel::Lower) && !bodyCells_.empty() &&
               bodyCells_[grid->index(local.x, local.y, local.z)];
    }

private:
    const sandcore::Scene& scene_;
    Int3 upperOrigin_, lowerSize_;
    bool outsideIsWall_;
    std::vector<bool> bodyCells_; // lower-grid cells a body covers; empty: none
};

void addFace(HullMesh& mesh, const WorldCells& cells, Int3 c, int axis, int side, float cellSize) {
    // Smoothed normal: from the fillable cell towards its non-fillable 26-neighbourhood.
    float nx = 0, ny = 0, nz = 0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if ((dx | dy | dz) != 0 && !cells.fillable(c.x + dx, c.y + dy, c.z + dz)) {
                    nx += float(dx);
                    ny += float(dy);
                    nz += float(dz);
                }
    float length = std::sqrt(nx * nx + ny * ny + nz * nz);
    if (length < 1e-4f) {
        nx = axis == 0 ? float(side) : 0.0f;
        ny = axis == 1 ? float(side) : 0.0f;
        nz = axis == 2 ? float(side) : 0.0f;
        length = 1.0f;
    }
    nx /= length, ny /= length, nz /= length;
    // The face's four corners: fixed coordinate on `axis`, the other two span the cell.
    const float fixed = float((axis == 0 ? c.x : axis == 1 ? c.y : c.z) + (side > 0 ? 1 : 0));
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const std::array<int, 3> base{c.x, c.y, c.z};
    auto corner = [&](int du, int dv) {
        std::array<float, 3> p{};
        p[std::size_t(axis)] = fixed;
        p[std::size_t(u)] = float(base[std::size_t(u)] + du);
        p[std::size_t(v)] = float(base[std::size_t(v)] + dv);
        return HullVertex{p[0] * cellSize, p[1] * cellSize, p[2] * cellSize, nx, ny, nz};
    };
    const HullVertex a = corner(0, 0), b = corner(1, 0), d = corner(1, 1), e = corner(0, 1);
    mesh.triangles.insert(mesh.triangles.end(), {a, b, d, a, d, e});
}

void addBoxOutline(HullMesh& mesh, Int3 lo, Int3 hi, float cellSize, bool floorOnly) {
    auto point = [&](int x, int y, int z) {
        return HullVertex{float(x) * cellSize, float(y) * cellSize, float(z) * cellSize, 0, 0, 0};
    };
    const std::array<int, 2> xs{lo.x, hi.x}, ys{lo.y, hi.y}, zs{lo.z, hi.z};
    for (int y : ys) {
        if (floorOnly && y != lo.y) continue;
        mesh.lines.insert(mesh.lines.end(), {point(xs[0], y, zs[0]), point(xs[1], y, zs[0]), point(xs[1], y, zs[0]),
                                             point(xs[1], y, zs[1]), point(xs[1], y, zs[1]), point(xs[0], y, zs[1]),
                                             point(xs[0], y, zs[1]), point(xs[0], y, zs[0])});
    }
    if (floorOnly) return;
    for (int x : xs)
        for (int z : zs) mesh.lines.insert(mesh.lines.end(), {point(x, ys[0], z), point(x, ys[1], z)});
}

} // namespace

HullMesh buildHullMesh(const sandcore::Scene& scene, sandcore::SceneKind kind, float cellSize) {
    HullMesh mesh;
    const bool hourglass = kind == sandcore::SceneKind::Hourglass;
    const WorldCells cells(scene, hourglass);
    const Int3 size = cells.size();
    for (int y = 0; y < size.y; ++y)
        for (int z = 0; z < size.z; ++z)
            for (int x = 0; x < size.x; ++x) {
                if (!cells.fillable(x, y, z)) continue;
                const Int3 c{x, y, z};
                if (!cells.fillable(x - 1, y, z)) addFace(mesh, cells, c, 0, -1, cellSize);
                if (!cells.fillable(x + 1, y, z)) addFace(mesh, cells, c, 0, +1, cellSize);
                if (!cells.fillable(x, y - 1, z)) addFace(mesh, cells, c, 1, -1, cellSize);
                if (!cells.fillable(x, y + 1, z)) addFace(mesh, cells, c, 1, +1, cellSize);
                if (!cells.fillable(x, y, z - 1)) addFace(mesh, cells, c, 2, -1, cellSize);
                if (!cells.fillable(x, y, z + 1)) addFace(mesh, cells, c, 2, +1, cellSize);
            }
    if (kind == sandcore::SceneKind::Canvas) {
        addBoxOutline(mesh, {0, 0, 0}, scene.grid(GridLevel::Lower).size(), cellSize, false);
        const Int3 o = scene.gridOrigin(GridLevel::Upper), s = scene.grid(GridLevel::Upper).size();
        addBoxOutline(mesh, o, {o.x + s.x, o.y + s.y, o.z + s.z}, cellSize, false);
    } else if (kind == sandcore::SceneKind::Sculpture) {
        addBoxOutline(mesh, {0, 0, 0}, scene.grid(GridLevel::Lower).size(), cellSize, true);
    }
    return mesh;
}

} // namespace sandglass
