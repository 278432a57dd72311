// SPDX-License-Identifier: MIT
// W6: sand exported from a model scene sits in the model's own coordinates and units, inside
// its glass, whatever up axis, unit and offset the file has, and also after a turn-over.
#include "support/temporary_folder.hpp"
#include "wild_models/wild_models.hpp"

#include "scene/scene_export.hpp"
#include "scene/scene_request.hpp"

#include <doctest/doctest.h>

#include <cstring>
#include <iomanip>
#include <fstream>
#include <sstream>

using namespace sandglass;

namespace {

struct Cloud {
    std::string header;
    std::vector<sandcore::Vec3> points;
};

Cloud readCloud(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Cloud cloud;
    const std::size_t end = bytes.find("end_header\n");
    REQUIRE(end != std::string::npos);
    cloud.header = bytes.substr(0, end);
    for (std::size_t at = end + std::strlen("end_header\n"); at + 15 <= bytes.size(); at += 15) {
        float xyz[3];
        std::memcpy(xyz, bytes.data() + at, sizeof xyz);
        cloud.points.push_back({xyz[0], xyz[1], xyz[2]});
    }
    return cloud;
}

} // namespace

TEST_CASE("W6: exported sand lies inside the glass in the file's own coordinates, turned over or not") {
    TemporaryFolder folder;
    for (std::uint64_t seed : {21, 22, 23, 24}) {
        const wild::WildModel model = wild::generate(wild::ModelClass::SingleWall, seed);
        const std::filesystem::path file = folder / ("glass-" + std::to_string(seed) + ".obj");
        wild::writeObj(model, file);
        SceneSettings settings;
        settings.request.modelPath = file.string();
        settings.request.resolution = 40;
        BuiltScene built = buildSceneWithReport(settings);
        REQUIRE(built.modelToWorld.has_value());
        const double cell = 1.0 / built.modelToWorld->placement.scale[1];
        for (int i = 0; i < 40; ++i) built.scene.step();
        for (bool turned : {false, true}) {
            CAPTURE(seed);
            CAPTURE(turned);
            if (turned) REQUIRE(built.scene.flip());
            const std::filesystem::path ply = folder / "sand.ply";
            exportScene(ply, built.scene, {{}, &*built.modelToWorld});
            const Cloud cloud = readCloud(ply);
            CHECK(cloud.points.size() == std::size_t(built.scene.grainCount()));
            std::ostringstream size;
            size << "comment cell_size " << std::setprecision(9) << cell;
            CHECK(cloud.header.find(size.str()) != std::string::npos);
            int outside = 0;
            for (const sandcore::Vec3& p : cloud.points) outside += model.insideGlass(p, 1.5 * cell) ? 0 : 1;
            CHECK(outside == 0);
        }
        // The surface mesh too (binary STL: 80 bytes, a count, 50 bytes a triangle): every corner
        // within a cell's diagonal of the glass's inside.
        const std::filesystem::path stl = folder / "sand.stl";
        exportScene(stl, built.scene, {{}, &*built.modelToWorld});
        std::ifstream in(stl, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        REQUIRE(bytes.size() > 84);
        int outside = 0;
        for (std::size_t at = 84 + 12; at + 36 <= bytes.size(); at += 50)
            for (std::size_t corner = 0; corner < 3; ++corner) {
                float xyz[3];
                std::memcpy(xyz, bytes.data() + at + 12 * corner, sizeof xyz);
                outside += model.insideGlass({xyz[0], xyz[1], xyz[2]}, 2.0 * cell) ? 0 : 1;
            }
        CHECK(outside == 0);
    }
}
