// SPDX-License-Identifier: MIT
#include "artist_models.hpp"

#include "sandcore/mesh_shapes.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

using namespace sandcore;

namespace {

constexpr double kPi = std::numbers::pi;

struct Part {
    std::string name;
    std::string material;
    TriangleMesh mesh;
};

struct Material {
    std::string name;
    float r, g, b;
    float opacity;
};

// A closed surface of revolution from a closed loop of (radius, y) points, none on the axis:
// a tube wall with its rims (the loop runs up the outside and down the inside).
TriangleMesh revolveLoop(const std::vector<ProfilePoint>& loop, int segments) {
    TriangleMesh mesh;
    const auto n = std::uint32_t(loop.size());
    for (int s = 0; s < segments; ++s) {
        const double angle = 2.0 * kPi * s / segments;
        for (const ProfilePoint& p : loop)
            mesh.vertices.push_back({float(p.radius * std::cos(angle)), p.y, float(p.radius * std::sin(angle))});
    }
    for (std::uint32_t s = 0; s < std::uint32_t(segments); ++s) {
        const std::uint32_t t = (s + 1) % std::uint32_t(segments);
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t j = (i + 1) % n;
            const std::uint32_t a = s * n + i, b = s * n + j, c = t * n + j, d = t * n + i;
            mesh.triangles.push_back({a, c, b});
            mesh.triangles.push_back({a, d, c});
        }
    }
    return mesh;
}

TriangleMesh cylinder(double radius, double y0, double y1, double x, double z, int segments) {
    TriangleMesh mesh = makeLatheMesh({{0.0f, float(y0)}, {float(radius), float(y0)}, {float(radius), float(y1)}, {0.0f, float(y1)}},
                                      segments);
    for (Vec3& v : mesh.vertices) v = {v.x + float(x), v.y, v.z + float(z)};
    return mesh;
}

// The glass's inner radius over its height t in [0, 1] (0.5 = the neck): round bulbs, a neck
// wide enough for sand at 40 cells, and mouths half a bulb wide where the plates close it.
double innerRadius(double t) {
    const double d = std::abs(t - 0.5) * 2.0; // 0 at the neck, 1 at the mouths
    const double neck = 0.1, bulb = 0.55;
    if (d <= 0.6) return neck + (bulb - neck) * std::sin(0.5 * kPi * d / 0.6);
    if (d <= 0.8) return bulb;
    const double s = (d - 0.8) / 0.2;
    return bulb * std::sqrt(1.0 - 0.75 * s * s);
}

// Glass from y0 to y1 with wall `thickness`: outer surface up, rim, inner surface down, rim.
TriangleMesh glassTube(double y0, double y1, double thickness, int samples, int segments) {
    std::vector<ProfilePoint> loop;
    for (int i = 0; i <= samples; ++i) {
        const double t = double(i) / samples;
        loop.push_back({float(innerRadius(t) + thickness), float(y0 + (y1 - y0) * t)});
    }
    for (int i = samples; i >= 0; --i) {
        const double t = double(i) / samples;
        loop.push_back({float(innerRadius(t)), float(y0 + (y1 - y0) * t)});
    }
    return revolveLoop(loop, segments);
}

// One closed surface of revolution following innerRadius + offset, closed at both ends.
TriangleMesh closedGlassSurface(double y0, double y1, double offset, int samples, int segments) {
    std::vector<ProfilePoint> profile{{0.0f, float(y0)}};
    for (int i = 0; i <= samples; ++i) {
        const double t = double(i) / samples;
        profile.push_back({float(innerRadius(t) + offset), float(y0 + (y1 - y0) * t)});
    }
    profile.push_back({0.0f, float(y1)});
    return makeLatheMesh(profile, segments);
}

std::vector<Part> framedHourglass() {
    // Plates 0.1 thick; the glass reaches 0.02 into each so the parts overlap as modelled ones do.
    const double plate = 0.1, height = 2.2, thickness = 0.03;
    std::vector<Part> parts;
    parts.push_back({"glass", "glass", glassTube(plate - 0.02, height - plate + 0.02, thickness, 64, 64)});
    parts.push_back({"bottom_plate", "wood", cylinder(0.8, 0.0, plate, 0.0, 0.0, 48)});
    parts.push_back({"top_plate", "wood", cylinder(0.8, height - plate, height, 0.0, 0.0, 48)});
    for (int i = 0; i < 3; ++i) {
        const double angle = 2.0 * kPi * (i + 0.25) / 3.0;
        parts.push_back({"pillar_" + std::to_string(i + 1), "wood",
                         cylinder(0.05, plate - 0.02, height - plate + 0.02, 0.68 * std::cos(angle), 0.68 * std::sin(angle), 16)});
    }
    return parts;
}

std::vector<Part> cappedGlass() {
    // The glass is closed at both ends: an outer and an inner closed surface, the cavity inside.
    const double cap = 0.12, height = 2.3, thickness = 0.04;
    Part glass{"glass", "glass", closedGlassSurface(cap, height - cap, thickness, 64, 64)};
    // The inner surface faces the cavity, as modelled glass does: its triangles wind the other way.
    TriangleMesh inner = closedGlassSurface(cap + thickness, height - cap - thickness, 0.0, 64, 64);
    for (auto& t : inner.triangles) std::swap(t[1], t[2]);
    glass.mesh.append(inner);
    std::vector<Part> parts{glass};
    parts.push_back({"cap_bottom", "wood", cylinder(0.75, 0.0, cap, 0.0, 0.0, 48)});
    parts.push_back({"cap_top", "wood", cylinder(0.75, height - cap, height, 0.0, 0.0, 48)});
    for (int i = 0; i < 4; ++i) {
        const double angle = 2.0 * kPi * (i + 0.5) / 4.0;
        parts.push_back({"post_" + std::to_string(i + 1), "wood",
                         cylinder(0.06, cap, height - cap, 0.69 * std::cos(angle), 0.69 * std::sin(angle), 16)});
    }
    return parts;
}

const std::vector<Material> kMaterials{{"glass", 0.82f, 0.9f, 0.95f, 0.25f}, {"wood", 0.45f, 0.27f, 0.13f, 1.0f}};

bool writeObjWithParts(const std::string& dir, const std::string& name, const std::vector<Part>& parts,
                       const std::string& comment) {
    const std::string mtl = name + ".mtl";
    std::FILE* m = std::fopen((dir + "/" + mtl).c_str(), "w");
    std::FILE* f = std::fopen((dir + "/" + name + ".obj").c_str(), "w");
    if (m == nullptr || f == nullptr) {
        std::fprintf(stderr, "make_models: cannot write %s/%s\n", dir.c_str(), name.c_str());
        if (m) std::fclose(m);
        if (f) std::fclose(f);
        return false;
    }
    std::fprintf(m, "# materials of %s.obj, generated by tools/make_models.cpp\n", name.c_str());
    for (const Material& mat : kMaterials)
        std::fprintf(m, "newmtl %s\nKd %.3f %.3f %.3f\nd %.2f\n", mat.name.c_str(), mat.r, mat.g, mat.b, mat.opacity);
    std::fclose(m);
    std::fprintf(f, "# %s\n# generated by tools/make_models.cpp\nmtllib %s\n", comment.c_str(), mtl.c_str());
    std::uint32_t base = 1;
    std::size_t triangles = 0;
    for (const Part& part : parts) {
        std::fprintf(f, "o %s\nusemtl %s\n", part.name.c_str(), part.material.c_str());
        for (const Vec3& v : part.mesh.vertices) std::fprintf(f, "v %.5f %.5f %.5f\n", v.x, v.y, v.z);
        for (const auto& t : part.mesh.triangles) std::fprintf(f, "f %u %u %u\n", t[0] + base, t[1] + base, t[2] + base);
        base += std::uint32_t(part.mesh.vertices.size());
        triangles += part.mesh.triangles.size();
    }
    std::fclose(f);
    std::printf("%s/%s.obj: %zu parts, %zu triangles\n", dir.c_str(), name.c_str(), parts.size(), triangles);
    return true;
}

// One binary STL of every part, turned so that the model's up (+y) becomes +z.
bool writeBinaryStlZUp(const std::string& path, const std::vector<Part>& parts) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) {
        std::fprintf(stderr, "make_models: cannot write %s\n", path.c_str());
        return false;
    }
    char header[80] = "framed hourglass, Z up, generated by tools/make_models.cpp";
    std::fwrite(header, 1, 80, f);
    std::uint32_t count = 0;
    for (const Part& part : parts) count += std::uint32_t(part.mesh.triangles.size());
    std::fwrite(&count, 4, 1, f);
    auto zUp = [](Vec3 v) { return Vec3{v.x, -v.z, v.y}; }; // a quarter turn about x
    for (const Part& part : parts)
        for (const auto& t : part.mesh.triangles) {
            const Vec3 a = zUp(part.mesh.vertices[t[0]]), b = zUp(part.mesh.vertices[t[1]]), c = zUp(part.mesh.vertices[t[2]]);
            const float u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, w[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
            float record[12] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0],
                                a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z};
            const float length = std::sqrt(record[0] * record[0] + record[1] * record[1] + record[2] * record[2]);
            for (int i = 0; i < 3; ++i) record[i] = length > 0 ? record[i] / length : 0.0f;
            const std::uint16_t attributes = 0;
            std::fwrite(record, 4, 12, f);
            std::fwrite(&attributes, 2, 1, f);
        }
    std::fclose(f);
    std::printf("%s: %u triangles\n", path.c_str(), count);
    return true;
}

} // namespace

bool writeArtistModels(const std::string& dir) {
    bool ok = true;
    const std::vector<Part> framed = framedHourglass();
    ok &= writeObjWithParts(dir, "framed_hourglass", framed,
                            "framed hourglass: glass 0.03 thick, open at the ends, closed by two plates; three pillars");
    ok &= writeBinaryStlZUp(dir + "/framed_hourglass_z.stl", framed);
    ok &= writeObjWithParts(dir, "capped_glass", cappedGlass(),
                            "capped glass: a closed glass with an inner cavity between two caps and four posts");
    return ok;
}
