// SPDX-License-Identifier: MIT
#include "view/paint/column_picker.hpp"

#include "view/render/shader_program.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sandglass {

ColumnPicker::ColumnPicker(const std::filesystem::path& shaderFolder)
    : program_(loadShaderProgram(shaderFolder / "pick.vert", shaderFolder / "pick.frag")),
      emptyArray_(newVertexArray()), framebuffer_(newFramebuffer()), idTexture_(newTexture()),
      depth_(newRenderbuffer()) {}

void ColumnPicker::resizeTarget(int width, int height) {
    if (width == targetWidth_ && height == targetHeight_) return;
    glBindTexture(GL_TEXTURE_2D, idTexture_.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, width, height, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, idTexture_.get(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("cannot make a " + std::to_string(width) + "x" + std::to_string(height) +
                                 " integer picking target");
    targetWidth_ = width;
    targetHeight_ = height;
}

void ColumnPicker::drawIds(const PickView& view) {
    GLint previousFramebuffer = 0, previousViewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    glGetIntegerv(GL_VIEWPORT, previousViewport);
    resizeTarget(view.width, view.height);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, view.width, view.height);
    const GLuint nothing[4] = {0, 0, 0, 0};
    glClearBufferuiv(GL_COLOR, 0, nothing);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);

    const CanvasSurface& s = view.surface;
    const glm::mat4 viewProjection = view.projection * view.view;
    const GLuint program = program_.get();
    glUseProgram(program);
    glUniformMatrix4fv(glGetUniformLocation(program, "viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    glUniform1i(glGetUniformLocation(program, "columnsX"), s.columnsX);
    glUniform3f(glGetUniformLocation(program, "origin"), s.originX, s.y, s.originZ);
    glUniform1f(glGetUniformLocation(program, "cellSize"), s.cellSize);
    glBindVertexArray(emptyArray_.get());
    glDrawArraysInstanced(GL_TRIANGLES, 0, 6, GLsizei(s.columnsX) * GLsizei(s.columnsZ));
    glBindVertexArray(0);
    glUseProgram(0);

    // The one read-back of this view; every later lookup reads this array.
    ids_.resize(std::size_t(view.width) * std::size_t(view.height));
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, view.width, view.height, GL_RED_INTEGER, GL_UNSIGNED_INT, ids_.data());
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFramebuffer));
    glViewport(previousViewport[0], previousViewport[1], previousViewport[2], previousViewport[3]);
    ++redraws_;
}

void ColumnPicker::prepare(const PickView& view) {
    if (cached_ && *cached_ == view) return;
    if (view.width <= 0 || view.height <= 0 || view.surface.columnsX <= 0 || view.surface.columnsZ <= 0) {
        ids_.clear();
        cached_ = view;
        return;
    }
    drawIds(view);
    cached_ = view;
}

std::optional<CanvasColumn> ColumnPicker::columnAt(int pixelX, int pixelY) const {
    if (!cached_ || ids_.empty()) return std::nullopt;
    const int width = cached_->width, height = cached_->height;
    if (pixelX < 0 || pixelY < 0 || pixelX >= width || pixelY >= height) return std::nullopt;
    const std::uint32_t id = ids_[std::size_t(height - 1 - pixelY) * std::size_t(width) + std::size_t(pixelX)];
    if (id == 0) return std::nullopt;
    const int columnsX = cached_->surface.columnsX;
    const int column = int(id - 1);
    return CanvasColumn{column % columnsX, column / columnsX};
}

void cursorToFramebuffer(double cursorX, double cursorY, int windowWidth, int windowHeight, int framebufferWidth,
                         int framebufferHeight, int& pixelX, int& pixelY) {
    const double scaleX = windowWidth > 0 ? double(framebufferWidth) / double(windowWidth) : 1.0;
    const double scaleY = windowHeight > 0 ? double(framebufferHeight) / double(windowHeight) : 1.0;
    pixelX = int(std::floor(cursorX * scaleX));
    pixelY = int(std::floor(cursorY * scaleY));
}

} // namespace sandglass
