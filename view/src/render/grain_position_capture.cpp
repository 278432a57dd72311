// SPDX-License-Identifier: MIT
// SceneRenderer::captureGpuPositions: the GPU path's display positions read back through
// transform feedback, so tests can hold them against sandcore::writeDisplayPositions (R8, V8).
#include "view/render/scene_renderer.hpp"

namespace sandglass {

std::vector<sandcore::Vec3> SceneRenderer::captureGpuPositions(const sandcore::Scene& scene, float stepFraction,
                                                               const RenderSettings& settings) {
    const GrainPath path = path_;
    path_ = GrainPath::GpuInterpolated;
    uploadGrains(scene, stepFraction, settings);
    path_ = path;
    // The upload above took the owner's change lists; the other path must not miss them.
    if (path != GrainPath::GpuInterpolated) sceneChanged();
    return readBackGpuPositions(scene, stepFraction, settings);
}

std::vector<sandcore::Vec3> SceneRenderer::readBackGpuPositions(const sandcore::Scene& scene, float stepFraction,
                                                                const RenderSettings& settings) const {
    const std::int64_t count = gpuStore_.grainCount();
    std::vector<sandcore::Vec3> positions(static_cast<std::size_t>(count));
    if (count == 0) return positions;

    GlBuffer captured(newBuffer());
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, captured.get());
    glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(std::size_t(count) * sizeof(sandcore::Vec3)), nullptr,
                 GL_STREAM_READ);
    glUseProgram(grainGpuProgram_.get());
    RenderSettings everyGrain = settings;
    everyGrain.innerGrains = true; // a hidden grain still has a position
    setGpuUniforms(scene, stepFraction, everyGrain);
    glUniform1i(glGetUniformLocation(grainGpuProgram_.get(), "mode"), 0); // points: one vertex per grain
    glUniform1f(glGetUniformLocation(grainGpuProgram_.get(), "cellSize"), settings.cellSize); // setGpuUniforms bound the grains
    glEnable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captured.get());
    glBeginTransformFeedback(GL_POINTS);
    glDrawArraysInstanced(GL_POINTS, 0, 1, GLsizei(count));
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);
    glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(positions.size() * sizeof(sandcore::Vec3)),
                       positions.data());
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
    glBindVertexArray(0);
    glUseProgram(0);
    return positions;
}

} // namespace sandglass
