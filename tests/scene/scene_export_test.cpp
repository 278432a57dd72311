// SPDX-License-Identifier: MIT
// SPEC E2: exports for other tools, each read back by an independent reader.
#include "scene/file_io.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/sand_patterns.hpp"
#include "scene/scene_export.hpp"

#include "sandcore/procedural_shapes.hpp"
#include "sandcore/triangle_mesh.hpp"

#include "support/state_scenes.hpp"
#include "support/temporary_folder.hpp"
#include "support/vox_reader.hpp"

#include <doctest/doctest.h>

#include <cstring>
#include <map>
#include <random>
#include <set>
#include <sstream>

using namespace sandglass;
using sandcore::GridLevel;
using sandcore::Int3;

namespace {

// World cells holding a grain, with the colour of one grain there (a lower-grid grain wins).
std::map<std::tuple<int, int, int>, std::uint32_t> worldGrains(const sandcore::Scene& scene) {
    const auto patterns = makeSandPatterns();
    std::map<std::tuple<int, int, int>, std::uint32_t> cells;
    const sandcore::GrainStore& g = scene.grains();
    for (std::uint32_t id = 0; id < g.size(); ++id) {
        const Int3 c = scene.grid(g.level[id]).coordinate(g.place[id].cell);
        const int y = c.y + scene.gridOrigin(g.level[id]).y;
        const auto key = std::make_tuple(c.x, y, c.z);
        const std::uint32_t color = grainExportColor(patterns, g.identity[id], g.color[id]);
        if (!cells.count(key) || g.level[id] == GridLevel::Lower) cells[key] = color;
    }
    return cells;
}

sandcore::Scene settledCanvas() {
    sandcore::Scene scene = support::paintedCanvas();
    for (int i = 0; i < 30; ++i) scene.step();
    return scene;
}

} // namespace

TEST_CASE("export: the PLY holds one vertex per grain at its display position, in its colour") {
    TemporaryFolder folder;
    const sandcore::Scene scene = settledCanvas();
    sandcore::DisplaySettings display;
    display.cellSize = 0.25f;
    exportScene(folder / "sand.ply", scene, {display});
    const std::vector<std::uint8_t> bytes = readFileBytes(folder / "sand.ply");
    const std::string text(bytes.begin(), bytes.end());
    const std::size_t headerEnd = text.find("end_header\n");
    REQUIRE(headerEnd != std::string::npos);
    const std::string header = text.substr(0, headerEnd);
    CHECK(header.find("comment cell_size 0.25\n") != std::string::npos);
    CHECK(header.find("element vertex " + std::to_string(scene.grainCount()) + "\n") != std::string::npos);
    CHECK(header.find("property uchar red\nproperty uchar green\nproperty uchar blue\n") != std::string::npos);
    const std::size_t body = headerEnd + std::strlen("end_header\n");
    REQUIRE(bytes.size() - body == std::size_t(scene.grainCount()) * 15);
    std::vector<sandcore::Vec3> expected(std::size_t(scene.grainCount()));
    sandcore::writeDisplayPositions(scene, 1.0f, display, expected);
    const auto patterns = makeSandPatterns();
    int wrong = 0, red = 0;
    for (std::size_t id = 0; id < expected.size(); ++id) {
        float xyz[3];
        std::memcpy(xyz, bytes.data() + body + 15 * id, 12);
        const std::uint8_t* rgb = bytes.data() + body + 15 * id + 12;
        const std::uint32_t color = grainExportColor(patterns, scene.grains().identity[id], scene.grains().color[id]);
        if (xyz[0] != expected[id].x || xyz[1] != expected[id].y || xyz[2] != expected[id].z) ++wrong;
        if (rgb[0] != (color & 255) || rgb[1] != ((color >> 8) & 255) || rgb[2] != ((color >> 16) & 255)) ++wrong;
        red += rgb[0] == 0xe0 && rgb[1] == 0x20 ? 1 : 0;
    }
    CHECK(wrong == 0);
    CHECK(red > 0);
}

TEST_CASE("export: the .vox reads back with every grain cell in its place and colour") {
    TemporaryFolder folder;
    const sandcore::Scene scene = settledCanvas();
    exportScene(folder / "sand.vox", scene);
    const support::VoxFile vox = support::readVox(readFileBytes(folder / "sand.vox"));
    const auto expected = worldGrains(scene);
    const int sizeZ = scene.grid(GridLevel::Lower).size().z;
    CHECK(vox.voxels.size() == expected.size());
    int wrong = 0;
    for (const auto& [cell, color] : expected) {
        const auto [x, y, z] = cell;
        const auto it = vox.voxels.find({x, sizeZ - 1 - z, y}); // MagicaVoxel is z up
        if (it == vox.voxels.end() || vox.palette[it->second] != color) ++wrong;
    }
    CHECK(wrong == 0);
}

TEST_CASE("export: grids over 256 cells per axis become several models that join up") {
    VoxelVolume volume;
    volume.size = {300, 5, 270};
    volume.index.assign(std::size_t(300 * 5 * 270), 0);
    volume.palette[1] = 0xff0000ffu;
    volume.palette[2] = 0xff00ff00u;
    std::set<std::tuple<int, int, int>> filled;
    std::mt19937 random(9);
    for (int i = 0; i < 2000; ++i) {
        const int x = int(random() % 300), y = int(random() % 5), z = int(random() % 270);
        volume.index[std::size_t(x) + 300u * (std::size_t(z) + 270u * std::size_t(y))] = std::uint8_t(1 + (x + z) % 2);
        filled.insert({x, 270 - 1 - z, y});
    }
    const support::VoxFile vox = support::readVox(encodeVox(volume));
    CHECK(vox.models == 4);
    CHECK(vox.largestModelSide <= 256);
    std::set<std::tuple<int, int, int>> read;
    for (const auto& [cell, index] : vox.voxels) {
        read.insert(cell);
        CHECK(index == 1 + (std::get<0>(cell) + (269 - std::get<1>(cell))) % 2);
    }
    CHECK(read == filled);
}

TEST_CASE("export: more than 255 colours are quantised to a palette close to every colour") {
    std::mt19937 random(5);
    std::vector<std::uint32_t> colors;
    std::vector<std::uint64_t> counts;
    for (int i = 0; i < 3000; ++i) {
        colors.push_back(0xff000000u | (random() & 0xffffffu));
        counts.push_back(1 + random() % 10);
    }
    std::array<std::uint32_t, 256> palette{};
    const std::vector<std::uint8_t> index = quantiseColors(colors, counts, palette);
    int worst = 0;
    for (std::size_t i = 0; i < colors.size(); ++i) {
        REQUIRE(index[i] >= 1);
        for (int k = 0; k < 3; ++k)
            worst = std::max(worst, std::abs(int((colors[i] >> (8 * k)) & 255) - int((palette[index[i]] >> (8 * k)) & 255)));
    }
    CHECK(worst < 64); // 255 boxes over a random cube: about 40 per channel at worst
    // No more than 255 colours: kept exactly.
    const std::vector<std::uint32_t> few{0xff102030u, 0xff405060u, 0xffa0b0c0u};
    const auto exact = quantiseColors(few, {5, 1, 2}, palette);
    for (std::size_t i = 0; i < few.size(); ++i) CHECK(palette[exact[i]] == few[i]);
}

TEST_CASE("export: the surface mesh re-imports through assimp closed, with the sand's volume") {
    TemporaryFolder folder;
    const sandcore::Scene scene = settledCanvas();
    const auto cells = worldGrains(scene);
    for (const char* name : {"sand.obj", "sand.stl", "sand.glb"}) {
        CAPTURE(name);
        exportScene(folder / name, scene);
        const sandcore::TriangleMesh mesh = loadMesh((folder / name).string());
        const sandcore::MeshClosedness closed = sandcore::closednessOf(mesh);
        CHECK(closed.closed);
        CHECK(closed.boundaryEdges == 0);
        // Each edge is met once in each direction (outward orientation everywhere), so the
        // divergence theorem gives the volume exactly: one per grain cell at cell size 1.
        const sandcore::TriangleMesh welded = sandcore::weldVertices(mesh);
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
        for (const auto& t : welded.triangles)
            for (int e = 0; e < 3; ++e) ++directed[{t[std::size_t(e)], t[std::size_t((e + 1) % 3)]}];
        int unbalanced = 0;
        for (const auto& [edge, count] : directed) unbalanced += directed[{edge.second, edge.first}] != count ? 1 : 0;
        CHECK(unbalanced == 0);
        CHECK(sandcore::signedVolume(mesh) == doctest::Approx(double(cells.size())).epsilon(1e-9));
    }
}

TEST_CASE("export: voxelize --out writes the inside cells as .binvox and .vox") {
    TemporaryFolder folder;
    const sandcore::InsideMask mask = sandcore::makeSphereMask(20);
    writeInsideMask(folder / "sphere.binvox", mask);
    const std::vector<std::uint8_t> bytes = readFileBytes(folder / "sphere.binvox");
    const std::string text(bytes.begin(), bytes.end());
    const std::size_t data = text.find("data\n");
    REQUIRE(data != std::string::npos);
    CHECK(text.rfind("#binvox 1\ndim 20 20 20\n", 0) == 0);
    std::vector<std::uint8_t> voxels;
    for (std::size_t at = data + 5; at + 1 < bytes.size(); at += 2) voxels.insert(voxels.end(), bytes[at + 1], bytes[at]);
    REQUIRE(voxels.size() == 8000);
    int wrong = 0;
    for (int x = 0; x < 20; ++x)
        for (int z = 0; z < 20; ++z)
            for (int y = 0; y < 20; ++y) wrong += (voxels[std::size_t(x * 400 + z * 20 + y)] != 0) != mask.at(x, y, z) ? 1 : 0;
    CHECK(wrong == 0);
    writeInsideMask(folder / "sphere.vox", mask);
    const support::VoxFile vox = support::readVox(readFileBytes(folder / "sphere.vox"));
    CHECK(std::int64_t(vox.voxels.size()) == mask.countInside());
    CHECK(vox.voxels.count({10, 20 - 1 - 10, 10}) == 1);
}

TEST_CASE("export: an unknown extension or a missing folder is one line naming the file") {
    TemporaryFolder folder;
    const sandcore::Scene scene = settledCanvas();
    const auto errorOf = [&](const std::filesystem::path& file) -> std::string {
        try {
            exportScene(file, scene);
        } catch (const FileError& e) {
            return e.what();
        }
        return {};
    };
    CHECK(errorOf(folder / "sand.xyz").find("unknown export format '.xyz'") != std::string::npos);
    CHECK(errorOf(folder / "missing" / "sand.ply").rfind((folder / "missing" / "sand.ply").string() + ": ", 0) == 0);
    CHECK_THROWS_AS(writeInsideMask(folder / "mask.png", sandcore::makeSphereMask(8)), FileError);
}
