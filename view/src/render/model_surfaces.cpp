// SPDX-License-Identifier: MIT
#include "view/render/model_surfaces.hpp"

#include "view/render/shader_program.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>
#include <numeric>

namespace sandglass {

namespace {

GLint uniform(const GlProgram& program, const char* name) { return glGetUniformLocation(program.get(), name); }

} // namespace

ModelSurfaces::ModelSurfaces(const std::filesystem::path& shaderFolder)
    : program_(loadShaderProgram(shaderFolder / "model.vert", shaderFolder / "model.frag")),
      opaqueArray_(newVertexArray()), glassArray_(newVertexArray()), opaqueBuffer_(newBuffer()),
      glassBuffer_(newBuffer()), glassOrder_(newBuffer()) {
    const auto stride = GLsizei(sizeof(GpuVertex));
    for (auto [array, buffer] : {std::pair{opaqueArray_.get(), opaqueBuffer_.get()}, std::pair{glassArray_.get(), glassBuffer_.get()}}) {
        glBindVertexArray(array);
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(GpuVertex, x)));
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(GpuVertex, nx)));
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(GpuVertex, r)));
    }
    glBindVertexArray(glassArray_.get());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, glassOrder_.get()); // kept by the vertex array
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void ModelSurfaces::set(const ModelDrawing* drawing, bool turnedOver, float cellSize) {
    std::vector<GpuVertex> opaque, glass;
    glassTriangles_.clear();
    if (drawing != nullptr)
        for (const DrawnPart& part : drawing->parts) {
            std::vector<GpuVertex>& into = part.look == PartLook::Glass ? glass : opaque;
            for (const ModelVertex& v : part.vertices) {
                // Turned over, the sand is mirrored in y within the grids' height (sandcore's flip).
                const float y = turnedOver ? drawing->heightCells - v.y : v.y;
                into.push_back({v.x * cellSize, y * cellSize, v.z * cellSize, v.nx, turnedOver ? -v.ny : v.ny, v.nz,
                                part.colour[0], part.colour[1], part.colour[2]});
            }
        }
    for (std::size_t t = 0; t + 2 < glass.size(); t += 3)
        glassTriangles_.push_back((glm::vec3(glass[t].x, glass[t].y, glass[t].z) +
                                   glm::vec3(glass[t + 1].x, glass[t + 1].y, glass[t + 1].z) +
                                   glm::vec3(glass[t + 2].x, glass[t + 2].y, glass[t + 2].z)) / 3.0f);
    glBindBuffer(GL_ARRAY_BUFFER, opaqueBuffer_.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(opaque.size() * sizeof(GpuVertex)), opaque.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, glassBuffer_.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(glass.size() * sizeof(GpuVertex)), glass.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    opaqueVertices_ = std::int64_t(opaque.size());
    bounds_ = WorldBox{glm::vec3(1e30f), glm::vec3(-1e30f)};
    for (const std::vector<GpuVertex>* vertices : {&opaque, &glass})
        for (const GpuVertex& v : *vertices) {
            bounds_.min = glm::min(bounds_.min, glm::vec3(v.x, v.y, v.z));
            bounds_.max = glm::max(bounds_.max, glm::vec3(v.x, v.y, v.z));
        }
    if (opaque.empty() && glass.empty()) bounds_ = WorldBox{};
    sortedFor_ = glm::vec3(1e30f); // the next glass draw sorts
}

void ModelSurfaces::sortGlass(const glm::vec3& eye) {
    // Triangles back to front by their centroid's distance from the eye: the far wall first,
    // the near one last, the inner surface of a wall before its outer one.
    std::vector<std::uint32_t> triangles(glassTriangles_.size());
    std::iota(triangles.begin(), triangles.end(), 0u);
    std::vector<float> distance(glassTriangles_.size());
    for (std::size_t t = 0; t < glassTriangles_.size(); ++t) {
        const glm::vec3 d = glassTriangles_[t] - eye;
        distance[t] = glm::dot(d, d);
    }
    std::sort(triangles.begin(), triangles.end(), [&](std::uint32_t a, std::uint32_t b) { return distance[a] > distance[b]; });
    order_.resize(3 * triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i)
        for (std::uint32_t k = 0; k < 3; ++k) order_[3 * i + k] = 3 * triangles[i] + k;
    glBindVertexArray(glassArray_.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(order_.size() * sizeof(std::uint32_t)), order_.data(), GL_STREAM_DRAW);
    glBindVertexArray(0);
    sortedFor_ = eye;
}

void ModelSurfaces::useProgram(const ModelLight& frame, bool glass) const {
    glUseProgram(program_.get());
    glUniformMatrix4fv(uniform(program_, "viewProjection"), 1, GL_FALSE, frame.viewProjection);
    glUniform3fv(uniform(program_, "cameraPosition"), 1, glm::value_ptr(frame.eye));
    glUniform3fv(uniform(program_, "lightPosition"), 1, glm::value_ptr(frame.light));
    glUniform1i(uniform(program_, "glass"), glass ? 1 : 0);
    setLookUniforms(program_.get(), frame.look != nullptr ? *frame.look : StudioLook{});
}

void ModelSurfaces::drawShadowCasters(const float* lightClip) {
    if (opaqueVertices_ == 0) return;
    glUseProgram(program_.get());
    glUniformMatrix4fv(uniform(program_, "viewProjection"), 1, GL_FALSE, lightClip);
    setLookUniforms(program_.get(), StudioLook{}); // reads no shadow map while drawing one
    glBindVertexArray(opaqueArray_.get());
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(opaqueVertices_));
    glBindVertexArray(0);
}

void ModelSurfaces::drawOpaque(const ModelLight& frame) {
    if (opaqueVertices_ == 0) return;
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    useProgram(frame, false);
    glBindVertexArray(opaqueArray_.get());
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(opaqueVertices_));
    glBindVertexArray(0);
}

void ModelSurfaces::sortGlassFor(const glm::vec3& eye) {
    if (glm::distance(eye, sortedFor_) > 1e-4f * std::max(1.0f, glm::length(eye))) sortGlass(eye);
}

void ModelSurfaces::drawGlass(const ModelLight& frame) {
    if (glassTriangles_.empty()) return;
    sortGlassFor(frame.eye);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE); // glass never hides what lies behind it
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    useProgram(frame, true);
    glUniform1i(uniform(program_, "blackBackground"), frame.blackBackground ? 1 : 0);
    glBindVertexArray(glassArray_.get());
    glDrawElements(GL_TRIANGLES, GLsizei(order_.size()), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

} // namespace sandglass
