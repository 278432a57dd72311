#include "scene/model_parts.hpp"

#include "scene/mesh_loader.hpp"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

namespace sandglass {

const char* partRoleName(PartRole role) {
    switch (role) {
    case PartRole::Vessel: return "vessel";
    case PartRole::Frame: return "frame";
    case PartRole::Sand: return "sand";
    case PartRole::Static: return "static";
    }
    return "vessel";
}

PartRole parsePartRole(std::string_view name) {
    for (PartRole role : {PartRole::Vessel, PartRole::Frame, PartRole::Sand, PartRole::Static})
        if (name == partRoleName(role)) return role;
    throw std::invalid_argument("unknown part role '" + std::string(name) + "' (vessel, frame, sand or static)");
}

PartRoleChoice parsePartRoleChoice(std::string_view text) {
    const std::size_t equals = text.rfind('=');
    if (equals == std::string_view::npos || equals == 0)
        throw std::invalid_argument("--part takes NAME=ROLE, got '" + std::string(text) + "'");
    return {std::string(text.substr(0, equals)), parsePartRole(text.substr(equals + 1))};
}

namespace {

struct PartCollector {
    const aiScene& scene;
    const std::string& path;
    std::vector<ModelPart> parts;

    void visit(const aiNode& node, const aiMatrix4x4& parent) {
        const aiMatrix4x4 transform = parent * node.mTransformation;
        if (node.mNumMeshes > 0) {
            ModelPart part;
            part.name = node.mName.length > 0 ? node.mName.C_Str() : "";
            for (unsigned m = 0; m < node.mNumMeshes; ++m) {
                const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
                if (part.name.empty() && mesh.mName.length > 0) part.name = mesh.mName.C_Str();
                const auto base = std::uint32_t(part.mesh.vertices.size());
                for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
                    const aiVector3D p = transform * mesh.mVertices[v];
                    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                        throw ModelError(path, "vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
                    part.mesh.vertices.push_back({p.x, p.y, p.z});
                }
                for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
                    const aiFace& face = mesh.mFaces[f];
                    if (face.mNumIndices != 3) continue; // points and lines enclose nothing
                    part.mesh.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
                }
                aiColor4D diffuse;
                if (!part.hasColour && mesh.mMaterialIndex < scene.mNumMaterials &&
                    (scene.mMaterials[mesh.mMaterialIndex]->Get(AI_MATKEY_BASE_COLOR, diffuse) == AI_SUCCESS ||
                     scene.mMaterials[mesh.mMaterialIndex]->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS)) {
                    part.hasColour = true;
                    part.colour = {diffuse.r, diffuse.g, diffuse.b};
                }
            }
            if (!part.mesh.triangles.empty()) parts.push_back(std::move(part));
        }
        for (unsigned c = 0; c < node.mNumChildren; ++c) visit(*node.mChildren[c], transform);
    }
};

// Names as a user types them after --part: unique, never empty.
void nameUniquely(std::vector<ModelPart>& parts, const std::string& path) {
    std::map<std::string, int> seen;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        std::string& name = parts[i].name;
        if (name.empty() || name == "defaultobject" || name == "<STL_BINARY>" || name == "<STL_ASCII>")
            name = parts.size() == 1 ? std::filesystem::path(path).stem().string() : "part " + std::to_string(i + 1);
        const int count = ++seen[name];
        if (count > 1) name += " #" + std::to_string(count);
    }
}

std::string lowered(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

bool nameHasAny(const std::string& name, std::initializer_list<const char*> words) {
    const std::string low = lowered(name);
    return std::any_of(words.begin(), words.end(), [&](const char* w) { return low.find(w) != std::string::npos; });
}

} // namespace

std::vector<ModelPart> loadModelParts(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) throw ModelError(path, "no such file");
    if (std::filesystem::is_directory(path, error)) throw ModelError(path, "is a directory, not a model file");
    if (!std::ifstream(path).good()) throw ModelError(path, "cannot be read (permission denied?)");
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
    if (scene == nullptr) {
        std::string cause = importer.GetErrorString();
        if (cause.empty()) cause = "unknown import error";
        for (char& c : cause)
            if (c == '\n' || c == '\r') c = ' ';
        throw ModelError(path, "cannot be read as a model: " + cause);
    }
    PartCollector collector{*scene, path, {}};
    if (scene->mRootNode != nullptr) collector.visit(*scene->mRootNode, aiMatrix4x4());
    std::vector<ModelPart> parts = std::move(collector.parts);
    if (parts.empty()) throw ModelError(path, "contains no triangles (only points or lines, or nothing)");
    const sandcore::MeshBounds bounds = sandcore::boundsOf(mergedMesh(parts));
    const char* axes[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
        if (!(bounds.extent(a) > 0.0))
            throw ModelError(path, std::string("has zero extent along ") + axes[a] + " (a flat model encloses no volume)");
    nameUniquely(parts, path);
    for (ModelPart& part : parts) part.closed = sandcore::closednessOf(part.mesh).closed;
    return parts;
}

sandcore::TriangleMesh mergedMesh(const std::vector<ModelPart>& parts) {
    sandcore::TriangleMesh merged;
    for (const ModelPart& part : parts) merged.append(part.mesh);
    return merged;
}

void chooseRoles(std::vector<ModelPart>& parts, sandcore::SceneKind kind, const std::vector<PartRoleChoice>& choices) {
    if (kind == sandcore::SceneKind::Sculpture) {
        std::size_t sand = 0;
        for (std::size_t i = 0; i < parts.size(); ++i) {
            const bool better = parts[i].closed != parts[sand].closed ? parts[i].closed
                                                                      : parts[i].mesh.triangles.size() > parts[sand].mesh.triangles.size();
            if (better) sand = i;
        }
        const sandcore::MeshBounds all = sandcore::boundsOf(mergedMesh(parts));
        const sandcore::MeshBounds sandBounds = sandcore::boundsOf(parts[sand].mesh);
        for (std::size_t i = 0; i < parts.size(); ++i) {
            const sandcore::MeshBounds b = sandcore::boundsOf(parts[i].mesh);
            const bool onFloor = b.min[1] - all.min[1] <= 0.01 * all.extent(1);
            const bool low = b.max[1] <= sandBounds.min[1] + 0.25 * sandBounds.extent(1);
            const bool pedestal = nameHasAny(parts[i].name, {"base", "pedestal", "plinth", "stand"}) || (onFloor && low);
            parts[i].role = i != sand && pedestal ? PartRole::Static : PartRole::Sand;
        }
    } else {
        for (ModelPart& part : parts) {
            const bool glass = nameHasAny(part.name, {"glass", "vessel", "bulb"});
            const bool frame = nameHasAny(part.name, {"frame", "base", "cap", "plate", "pillar", "post", "stand", "rod", "wood"});
            part.role = frame && !glass ? PartRole::Frame : PartRole::Vessel;
        }
    }
    for (const PartRoleChoice& choice : choices) {
        auto it = std::find_if(parts.begin(), parts.end(), [&](const ModelPart& p) { return p.name == choice.name; });
        if (it == parts.end()) {
            std::string names;
            for (const ModelPart& p : parts) names += (names.empty() ? "" : ", ") + p.name;
            throw std::invalid_argument("--part: the model has no part '" + choice.name + "' (its parts: " + names + ")");
        }
        it->role = choice.role;
    }
}

std::vector<PartSummary> summarize(const std::vector<ModelPart>& parts) {
    std::vector<PartSummary> out;
    for (const ModelPart& p : parts) out.push_back({p.name, std::int64_t(p.mesh.triangles.size()), p.closed, p.role});
    return out;
}

} // namespace sandglass
