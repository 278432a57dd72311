// SPDX-License-Identifier: MIT
// libFuzzer target of the model loader (SPEC H4). The first byte picks the format's extension,
// the rest is the file. loadMesh must return a mesh or throw ModelError with one line; a crash
// or hang of assimp itself is contained in the import child and is not a finding. The bytes are
// also fed to decodeImport, the parent's reader of the child's reply, which must never read
// out of bounds.

#include "isolated_import.hpp"
#include "scene/mesh_loader.hpp"

#include "fuzz_file.hpp"

#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<std::uint8_t> reply(data, data + size);
    const sandglass::ImportedTriangles decoded = sandglass::decodeImport(reply);
    for (const auto& t : decoded.triangles)
        for (std::uint32_t i : t)
            if (i >= decoded.vertices.size()) std::abort();

    if (size < 1) return 0;
    static const char* const extensions[] = {".obj", ".ply", ".off", ".stl", ".gltf", ".glb"};
    const fuzzing::InputFile file(data + 1, size - 1, extensions[data[0] % 6]);
    try {
        const sandcore::TriangleMesh mesh = sandglass::loadMesh(file.path(), {2.0});
        if (mesh.triangles.empty()) std::abort(); // loadMesh promises triangles
    } catch (const sandglass::ModelError& e) {
        const std::string message = e.what();
        if (message.rfind(file.path() + ": ", 0) != 0 || message.find('\n') != std::string::npos) std::abort();
    }
    return 0;
}
