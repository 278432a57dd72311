// SPDX-License-Identifier: MIT
#include "scene/mesh_loader.hpp"

#include "checked_import.hpp"
#include "scene/file_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sys/stat.h>

namespace sandglass {

namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

// Spacing of single-precision numbers at magnitude `distance`.
double floatStepAt(double distance) {
    const float at = float(std::max(distance, double(std::numeric_limits<float>::min())));
    return double(std::nextafter(at, std::numeric_limits<float>::infinity())) - double(at);
}

double timeLimitFor(const std::string& path, const MeshLoadOptions& options) {
    if (options.timeLimitSeconds > 0.0) return options.timeLimitSeconds;
    struct stat info {};
    const double mebibytes = ::stat(path.c_str(), &info) == 0 ? double(info.st_size) / double(1 << 20) : 0.0;
    return 20.0 + mebibytes;
}

} // namespace

sandcore::Vec3 CheckedImport::centred(std::uint32_t i) const {
    const auto& p = imported.vertices[i];
    return {float(p[0] - centre[0]), float(p[1] - centre[1]), float(p[2] - centre[2])};
}

CheckedImport importChecked(const std::string& path, const MeshLoadOptions& options) {
    try {
        requireReadableRegularFile(path); // a FIFO would block the importer forever
    } catch (const FileError& e) {
        // FileError's message is "path: cause" already.
        throw ModelError(path, std::string(e.what()).substr(std::min(path.size() + 2, std::string(e.what()).size())));
    }
    CheckedImport out;
    out.imported = importInChildProcess(path, timeLimitFor(path, options));
    const ImportedTriangles& imported = out.imported;
    if (!imported.error.empty()) throw ModelError(path, imported.error);
    if (imported.triangles.empty()) throw ModelError(path, "contains no triangles (only points or lines, or nothing)");

    // Bounds of the vertices that triangles use, in double.
    std::array<double, 3> low, high;
    low.fill(std::numeric_limits<double>::infinity());
    high.fill(-std::numeric_limits<double>::infinity());
    for (const auto& t : imported.triangles)
        for (std::uint32_t i : t) {
            const auto& p = imported.vertices[i];
            for (std::size_t a = 0; a < 3; ++a) {
                if (!std::isfinite(p[a]))
                    throw ModelError(path, "vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
                low[a] = std::min(low[a], p[a]);
                high[a] = std::max(high[a], p[a]);
            }
        }
    double distance = 0.0, largest = 0.0;
    for (std::size_t a = 0; a < 3; ++a) {
        distance = std::max({distance, std::abs(low[a]), std::abs(high[a])});
        largest = std::max(largest, high[a] - low[a]);
    }
    // H2: assimp stores coordinates in single precision. A model whose size is a few steps of
    // single precision at its distance from the origin has lost its shape before we see it.
    const double step = floatStepAt(distance);
    if (largest < kMinSinglePrecisionSteps * step)
        throw ModelError(path, "the coordinates cannot hold the model: its largest extent " + number(largest) +
                                   " is below what single precision resolves at its distance " + number(distance) +
                                   " from the origin (steps of " + number(step) + "; at least " +
                                   number(kMinSinglePrecisionSteps) + " steps are needed); move the model nearer the origin");
    const char* axes[3] = {"x", "y", "z"};
    for (std::size_t a = 0; a < 3; ++a)
        if (!(high[a] - low[a] > 0.0))
            throw ModelError(path, std::string("has zero extent along ") + axes[a] + " (a flat model encloses no volume)");
    for (std::size_t a = 0; a < 3; ++a) out.centre[a] = 0.5 * (low[a] + high[a]);
    return out;
}

sandcore::TriangleMesh loadMesh(const std::string& path, const MeshLoadOptions& options) {
    const CheckedImport checked = importChecked(path, options);
    // Relative to the bounding-box centre, in double, before anything is rounded to float.
    sandcore::TriangleMesh mesh;
    mesh.vertices.reserve(checked.imported.vertices.size());
    for (std::uint32_t i = 0; i < std::uint32_t(checked.imported.vertices.size()); ++i)
        mesh.vertices.push_back(checked.centred(i));
    mesh.triangles = checked.imported.triangles;
    return sandcore::weldVertices(mesh);
}

} // namespace sandglass
