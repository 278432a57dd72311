// SPDX-License-Identifier: MIT
// The sand's surface for printing or rendering elsewhere (E2): every face between a grain cell
// and a cell without one, as two triangles, with each lattice corner one shared vertex, so the
// mesh is closed and consistently oriented (outward). Written by assimp's exporter to memory and
// then through writeFileAtomically like every other output.
#include "scene/file_io.hpp"
#include "scene/scene_export.hpp"

#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <memory>
#include <unordered_map>

namespace sandglass {

using sandcore::Int3;

namespace {

const char* assimpFormatOf(ExportFormat format) {
    switch (format) {
    case ExportFormat::Obj: return "objnomtl"; // one file, no material library beside it
    case ExportFormat::Stl: return "stlb";
    case ExportFormat::Glb: return "glb2";
    default: return nullptr;
    }
}

struct SurfaceBuilder {
    Int3 size;
    float cellSize = 1.0f;
    std::unordered_map<std::uint64_t, unsigned> vertexOf;
    std::vector<aiVector3D> vertices;
    std::vector<unsigned> triangles;

    unsigned corner(int x, int y, int z) {
        const std::uint64_t key = std::uint64_t(x) + std::uint64_t(size.x + 1) * (std::uint64_t(z) + std::uint64_t(size.z + 1) * std::uint64_t(y));
        const auto [it, added] = vertexOf.try_emplace(key, unsigned(vertices.size()));
        if (added) vertices.emplace_back(float(x) * cellSize, float(y) * cellSize, float(z) * cellSize);
        return it->second;
    }
    // A unit square at corner p spanned by unit steps u and v, facing u x v.
    void square(Int3 p, Int3 u, Int3 v) {
        const unsigned a = corner(p.x, p.y, p.z);
        const unsigned b = corner(p.x + u.x, p.y + u.y, p.z + u.z);
        const unsigned c = corner(p.x + u.x + v.x, p.y + u.y + v.y, p.z + u.z + v.z);
        const unsigned d = corner(p.x + v.x, p.y + v.y, p.z + v.z);
        triangles.insert(triangles.end(), {a, b, c, a, c, d});
    }
};

} // namespace

void writeSurfaceMesh(const std::filesystem::path& file, const sandcore::Scene& scene, const ExportFrame& frame) {
    const char* formatId = assimpFormatOf(exportFormatOf(file));
    if (!formatId) throw FileError(file, "is not a mesh format (.obj, .stl or .glb)");
    requireWritableFileTarget(file);
    const VoxelVolume volume = sceneVoxels(scene);
    const Int3 s = volume.size;
    const auto filled = [&](int x, int y, int z) {
        if (x < 0 || y < 0 || z < 0 || x >= s.x || y >= s.y || z >= s.z) return false;
        return volume.index[std::size_t(x) + std::size_t(s.x) * (std::size_t(z) + std::size_t(s.z) * std::size_t(y))] != 0;
    };
    SurfaceBuilder builder{s, 1.0f, {}, {}, {}}; // world cells; placed by the frame below
    const Int3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};
    for (int y = 0; y < s.y; ++y)
        for (int z = 0; z < s.z; ++z)
            for (int x = 0; x < s.x; ++x) {
                if (!filled(x, y, z)) continue;
                // +a faces at the far side with (u, v) where u x v = a; -a faces at the near side, reversed.
                if (!filled(x + 1, y, z)) builder.square({x + 1, y, z}, Y, Z);
                if (!filled(x - 1, y, z)) builder.square({x, y, z}, Z, Y);
                if (!filled(x, y + 1, z)) builder.square({x, y + 1, z}, Z, X);
                if (!filled(x, y - 1, z)) builder.square({x, y, z}, X, Z);
                if (!filled(x, y, z + 1)) builder.square({x, y, z + 1}, X, Y);
                if (!filled(x, y, z - 1)) builder.square({x, y, z}, Y, X);
            }
    if (builder.triangles.empty()) throw FileError(file, "not written: the scene holds no sand to make a surface of");
    for (aiVector3D& v : builder.vertices) {
        const std::array<double, 3> p = exportedPoint(scene, frame, {v.x, v.y, v.z});
        v = aiVector3D(float(p[0]), float(p[1]), float(p[2]));
    }
    // Undoing a turn-over mirrors y, which would turn every face inside out.
    if (frame.model && scene.flipped())
        for (std::size_t t = 0; t < builder.triangles.size(); t += 3) std::swap(builder.triangles[t + 1], builder.triangles[t + 2]);

    // assimp's scene owns its arrays and frees them with delete[] / delete in its destructors,
    // so they are allocated the way it expects and handed over at once.
    auto sceneData = std::make_unique<aiScene>();
    sceneData->mRootNode = new aiNode("sand");
    sceneData->mRootNode->mNumMeshes = 1;
    sceneData->mRootNode->mMeshes = new unsigned[1]{0};
    sceneData->mNumMaterials = 1;
    sceneData->mMaterials = new aiMaterial*[1]{new aiMaterial()};
    aiString name("sand");
    sceneData->mMaterials[0]->AddProperty(&name, AI_MATKEY_NAME);
    sceneData->mNumMeshes = 1;
    sceneData->mMeshes = new aiMesh*[1]{new aiMesh()};
    aiMesh& mesh = *sceneData->mMeshes[0];
    mesh.mName = "sand surface";
    mesh.mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh.mMaterialIndex = 0;
    mesh.mNumVertices = unsigned(builder.vertices.size());
    mesh.mVertices = new aiVector3D[builder.vertices.size()];
    std::copy(builder.vertices.begin(), builder.vertices.end(), mesh.mVertices);
    mesh.mNumFaces = unsigned(builder.triangles.size() / 3);
    mesh.mFaces = new aiFace[mesh.mNumFaces];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        mesh.mFaces[f].mNumIndices = 3;
        mesh.mFaces[f].mIndices = new unsigned[3]{builder.triangles[3 * f], builder.triangles[3 * f + 1], builder.triangles[3 * f + 2]};
    }

    Assimp::Exporter exporter;
    const aiExportDataBlob* blob = exporter.ExportToBlob(sceneData.get(), formatId);
    if (!blob) throw FileError(file, std::string("the mesh exporter failed: ") + exporter.GetErrorString());
    writeFileAtomically(file, std::span<const std::uint8_t>(static_cast<const std::uint8_t*>(blob->data), blob->size));
}

} // namespace sandglass
