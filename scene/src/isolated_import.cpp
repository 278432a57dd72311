// SPDX-License-Identifier: MIT
// The import itself (assimp, in the child: importInThisProcess) and the wire format of its reply.
// Starting the child and reading the reply: import_in_child_process.cpp.

#include "isolated_import.hpp"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace sandglass {

namespace {

constexpr char kMagic[4] = {'S', 'G', 'T', 'L'};

using Matrix = std::array<double, 16>; // row-major 4x4, as aiMatrix4x4

Matrix toDouble(const aiMatrix4x4& m) {
    return {m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4};
}

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k) sum += a[std::size_t(4 * i + k)] * b[std::size_t(4 * k + j)];
            r[std::size_t(4 * i + j)] = sum;
        }
    return r;
}

// Node transforms are composed and applied in double: a model far from the origin keeps what
// precision the file gave it.
void appendNode(const aiScene& scene, const aiNode& node, const Matrix& parent, ImportedTriangles& out, int depth) {
    if (depth > 1000) throw std::runtime_error("the node hierarchy is deeper than 1000 levels");
    const Matrix transform = multiply(parent, toDouble(node.mTransformation));
    // S7: a node with meshes is one part, named after the node (or its first named mesh).
    ImportedPart part;
    part.name = node.mName.C_Str();
    const std::size_t firstTriangle = out.triangles.size();
    for (unsigned m = 0; m < node.mNumMeshes; ++m) {
        if (node.mMeshes == nullptr || node.mMeshes[m] >= scene.mNumMeshes || scene.mMeshes == nullptr ||
            scene.mMeshes[node.mMeshes[m]] == nullptr)
            throw std::runtime_error("a node refers to a missing mesh");
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
        if (part.name.empty()) part.name = mesh.mName.C_Str();
        aiColor4D diffuse;
        if (!part.hasColour && mesh.mMaterialIndex < scene.mNumMaterials && scene.mMaterials != nullptr &&
            scene.mMaterials[mesh.mMaterialIndex] != nullptr &&
            (scene.mMaterials[mesh.mMaterialIndex]->Get(AI_MATKEY_BASE_COLOR, diffuse) == AI_SUCCESS ||
             scene.mMaterials[mesh.mMaterialIndex]->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS) &&
            std::isfinite(diffuse.r) && std::isfinite(diffuse.g) && std::isfinite(diffuse.b)) {
            part.hasColour = true;
            part.colour = {std::clamp(float(diffuse.r), 0.0f, 1.0f), std::clamp(float(diffuse.g), 0.0f, 1.0f),
                           std::clamp(float(diffuse.b), 0.0f, 1.0f)};
        }
        if (mesh.mNumVertices > 0 && mesh.mVertices == nullptr) throw std::runtime_error("a mesh has no positions");
        const std::size_t base = out.vertices.size();
        if (base + mesh.mNumVertices > 0xffffffffull) throw std::runtime_error("more than 2^32 vertices");
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const double p[3] = {mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z};
            std::array<double, 3> world{};
            for (std::size_t r = 0; r < 3; ++r)
                world[r] = transform[4 * r] * p[0] + transform[4 * r + 1] * p[1] + transform[4 * r + 2] * p[2] +
                           transform[4 * r + 3];
            out.vertices.push_back(world);
        }
        for (unsigned f = 0; f < mesh.mNumFaces && mesh.mFaces != nullptr; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3 || face.mIndices == nullptr) continue; // points and lines enclose nothing
            std::array<std::uint32_t, 3> t{};
            for (std::size_t i = 0; i < 3; ++i) {
                if (face.mIndices[i] >= mesh.mNumVertices) throw std::runtime_error("a face refers to a missing vertex");
                t[i] = std::uint32_t(base + face.mIndices[i]);
            }
            out.triangles.push_back(t);
        }
    }
    part.triangleCount = out.triangles.size() - firstTriangle;
    if (part.triangleCount > 0) out.parts.push_back(std::move(part));
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        if (node.mChildren != nullptr && node.mChildren[c] != nullptr)
            appendNode(scene, *node.mChildren[c], transform, out, depth + 1);
}

std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

// assimp's PLY reader loops forever when a binary file ends inside its header; a PLY file
// whose header has no end_header line is refused before assimp sees it.
std::string plyHeaderProblem(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return {};
    std::string head(64 * 1024, '\0');
    std::size_t got = 0;
    while (got < head.size()) {
        const ssize_t n = ::read(fd, head.data() + got, head.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += std::size_t(n);
    }
    ::close(fd);
    head.resize(got);
    if (head.rfind("ply", 0) != 0) return {};
    if (head.find("end_header") == std::string::npos) return "the PLY header has no end_header line (truncated or corrupt)";
    return {};
}

void put(std::vector<std::uint8_t>& out, const void* data, std::size_t size) {
    if (size == 0) return;
    const std::size_t at = out.size();
    out.resize(at + size);
    std::memcpy(out.data() + at, data, size);
}

} // namespace

ImportedTriangles importInThisProcess(const std::string& path) {
    ImportedTriangles out;
    if (std::string problem = plyHeaderProblem(path); !problem.empty()) {
        out.error = problem;
        return out;
    }
    try {
        Assimp::Importer importer;
        // No aiProcess_JoinIdenticalVertices: its epsilon merges distinct vertices of a model at
        // millimetre scale; loadMesh joins bit-identical positions only.
        const aiScene* scene = importer.ReadFile(
            path, aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_SortByPType);
        if (scene == nullptr) {
            std::string cause = oneLine(importer.GetErrorString());
            out.error = "cannot be read as a model: " + (cause.empty() ? std::string("unknown import error") : cause);
            return out;
        }
        if (scene->mRootNode != nullptr) appendNode(*scene, *scene->mRootNode, toDouble(aiMatrix4x4()), out, 0);
    } catch (const std::exception& e) {
        out = {};
        out.error = "cannot be read as a model: " + oneLine(e.what());
    }
    return out;
}

std::vector<std::uint8_t> encodeImport(const ImportedTriangles& imported) {
    std::vector<std::uint8_t> out;
    // Room for the whole reply first (also keeps GCC 12 from a false -Wstringop-overflow).
    std::size_t names = 0;
    for (const ImportedPart& part : imported.parts) names += part.name.size();
    out.reserve(5 + 8 + imported.error.size() + 24 + imported.vertices.size() * 24 + imported.triangles.size() * 12 +
                imported.parts.size() * 29 + names);
    put(out, kMagic, sizeof kMagic);
    const std::uint8_t failed = imported.error.empty() ? 0 : 1;
    put(out, &failed, 1);
    if (failed) {
        const auto length = std::uint64_t(imported.error.size());
        put(out, &length, sizeof length);
        put(out, imported.error.data(), imported.error.size());
        return out;
    }
    const auto vertexCount = std::uint64_t(imported.vertices.size());
    const auto triangleCount = std::uint64_t(imported.triangles.size());
    put(out, &vertexCount, sizeof vertexCount);
    put(out, imported.vertices.data(), imported.vertices.size() * sizeof(imported.vertices[0]));
    put(out, &triangleCount, sizeof triangleCount);
    put(out, imported.triangles.data(), imported.triangles.size() * sizeof(imported.triangles[0]));
    const auto partCount = std::uint64_t(imported.parts.size());
    put(out, &partCount, sizeof partCount);
    for (const ImportedPart& part : imported.parts) {
        const auto nameLength = std::uint64_t(part.name.size());
        put(out, &nameLength, sizeof nameLength);
        put(out, part.name.data(), part.name.size());
        put(out, &part.triangleCount, sizeof part.triangleCount);
        const std::uint8_t hasColour = part.hasColour ? 1 : 0;
        put(out, &hasColour, 1);
        put(out, part.colour.data(), sizeof part.colour);
    }
    return out;
}

ImportedTriangles decodeImport(std::span<const std::uint8_t> bytes) {
    ImportedTriangles out;
    std::size_t at = 0;
    auto take = [&](void* into, std::size_t size) {
        if (bytes.size() - at < size) return false;
        if (size == 0) return true; // an empty vector's data() may be null: memcpy must not see it
        std::memcpy(into, bytes.data() + at, size);
        at += size;
        return true;
    };
    char magic[4];
    std::uint8_t failed = 0;
    if (!take(magic, 4) || std::memcmp(magic, kMagic, 4) != 0 || !take(&failed, 1)) {
        out.error = "the model importer gave no answer";
        return out;
    }
    std::uint64_t count = 0;
    if (failed) {
        if (!take(&count, sizeof count) || count > bytes.size() - at) {
            out.error = "the model importer failed";
            return out;
        }
        out.error = oneLine(std::string(reinterpret_cast<const char*>(bytes.data() + at), std::size_t(count)));
        if (out.error.empty()) out.error = "the model importer failed";
        return out;
    }
    const char* const garbled = "the model importer's answer is incomplete";
    if (!take(&count, sizeof count) || count > (bytes.size() - at) / 24) {
        out.error = garbled;
        return out;
    }
    out.vertices.resize(std::size_t(count));
    take(out.vertices.data(), out.vertices.size() * 24);
    auto fail = [&] {
        out = {};
        out.error = garbled;
        return out;
    };
    if (!take(&count, sizeof count) || count > (bytes.size() - at) / 12) return fail();
    out.triangles.resize(std::size_t(count));
    take(out.triangles.data(), out.triangles.size() * 12);
    for (const auto& t : out.triangles)
        for (std::uint32_t i : t)
            if (i >= out.vertices.size()) return fail();
    // The parts: each at least 8 + 8 + 1 + 12 bytes, their triangles adding up to all of them.
    if (!take(&count, sizeof count) || count > (bytes.size() - at) / 29) return fail();
    out.parts.resize(std::size_t(count));
    std::uint64_t covered = 0;
    for (ImportedPart& part : out.parts) {
        std::uint64_t nameLength = 0;
        if (!take(&nameLength, sizeof nameLength) || nameLength > bytes.size() - at) return fail();
        part.name.assign(reinterpret_cast<const char*>(bytes.data() + at), std::size_t(nameLength));
        at += std::size_t(nameLength);
        std::uint8_t hasColour = 0;
        if (!take(&part.triangleCount, sizeof part.triangleCount) || !take(&hasColour, 1) ||
            !take(part.colour.data(), sizeof part.colour))
            return fail();
        part.hasColour = hasColour != 0;
        for (float& channel : part.colour)
            if (!(channel >= 0.0f && channel <= 1.0f)) return fail();
        if (part.triangleCount > out.triangles.size() - covered) return fail();
        covered += part.triangleCount;
    }
    if (covered != out.triangles.size() || at != bytes.size()) return fail();
    return out;
}

} // namespace sandglass
