// SPDX-License-Identifier: MIT
// Writes a corpus of models from the wild, with a line per file in corpus.txt:
//   wild_models OUT_DIR [--count N] [--seed S] [--subdivide K]
// N models of every class (default 3), seeds S, S+1, ... (default 1), each as OBJ and STL.
// --subdivide K splits every triangle into 4^K (the same surface, for timing dense models: K = 3
// gives a thick-framed hourglass of about a million triangles).
#include "wild_models/wild_models.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

const char* const kUpAxisNames[] = {"+x", "-x", "+y", "-y", "+z", "-z"};

int usage() {
    std::fprintf(stderr, "usage: wild_models OUT_DIR [--count N] [--seed S] [--subdivide K]\n");
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') return usage();
    const std::filesystem::path folder = argv[1];
    long long count = 3;
    unsigned long long firstSeed = 1;
    long long subdivisions = 0;
    for (int i = 2; i < argc; ++i) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) return usage();
        char* end = nullptr;
        if (flag == "--count") count = std::strtoll(argv[++i], &end, 10);
        else if (flag == "--seed") firstSeed = std::strtoull(argv[++i], &end, 10);
        else if (flag == "--subdivide") subdivisions = std::strtoll(argv[++i], &end, 10);
        else return usage();
        if (end == nullptr || *end != '\0' || count < 1 || subdivisions < 0 || subdivisions > 6) return usage();
    }
    try {
        std::filesystem::create_directories(folder);
        std::ofstream corpus(folder / "corpus.txt");
        corpus << "# file class seed up unit_scale canonical_height objects triangles\n";
        std::size_t files = 0;
        for (sandglass::wild::ModelClass modelClass : sandglass::wild::kAllClasses)
            for (long long i = 0; i < count; ++i) {
                const std::uint64_t seed = firstSeed + std::uint64_t(i);
                sandglass::wild::WildModel model = sandglass::wild::generate(modelClass, seed);
                for (sandglass::wild::Object& object : model.objects) object.mesh = sandglass::wild::subdivided(object.mesh, int(subdivisions));
                const std::string stem = std::string(sandglass::wild::className(modelClass)) + "_" + std::to_string(seed);
                sandglass::wild::writeObj(model, folder / (stem + ".obj"));
                sandglass::wild::writeStl(model, folder / (stem + ".stl"));
                for (const char* extension : {".obj", ".stl"}) {
                    char scale[32];
                    std::snprintf(scale, sizeof scale, "%.9g", model.unitScale);
                    corpus << stem << extension << ' ' << sandglass::wild::className(modelClass) << ' ' << seed << ' '
                           << kUpAxisNames[model.upAxis] << ' ' << scale << ' ' << model.height << ' ' << model.objects.size() << ' '
                           << model.triangleCount() << '\n';
                    ++files;
                }
            }
        if (!corpus) throw std::runtime_error("cannot write " + (folder / "corpus.txt").string());
        std::printf("%s: %zu files\n", folder.string().c_str(), files);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "wild_models: %s\n", error.what());
        return 1;
    }
    return 0;
}
