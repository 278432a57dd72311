// SPDX-License-Identifier: MIT
#include "view/render/studio_look.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace sandglass {

StudioLook studioLookFor(const RenderSettings& settings, float cellSize) {
    StudioLook look;
    look.studio = studioLights(settings);
    look.toneMapping = look.studio && settings.toneMapping;
    look.environment = look.studio && settings.glassEnvironment;
    look.shadows = keyShadows(settings);
    // The default camera looks from yaw 0.6, pitch 0.35: the key comes from its left and in front,
    // 35 degrees up, so it reaches under a frame's top plate into the upper bulb; the fill comes
    // low from its right.
    look.keyDirection = glm::normalize(glm::vec3(-0.35f, 0.57f, 0.74f));
    look.keyColor = glm::vec3(1.40f, 1.08f, 0.72f);  // warm, the sun
    look.fillDirection = glm::normalize(glm::vec3(0.90f, 0.33f, -0.24f));
    look.fillColor = glm::vec3(0.10f, 0.12f, 0.18f); // cool, the sky's bounce
    look.skyColor = glm::vec3(0.22f, 0.23f, 0.27f);
    look.groundColor = glm::vec3(0.26f, 0.18f, 0.11f); // warm light bounced off sand and wood
    look.shadowOffset = cellSize;
    return look;
}

void setLookUniforms(GLuint program, const StudioLook& look) {
    auto at = [&](const char* name) { return glGetUniformLocation(program, name); };
    glUniform1i(at("studio"), look.studio ? 1 : 0);
    glUniform1i(at("toneMapping"), look.toneMapping ? 1 : 0);
    glUniform1i(at("environment"), look.environment ? 1 : 0);
    glUniform1i(at("keyShadows"), look.shadows ? 1 : 0);
    glUniform3fv(at("keyDirection"), 1, glm::value_ptr(look.keyDirection));
    glUniform3fv(at("keyColor"), 1, glm::value_ptr(look.keyColor));
    glUniform3fv(at("fillDirection"), 1, glm::value_ptr(look.fillDirection));
    glUniform3fv(at("fillColor"), 1, glm::value_ptr(look.fillColor));
    glUniform3fv(at("skyColor"), 1, glm::value_ptr(look.skyColor));
    glUniform3fv(at("groundColor"), 1, glm::value_ptr(look.groundColor));
    glUniformMatrix4fv(at("lightMatrix"), 1, GL_FALSE, glm::value_ptr(look.lightMatrix));
    glUniform1f(at("shadowOffset"), look.shadowOffset);
    glUniform1i(at("shadowMap"), kShadowMapUnit);
}

ShadowMap::ShadowMap() : framebuffer_(newFramebuffer()), depth_(newTexture()) {}

glm::mat4 ShadowMap::begin(const WorldBox& box, float cellSize, StudioLook& look) {
    const glm::vec3 centre = 0.5f * (box.min + box.max);
    const float radius = std::max(0.5f * glm::length(box.max - box.min), cellSize);
    // About two texels a cell, a power of two from 512 to 2048.
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer_);
    glGetIntegerv(GL_VIEWPORT, previousViewport_);
    int size = 512;
    while (size < 2048 && float(size) < 4.0f * radius / cellSize) size *= 2;
    if (size != size_) {
        size_ = size;
        glBindTexture(GL_TEXTURE_2D, depth_.get());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
        // Filtered comparison: each tap is a bilinear blend of four lit-or-not answers.
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.get(), 0);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        usable_ = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }
    bind(false);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, size, size);
    glClear(GL_DEPTH_BUFFER_BIT);
    const glm::vec3 up = std::abs(look.keyDirection.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::mat4 view = glm::lookAt(centre + look.keyDirection * (2.0f * radius), centre, up);
    const glm::mat4 clip = glm::ortho(-radius, radius, -radius, radius, radius, 3.0f * radius) * view;
    // Clip [-1, 1] to texture [0, 1] in all three coordinates.
    const glm::mat4 toTexture = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    look.lightMatrix = toTexture * clip;
    texelsPerUnit_ = float(size) / (2.0f * radius);
    return clip;
}

void ShadowMap::end() {
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFramebuffer_));
    glViewport(previousViewport_[0], previousViewport_[1], previousViewport_[2], previousViewport_[3]);
}

void ShadowMap::bind(bool on) const {
    glActiveTexture(GL_TEXTURE0 + kShadowMapUnit);
    glBindTexture(GL_TEXTURE_2D, on ? depth_.get() : 0);
    glActiveTexture(GL_TEXTURE0);
}

} // namespace sandglass
