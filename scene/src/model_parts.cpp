#include "scene/model_parts.hpp"

#include "checked_import.hpp"
#include "scene/mesh_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <unordered_map>

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

std::vector<ModelPart> loadModelParts(const std::string& path, const MeshLoadOptions& options) {
    // The same child process and checks as loadMesh: no model is read by assimp in this process.
    const CheckedImport checked = importChecked(path, options);
    const ImportedTriangles& imported = checked.imported;
    std::vector<ModelPart> parts;
    std::size_t next = 0;
    for (const ImportedPart& piece : imported.parts) {
        ModelPart part;
        part.name = piece.name;
        part.hasColour = piece.hasColour;
        part.colour = piece.colour;
        // The part's own vertices, in the order its triangles first use them.
        std::unordered_map<std::uint32_t, std::uint32_t> local;
        for (std::size_t t = next; t < next + std::size_t(piece.triangleCount); ++t) {
            std::array<std::uint32_t, 3> triangle{};
            for (std::size_t c = 0; c < 3; ++c) {
                const std::uint32_t global = imported.triangles[t][c];
                const auto [it, added] = local.emplace(global, std::uint32_t(part.mesh.vertices.size()));
                if (added) part.mesh.vertices.push_back(checked.centred(global));
                triangle[c] = it->second;
            }
            part.mesh.triangles.push_back(triangle);
        }
        next += std::size_t(piece.triangleCount);
        part.mesh = sandcore::weldVertices(part.mesh);
        parts.push_back(std::move(part));
    }
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
