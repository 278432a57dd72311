// SPDX-License-Identifier: MIT
// wild_report: loads generated models of every class as a user would (no options) and prints the
// share of each class that passes the checks of wild_checks.hpp, with the first failures.
//   wild_report [--count N] [--seed S] [--res R] [--class NAME] [--no-drain] [--failures]
// --class checks one class only; --failures also lists every failing model on standard error as
// it is found. A model's seed alone names it: even seeds are written as STL, odd ones as OBJ.
#include "wild_models/wild_checks.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>
#include <vector>

using namespace sandglass::wild;

int main(int argc, char** argv) {
    int count = 20;
    std::uint64_t seed = 1;
    CheckSettings settings;
    bool everyFailure = false;
    std::string onlyClass;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--count" && i + 1 < argc) count = std::atoi(argv[++i]);
        else if (arg == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
        else if (arg == "--res" && i + 1 < argc) settings.resolution = std::atoi(argv[++i]);
        else if (arg == "--class" && i + 1 < argc) onlyClass = argv[++i];
        else if (arg == "--no-drain") settings.drain = false;
        else if (arg == "--failures") everyFailure = true;
        else {
            std::fprintf(stderr, "usage: wild_report [--count N] [--seed S] [--res R] [--class NAME] [--no-drain] [--failures]\n");
            return 2;
        }
    }
    std::string folder = (std::filesystem::temp_directory_path() / "wild-report-XXXXXX").string();
    if (!::mkdtemp(folder.data())) return 1;
    std::printf("| class | passed | median build ms | first failure |\n|---|---|---|---|\n");
    for (ModelClass modelClass : kAllClasses) {
        if (!onlyClass.empty() && onlyClass != className(modelClass)) continue;
        int passed = 0;
        std::vector<double> milliseconds;
        std::string firstFailure;
        for (int i = 0; i < count; ++i) {
            const std::uint64_t s = seed + std::uint64_t(i);
            const WildModel model = generate(modelClass, s);
            const std::filesystem::path file = std::filesystem::path(folder) / (std::string(className(modelClass)) + (s % 2 == 0 ? ".stl" : ".obj"));
            const ModelCheck check = checkModel(model, file, settings);
            passed += check.passed() ? 1 : 0;
            if (check.loaded) milliseconds.push_back(check.loadMilliseconds);
            if (check.passed()) continue;
            const std::string failure = "seed " + std::to_string(s) + " " + file.extension().string() + ": " + check.failure;
            if (firstFailure.empty()) firstFailure = failure;
            if (everyFailure) std::fprintf(stderr, "%s %s\n", className(modelClass), failure.c_str());
        }
        std::sort(milliseconds.begin(), milliseconds.end());
        const double median = milliseconds.empty() ? 0.0 : milliseconds[milliseconds.size() / 2];
        std::printf("| %s | %d/%d | %.0f | %s |\n", className(modelClass), passed, count, median, firstFailure.c_str());
        std::fflush(stdout);
    }
    std::filesystem::remove_all(folder);
    return 0;
}
