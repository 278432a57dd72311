// SPDX-License-Identifier: MIT
#include "scene/model_parts.hpp"

#include "checked_import.hpp"
#include "scene/mesh_loader.hpp"

#include "sandcore/mesh_shells.hpp"

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

// A word of the name, not any substring: "Capsule" is no cap, "Landscape" no sand. Words run
// between non-letters and at lower-to-upper case changes ("GlassTop" holds "glass").
bool nameHasAny(const std::string& name, std::initializer_list<const char*> words) {
    std::vector<std::string> parts(1);
    for (std::size_t i = 0; i < name.size(); ++i) {
        const auto c = static_cast<unsigned char>(name[i]);
        const bool startsWord = std::isupper(c) && i > 0 && std::islower(static_cast<unsigned char>(name[i - 1]));
        if (!std::isalpha(c) || startsWord) {
            if (!parts.back().empty()) parts.emplace_back();
            if (!std::isalpha(c)) continue;
        }
        parts.back().push_back(char(std::tolower(c)));
    }
    for (const std::string& part : parts)
        for (const char* w : words) {
            const std::string word = w;
            // A plural or a number after it still names it: "plates", "post2".
            if (part == word || part == word + "s" || part == word + "es") return true;
        }
    return false;
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
    // W1: every connected shell is a part of its own, named after its object.
    std::vector<ModelPart> shells;
    for (ModelPart& object : parts) {
        std::vector<sandcore::TriangleMesh> pieces = sandcore::splitIntoShells(object.mesh);
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            ModelPart shell;
            shell.object = object.name;
            shell.name = pieces.size() == 1 ? object.name : object.name + " #" + std::to_string(k + 1);
            shell.mesh = std::move(pieces[k]);
            shell.hasColour = object.hasColour;
            shell.colour = object.colour;
            shell.closed = sandcore::closednessOf(shell.mesh).closed;
            shell.fileCentre = checked.centre;
            shells.push_back(std::move(shell));
        }
    }
    return shells;
}

sandcore::TriangleMesh mergedMesh(const std::vector<ModelPart>& parts) {
    sandcore::TriangleMesh merged;
    for (const ModelPart& part : parts) merged.append(part.mesh);
    return merged;
}

namespace {

// The sculpture's roles, decided for whole objects: the shells of a character (body, head, feet)
// are one figure, not a figure on a pedestal of its own feet.
void chooseSculptureRoles(std::vector<ModelPart>& parts) {
    std::vector<std::string> objects;
    std::vector<sandcore::TriangleMesh> meshes;
    std::vector<bool> closed;
    for (const ModelPart& part : parts) {
        auto it = std::find(objects.begin(), objects.end(), part.object);
        if (it == objects.end()) {
            objects.push_back(part.object);
            meshes.emplace_back();
            closed.push_back(true);
            it = objects.end() - 1;
        }
        const auto o = std::size_t(it - objects.begin());
        meshes[o].append(part.mesh);
        closed[o] = closed[o] && part.closed;
    }
    std::size_t sand = 0;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const bool better = closed[i] != closed[sand] ? bool(closed[i]) : meshes[i].triangles.size() > meshes[sand].triangles.size();
        if (better) sand = i;
    }
    const sandcore::MeshBounds all = sandcore::boundsOf(mergedMesh(parts));
    const sandcore::MeshBounds sandBounds = sandcore::boundsOf(meshes[sand]);
    std::vector<PartRole> roleOf(objects.size());
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const sandcore::MeshBounds b = sandcore::boundsOf(meshes[i]);
        const bool onFloor = b.min[1] - all.min[1] <= 0.01 * all.extent(1);
        const bool low = b.max[1] <= sandBounds.min[1] + 0.25 * sandBounds.extent(1);
        const bool pedestal = nameHasAny(objects[i], {"base", "pedestal", "plinth", "stand"}) || (onFloor && low);
        roleOf[i] = i != sand && pedestal ? PartRole::Static : PartRole::Sand;
    }
    for (ModelPart& part : parts) {
        part.role = roleOf[std::size_t(std::find(objects.begin(), objects.end(), part.object) - objects.begin())];
        part.roleFixed = true;
    }
}

// A name is a hint the role keeps only for an object of one shell: an object "Glass" of several
// shells may hold its posts or its sand too, and the sand-space search sorts them.
void chooseHourglassRoles(std::vector<ModelPart>& parts) {
    std::map<std::string, int> shellsOf;
    for (const ModelPart& part : parts) ++shellsOf[part.object];
    for (ModelPart& part : parts) {
        // "hourglass", "sandglass", "sand timer" and "Sanduhr" name the whole model, not its glass
        // or its sand: as whole words they match no hint below.
        const std::string& name = part.object;
        const bool glass = nameHasAny(name, {"glass", "vessel", "bulb"});
        const bool frame = nameHasAny(name, {"frame", "base", "cap", "plate", "pillar", "post", "stand", "rod", "wood"});
        const bool sand = nameHasAny(name, {"sand"}) && !glass && !nameHasAny(name, {"timer", "clock", "uhr"});
        part.role = sand ? PartRole::Sand : frame && !glass ? PartRole::Frame : PartRole::Vessel;
        part.roleFixed = sand || ((glass || frame) && shellsOf[part.object] == 1);
    }
}

} // namespace

void chooseRoles(std::vector<ModelPart>& parts, sandcore::SceneKind kind, const std::vector<PartRoleChoice>& choices) {
    if (kind == sandcore::SceneKind::Sculpture) chooseSculptureRoles(parts);
    else chooseHourglassRoles(parts);
    for (const PartRoleChoice& choice : choices) {
        bool found = false;
        for (ModelPart& part : parts)
            if (part.name == choice.name || part.object == choice.name) {
                part.role = choice.role;
                part.roleFixed = true;
                found = true;
            }
        if (!found) {
            std::string names;
            for (const ModelPart& p : parts) names += (names.empty() ? "" : ", ") + p.name;
            throw std::invalid_argument("--part: the model has no part '" + choice.name + "' (its parts: " + names + ")");
        }
    }
}

std::vector<PartSummary> summarize(const std::vector<ModelPart>& parts) {
    std::vector<PartSummary> out;
    for (const ModelPart& p : parts) out.push_back({p.name, std::int64_t(p.mesh.triangles.size()), p.closed, p.role});
    return out;
}

} // namespace sandglass
