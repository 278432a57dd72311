// SPDX-License-Identifier: MIT
#include "scene/model_drawing.hpp"

#include "sandcore/mesh_shells.hpp"

#include <algorithm>
#include <cmath>

namespace sandglass {

using sandcore::Vec3;

namespace {

Vec3 minus(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 cross(const Vec3& a, const Vec3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
float dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 normalized(const Vec3& v) {
    const float length = std::sqrt(dot(v, v));
    return length > 0.0f ? Vec3{v.x / length, v.y / length, v.z / length} : Vec3{0.0f, 0.0f, 0.0f};
}

// Smooth normals with sharp creases: a corner averages the area-weighted normals of the
// triangles around its vertex that turn less than kCreaseDegrees from its own triangle, so a
// glass wall shades round while a plate's edge or a tube's rim stays crisp.
std::vector<ModelVertex> smoothTriangles(const sandcore::TriangleMesh& mesh) {
    const std::size_t triangleCount = mesh.triangles.size();
    std::vector<Vec3> faceNormals(triangleCount); // length = twice the area
    std::vector<std::uint32_t> start(mesh.vertices.size() + 1, 0);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const auto& tri = mesh.triangles[t];
        faceNormals[t] = cross(minus(mesh.vertices[tri[1]], mesh.vertices[tri[0]]),
                               minus(mesh.vertices[tri[2]], mesh.vertices[tri[0]]));
        for (std::uint32_t v : tri) ++start[v + 1];
    }
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> around(start.back()), filled(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < triangleCount; ++t)
        for (std::uint32_t v : mesh.triangles[t]) around[filled[v]++] = std::uint32_t(t);
    const float creaseCos = std::cos(kCreaseDegrees * 3.14159265f / 180.0f);
    std::vector<ModelVertex> out;
    out.reserve(3 * triangleCount);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const Vec3 own = normalized(faceNormals[t]);
        for (std::uint32_t v : mesh.triangles[t]) {
            Vec3 sum{0.0f, 0.0f, 0.0f};
            for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
                const Vec3& other = faceNormals[around[i]];
                if (dot(own, normalized(other)) >= creaseCos) sum = {sum.x + other.x, sum.y + other.y, sum.z + other.z};
            }
            Vec3 normal = normalized(sum);
            if (dot(normal, normal) == 0.0f) normal = own;
            if (dot(normal, normal) == 0.0f) normal = {0.0f, 1.0f, 0.0f}; // a degenerate triangle
            const Vec3& p = mesh.vertices[v];
            out.push_back({p.x, p.y, p.z, normal.x, normal.y, normal.z});
        }
    }
    return out;
}

} // namespace

Vec3 ModelToWorld::apply(const Vec3& model) const {
    // Model units to grid cells, in double as the voxelizer's toGridSpace.
    const double m[3] = {double(model.x), double(model.y), double(model.z)};
    double grid[3];
    for (std::size_t a = 0; a < 3; ++a) grid[a] = (m[a] - placement.modelMin[a]) * placement.scale[a] + placement.padding[a];
    // The quarter turns of sandcore::turnToUp, for points: a cell [q, q+1] along a mirrored axis
    // becomes [size - 1 - q, size - q], so the point u goes to size - u.
    const sandcore::AxisTurn turn = sandcore::axisTurnFor(up);
    const int size[3] = {placement.size.x, placement.size.y, placement.size.z};
    const int origin[3] = {maskOrigin.x, maskOrigin.y, maskOrigin.z};
    double world[3];
    for (int a = 0; a < 3; ++a) {
        const int source = turn.source[a];
        const double along = turn.sign[a] > 0 ? grid[source] : double(size[source]) - grid[source];
        world[a] = along + double(origin[a]);
    }
    return {float(world[0]), float(world[1]), float(world[2])};
}

std::array<double, 3> ModelToWorld::toFile(const Vec3& world) const {
    const sandcore::AxisTurn turn = sandcore::axisTurnFor(up);
    const int size[3] = {placement.size.x, placement.size.y, placement.size.z};
    const int origin[3] = {maskOrigin.x, maskOrigin.y, maskOrigin.z};
    const double w[3] = {double(world.x), double(world.y), double(world.z)};
    double grid[3];
    for (int a = 0; a < 3; ++a) {
        const int source = turn.source[a];
        const double along = w[a] - double(origin[a]);
        grid[source] = turn.sign[a] > 0 ? along : double(size[source]) - along;
    }
    std::array<double, 3> file{};
    for (std::size_t a = 0; a < 3; ++a)
        file[a] = (grid[a] - placement.padding[a]) / placement.scale[a] + placement.modelMin[a] + fileCentre[a];
    return file;
}

void includeInBounds(const ModelDrawing& drawing, bool turnedOver, float cellSize, Vec3& lo, Vec3& hi) {
    for (const DrawnPart& part : drawing.parts)
        for (const ModelVertex& v : part.vertices) {
            const Vec3 p{v.x * cellSize, (turnedOver ? drawing.heightCells - v.y : v.y) * cellSize, v.z * cellSize};
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        }
}

ModelDrawing makeModelDrawing(const std::vector<ModelPart>& parts, const ModelToWorld& toWorld, float heightCells) {
    ModelDrawing drawing;
    drawing.heightCells = heightCells;
    for (const ModelPart& part : parts) {
        if (part.role == PartRole::Sand) continue; // it becomes the sand
        DrawnPart drawn;
        drawn.name = part.name;
        drawn.look = part.role == PartRole::Vessel ? PartLook::Glass : PartLook::Opaque;
        const std::array<float, 3> fallback = part.role == PartRole::Vessel ? kGlassColour
                                              : part.role == PartRole::Static ? kStoneColour
                                                                              : kWoodColour;
        drawn.colour = part.hasColour ? part.colour : fallback;
        // Normals from the turned, scaled triangles: with --stretch the scale differs per axis.
        // A face modelled twice (once per side) would fight itself in the depth test: draw it once.
        sandcore::TriangleMesh world = sandcore::withoutDoubledFaces(part.mesh);
        for (Vec3& v : world.vertices) v = toWorld.apply(v);
        drawn.vertices = smoothTriangles(world);
        drawing.parts.push_back(std::move(drawn));
    }
    return drawing;
}

} // namespace sandglass
