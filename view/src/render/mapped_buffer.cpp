// SPDX-License-Identifier: MIT
#include "view/render/mapped_buffer.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace sandglass {

bool persistentMappingAvailable() {
    const char* setting = std::getenv("SANDGLASS_GL_BUFFER_STORAGE");
    if (setting != nullptr && std::strcmp(setting, "0") == 0) return false;
    return GLEW_ARB_buffer_storage != 0 && glBufferStorage != nullptr;
}

MappedBuffer::MappedBuffer(bool persistent) : buffer_(newBuffer()), persistent_(persistent) {}

MappedBuffer::~MappedBuffer() = default; // deleting a mapped buffer unmaps it

void MappedBuffer::allocate(GLenum target, std::size_t bytes, const void* data) {
    // Never empty (a texture needs storage): a smaller start is padded with zeros, so the driver
    // never reads past the caller's data.
    constexpr std::size_t kLeast = 16;
    std::array<std::byte, kLeast> padded{};
    if (bytes < kLeast && data != nullptr) {
        std::memcpy(padded.data(), data, bytes);
        data = padded.data();
    }
    bytes = std::max(bytes, kLeast);
    bytes_ = bytes;
    if (!persistent_) {
        glBindBuffer(target, buffer_.get());
        glBufferData(target, GLsizeiptr(bytes), data, GL_DYNAMIC_DRAW);
        glBindBuffer(target, 0);
        return;
    }
    buffer_ = GlBuffer(newBuffer());
    constexpr GLbitfield kFlags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    glBindBuffer(target, buffer_.get());
    glBufferStorage(target, GLsizeiptr(bytes), data, kFlags);
    mapped_ = glMapBufferRange(target, 0, GLsizeiptr(bytes), kFlags);
    if (mapped_ == nullptr) { // the driver would not map it: a plain buffer from now on
        persistent_ = false;
        buffer_ = GlBuffer(newBuffer());
        glBindBuffer(target, buffer_.get());
        glBufferData(target, GLsizeiptr(bytes), data, GL_DYNAMIC_DRAW);
    }
    glBindBuffer(target, 0);
}

DrawFence::~DrawFence() {
    if (fence_ != nullptr) glDeleteSync(fence_);
}

void DrawFence::drawn() {
    if (fence_ != nullptr) glDeleteSync(fence_);
    fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

void DrawFence::waitForDraws() {
    if (fence_ == nullptr) return;
    constexpr GLuint64 kSecond = 1'000'000'000;
    while (glClientWaitSync(fence_, GL_SYNC_FLUSH_COMMANDS_BIT, kSecond) == GL_TIMEOUT_EXPIRED) {
    }
    glDeleteSync(fence_);
    fence_ = nullptr;
}

} // namespace sandglass
