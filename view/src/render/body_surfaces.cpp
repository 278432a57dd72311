// SPDX-License-Identifier: MIT
#include "view/render/body_surfaces.hpp"

#include "view/render/shader_program.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <tuple>

namespace sandglass {

using sandcore::Int3;

namespace {

GLint uniform(const GlProgram& program, const char* name) { return glGetUniformLocation(program.get(), name); }

// Painted steel: apart from every sand palette, so the body reads against the heap it pushes.
constexpr std::array<float, 3> kBodyColour{0.34f, 0.44f, 0.58f};

struct CellOrder {
    bool operator()(const Int3& a, const Int3& b) const {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    }
};
using CellSet = std::set<Int3, CellOrder>;

bool inside(const CellSet& cells, Int3 c) { return cells.count(c) != 0; }

void addFace(std::vector<BodyVertex>& mesh, const CellSet& cells, Int3 c, int axis, int side, float cellSize) {
    // The face's own normal plus the direction from the cell to the free cells around it: edges
    // and a ball's staircase shade rounded, a flat face stays flat.
    glm::vec3 face(0.0f);
    face[axis] = float(side);
    glm::vec3 around(0.0f);
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if ((dx | dy | dz) != 0 && !inside(cells, {c.x + dx, c.y + dy, c.z + dz}))
                    around += glm::vec3(float(dx), float(dy), float(dz));
    const float length = glm::length(around);
    const glm::vec3 n = glm::normalize(length > 1e-4f && glm::dot(around, face) > 0.0f ? face + around / length : face);
    const std::array<int, 3> base{c.x, c.y, c.z};
    const float fixed = float(base[std::size_t(axis)] + (side > 0 ? 1 : 0));
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    auto corner = [&](int du, int dv) {
        std::array<float, 3> p{};
        p[std::size_t(axis)] = fixed;
        p[std::size_t(u)] = float(base[std::size_t(u)] + du);
        p[std::size_t(v)] = float(base[std::size_t(v)] + dv);
        return BodyVertex{p[0] * cellSize, p[1] * cellSize, p[2] * cellSize, n.x, n.y, n.z};
    };
    const BodyVertex a = corner(0, 0), b = corner(1, 0), d = corner(1, 1), e = corner(0, 1);
    mesh.insert(mesh.end(), {a, b, d, a, d, e});
}

} // namespace

std::vector<BodyVertex> buildBodyMesh(const sandcore::InsideMask& shape, int quarterTurns, float cellSize) {
    const std::vector<Int3> offsets = sandcore::bodyOffsets(shape, quarterTurns);
    const CellSet cells(offsets.begin(), offsets.end());
    std::vector<BodyVertex> mesh;
    for (const Int3& c : offsets)
        for (int axis = 0; axis < 3; ++axis)
            for (int side : {-1, +1}) {
                Int3 next = c;
                (axis == 0 ? next.x : axis == 1 ? next.y : next.z) += side;
                if (!inside(cells, next)) addFace(mesh, cells, c, axis, side, cellSize);
            }
    return mesh;
}

BodySurfaces::BodySurfaces(const std::filesystem::path& shaderFolder)
    : program_(loadShaderProgram(shaderFolder / "model.vert", shaderFolder / "model.frag")) {}

void BodySurfaces::update(const sandcore::Scene& scene, float cellSize) {
    const std::vector<sandcore::MovingBody>& bodies = scene.bodies();
    meshes_.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const sandcore::MovingBody& body = bodies[i];
        Mesh& mesh = meshes_[i];
        mesh.offset = glm::vec3(float(body.position.x), float(body.position.y), float(body.position.z)) * cellSize;
        const bool same = mesh.array.get() != 0 && mesh.quarterTurns == body.quarterTurns &&
                          mesh.shape.size.x == body.shape.size.x && mesh.shape.size.y == body.shape.size.y &&
                          mesh.shape.size.z == body.shape.size.z && mesh.shape.inside == body.shape.inside;
        if (same) continue;
        std::vector<BodyVertex> vertices = buildBodyMesh(body.shape, body.quarterTurns, cellSize);
        if (mesh.array.get() == 0) {
            mesh.array = GlVertexArray(newVertexArray());
            mesh.buffer = GlBuffer(newBuffer());
            glBindVertexArray(mesh.array.get());
            glBindBuffer(GL_ARRAY_BUFFER, mesh.buffer.get());
            const auto stride = GLsizei(sizeof(BodyVertex));
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(BodyVertex, x)));
            glEnableVertexAttribArray(1);
            glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(BodyVertex, nx)));
            glDisableVertexAttribArray(2); // one colour for the whole body, set per draw
            glBindVertexArray(0);
        }
        glBindBuffer(GL_ARRAY_BUFFER, mesh.buffer.get());
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(BodyVertex)), vertices.data(), GL_STATIC_DRAW);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        mesh.vertices = std::int64_t(vertices.size());
        mesh.shape = body.shape;
        mesh.quarterTurns = body.quarterTurns;
    }
}

void BodySurfaces::drawMeshes(const float* viewProjection) const {
    glUniformMatrix4fv(uniform(program_, "viewProjection"), 1, GL_FALSE, viewProjection);
    glVertexAttrib3f(2, kBodyColour[0], kBodyColour[1], kBodyColour[2]);
    for (const Mesh& mesh : meshes_) {
        if (mesh.vertices == 0) continue;
        glUniform3fv(uniform(program_, "offset"), 1, glm::value_ptr(mesh.offset));
        glBindVertexArray(mesh.array.get());
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(mesh.vertices));
    }
    glBindVertexArray(0);
}

void BodySurfaces::draw(const ModelLight& frame) const {
    if (meshes_.empty()) return;
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glUseProgram(program_.get());
    glUniform3fv(uniform(program_, "cameraPosition"), 1, glm::value_ptr(frame.eye));
    glUniform3fv(uniform(program_, "lightPosition"), 1, glm::value_ptr(frame.light));
    glUniform1i(uniform(program_, "glass"), 0);
    setLookUniforms(program_.get(), frame.look != nullptr ? *frame.look : StudioLook{});
    drawMeshes(frame.viewProjection);
}

void BodySurfaces::drawShadowCasters(const float* lightClip) const {
    if (meshes_.empty()) return;
    glUseProgram(program_.get());
    setLookUniforms(program_.get(), StudioLook{}); // reads no shadow map while drawing one
    drawMeshes(lightClip);
}

std::int64_t BodySurfaces::triangles() const {
    std::int64_t total = 0;
    for (const Mesh& mesh : meshes_) total += mesh.vertices / 3;
    return total;
}

} // namespace sandglass
