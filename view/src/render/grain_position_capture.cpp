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
    RenderSettings everyGrain = settings;
    everyGrain.innerGrains = true; // a hidden grain still has a position
    const std::int64_t count = runGrainPass(scene, stepFraction, everyGrain);
    std::vector<sandcore::Vec3> positions(static_cast<std::size_t>(count));
    if (count > 0) {
        // The pass keeps x, y, z and a fourth float per grain.
        std::vector<float> captured(static_cast<std::size_t>(count) * 4);
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, passCentres_.get());
        glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(captured.size() * sizeof(float)), captured.data());
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
        for (std::size_t i = 0; i < positions.size(); ++i)
            positions[i] = {captured[4 * i], captured[4 * i + 1], captured[4 * i + 2]};
    }
    glBindVertexArray(0);
    glUseProgram(0);
    return positions;
}

} // namespace sandglass
