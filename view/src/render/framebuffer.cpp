// SPDX-License-Identifier: MIT
#include "view/render/framebuffer.hpp"

#include "scene/file_io.hpp"

#include <stb_image_write.h>

#include <cstring>
#include <span>
#include <vector>
#include <stdexcept>
#include <string>

namespace sandglass {

OffscreenTarget::OffscreenTarget(int width, int height)
    : width_(width), height_(height), framebuffer_(newFramebuffer()), color_(newRenderbuffer()),
      depth_(newRenderbuffer()) {
    glBindRenderbuffer(GL_RENDERBUFFER, color_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("cannot make a " + std::to_string(width) + "x" + std::to_string(height) +
                                 " offscreen framebuffer (status " + std::to_string(status) + ")");
}

void OffscreenTarget::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get()); }

RgbImage readPixels(int width, int height) {
    RgbImage image{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 3)};
    std::vector<std::uint8_t> bottomUp(image.pixels.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
    const std::size_t row = std::size_t(width) * 3;
    // GL's first row is the bottom one; PNG's is the top one.
    for (int y = 0; y < height; ++y)
        std::memcpy(image.pixels.data() + std::size_t(y) * row, bottomUp.data() + std::size_t(height - 1 - y) * row,
                    row);
    return image;
}

std::vector<std::uint8_t> encodePng(const RgbImage& image) {
    if (image.width <= 0 || image.height <= 0) throw std::runtime_error("no image to encode");
    std::vector<std::uint8_t> encoded;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        out->insert(out->end(), bytes, bytes + size);
    };
    if (stbi_write_png_to_func(append, &encoded, image.width, image.height, 3, image.pixels.data(), image.width * 3) == 0)
        throw std::runtime_error("cannot encode the PNG image");
    return encoded;
}

void writePng(const std::filesystem::path& file, const RgbImage& image) {
    if (image.width <= 0 || image.height <= 0) throw std::runtime_error("no image to write to " + file.string());
    // Encoded in memory, then written through a temporary file renamed into place: a full disk
    // or a missing folder is an error and never leaves a truncated PNG over an existing one.
    writeFileAtomically(file, std::span<const std::uint8_t>(encodePng(image)));
}

} // namespace sandglass
