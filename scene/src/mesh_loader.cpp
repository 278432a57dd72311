#include "scene/mesh_loader.hpp"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace sandglass {

namespace {

void appendNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, sandcore::TriangleMesh& out,
                const std::string& path) {
    const aiMatrix4x4 transform = parent * node.mTransformation;
    for (unsigned m = 0; m < node.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
        const auto base = std::uint32_t(out.vertices.size());
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D p = transform * mesh.mVertices[v];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw ModelError(path, "vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
            out.vertices.push_back({p.x, p.y, p.z});
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) continue; // points and lines enclose nothing
            out.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
        }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) appendNode(scene, *node.mChildren[c], transform, out, path);
}

} // namespace

sandcore::TriangleMesh loadMesh(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) throw ModelError(path, "no such file");
    if (std::filesystem::is_directory(path, error)) throw ModelError(path, "is a directory, not a model file");
    if (!std::ifstream(path).good()) throw ModelError(path, "cannot be read (permission denied?)");

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(
        path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
    if (scene == nullptr) {
        std::string cause = importer.GetErrorString();
        if (cause.empty()) cause = "unknown import error";
        // assimp's messages can span lines; the CLI promises one.
        for (char& c : cause)
            if (c == '\n' || c == '\r') c = ' ';
        throw ModelError(path, "cannot be read as a model: " + cause);
    }
    sandcore::TriangleMesh mesh;
    if (scene->mRootNode != nullptr) appendNode(*scene, *scene->mRootNode, aiMatrix4x4(), mesh, path);
    if (mesh.triangles.empty()) throw ModelError(path, "contains no triangles (only points or lines, or nothing)");
    const sandcore::MeshBounds bounds = sandcore::boundsOf(mesh);
    const char* axes[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
        if (!(bounds.extent(a) > 0.0)) throw ModelError(path, std::string("has zero extent along ") + axes[a] + " (a flat model encloses no volume)");
    return mesh;
}

} // namespace sandglass
