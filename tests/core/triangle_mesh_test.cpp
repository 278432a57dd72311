// SPDX-License-Identifier: MIT
#include "sandcore/mesh_shapes.hpp"
#include "sandcore/triangle_mesh.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace sandcore;

namespace {
// The same box with every face's corners duplicated, as many exporters write it.
TriangleMesh unweldedBox() {
    const TriangleMesh box = makeBoxMesh({0, 0, 0}, {2, 3, 4});
    TriangleMesh split;
    for (const auto& t : box.triangles) {
        const auto base = std::uint32_t(split.vertices.size());
        for (std::uint32_t i : t) split.vertices.push_back(box.vertices[i]);
        split.triangles.push_back({base, base + 1, base + 2});
    }
    return split;
}
} // namespace

TEST_CASE("a box is closed and its signed volume is width * height * depth") {
    const TriangleMesh box = makeBoxMesh({0, 0, 0}, {2, 3, 4});
    const MeshClosedness c = closednessOf(box);
    CHECK(c.closed);
    CHECK(c.boundaryEdges == 0);
    CHECK(c.nonManifoldEdges == 0);
    CHECK(signedVolume(box) == doctest::Approx(24.0));
}

TEST_CASE("duplicated corners are welded before counting edges") {
    const TriangleMesh split = unweldedBox();
    CHECK(split.vertices.size() == 36);
    CHECK(weldVertices(split).vertices.size() == 8);
    CHECK(closednessOf(split).closed);
    CHECK(signedVolume(split) == doctest::Approx(24.0));
}

TEST_CASE("a box without its top face has the four rim edges as boundary") {
    TriangleMesh box = makeBoxMesh({0, 0, 0}, {1, 1, 1});
    box.triangles.erase(box.triangles.begin() + 6, box.triangles.begin() + 8); // the +y quad
    const MeshClosedness c = closednessOf(box);
    CHECK_FALSE(c.closed);
    CHECK(c.boundaryEdges == 4);
}

TEST_CASE("flipping every face negates the signed volume") {
    TriangleMesh box = makeBoxMesh({-1, -1, -1}, {1, 1, 1});
    for (auto& t : box.triangles) std::swap(t[1], t[2]);
    CHECK(signedVolume(box) == doctest::Approx(-8.0));
    CHECK(closednessOf(box).closed);
}

TEST_CASE("signed volume keeps its precision far from the origin") {
    TriangleMesh box = makeBoxMesh({1048576.0f, -2097152.0f, 4194304.0f}, {1048578.0f, -2097149.0f, 4194308.0f});
    CHECK(signedVolume(box) == doctest::Approx(24.0).epsilon(1e-12));
}

TEST_CASE("generated shapes are closed, outward and near their analytic volume") {
    const TriangleMesh sphere = makeIcosphereMesh(4, 1.0f);
    CHECK(sphere.triangles.size() == 5120);
    CHECK(closednessOf(sphere).closed);
    CHECK(signedVolume(sphere) == doctest::Approx(4.0 / 3.0 * std::numbers::pi).epsilon(0.01));

    const TriangleMesh torus = makeTorusMesh(1.0f, 0.25f, 64, 32);
    CHECK(closednessOf(torus).closed);
    CHECK(signedVolume(torus) == doctest::Approx(2.0 * std::numbers::pi * std::numbers::pi * 0.0625).epsilon(0.01));

    const TriangleMesh cylinder = makeLatheMesh({{0, 0}, {1, 0}, {1, 2}, {0, 2}}, 256);
    CHECK(closednessOf(cylinder).closed);
    CHECK(signedVolume(cylinder) == doctest::Approx(2.0 * std::numbers::pi).epsilon(0.001));

    std::vector<Vec3> ring;
    for (int i = 0; i < 128; ++i) {
        const double a = 2.0 * std::numbers::pi * i / 128;
        ring.push_back({float(3 * std::cos(a)), 0.0f, float(3 * std::sin(a))});
    }
    const TriangleMesh tube = makeTubeMesh(ring, 0.5f, 24);
    CHECK(closednessOf(tube).closed);
    CHECK(std::abs(signedVolume(tube)) == doctest::Approx(2.0 * std::numbers::pi * std::numbers::pi * 3 * 0.25).epsilon(0.02));
}

TEST_CASE("a triangle that repeats a vertex adds no edges") {
    TriangleMesh box = makeBoxMesh({0, 0, 0}, {1, 1, 1});
    box.triangles.push_back({0, 0, 5});
    CHECK(closednessOf(box).closed);
}
