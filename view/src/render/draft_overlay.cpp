// SPDX-License-Identifier: MIT
#include "view/render/draft_overlay.hpp"

#include "view/render/shader_program.hpp"

namespace sandglass {

DraftOverlay::DraftOverlay(const std::filesystem::path& shaderFolder)
    : program_(loadShaderProgram(shaderFolder / "draft.vert", shaderFolder / "draft.frag")),
      emptyArray_(newVertexArray()), texture_(newTexture()) {}

void DraftOverlay::setImage(const DraftImage& image) {
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Rows from the top go in as they are: texture row 0 (t = 0) is the image's top row, which
    // DraftImage::colorAt puts at z = 0, so what is shown is what "colour from draft" pours.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width(), image.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image.rgba().data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    hasImage_ = true;
}

void DraftOverlay::draw(const DraftPlacement& placement, const float* viewProjection) const {
    if (!placement.visible || !hasImage_) return;
    const CanvasSurface& s = placement.surface;
    const GLuint program = program_.get();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glUseProgram(program);
    glUniformMatrix4fv(glGetUniformLocation(program, "viewProjection"), 1, GL_FALSE, viewProjection);
    glUniform3f(glGetUniformLocation(program, "origin"), s.originX, s.y, s.originZ);
    glUniform2f(glGetUniformLocation(program, "extent"), float(s.columnsX) * s.cellSize,
                float(s.columnsZ) * s.cellSize);
    glUniform1f(glGetUniformLocation(program, "opacity"), placement.opacity);
    glUniform1i(glGetUniformLocation(program, "draft"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    glBindVertexArray(emptyArray_.get());
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

} // namespace sandglass
