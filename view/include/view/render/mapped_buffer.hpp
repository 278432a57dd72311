// SPDX-License-Identifier: MIT
#pragma once
// A GL buffer the CPU changes entry by entry. Where the GL has ARB_buffer_storage (core in 4.4;
// the renderer itself needs only 3.3) the buffer is mapped once, persistently and coherently, so
// a changed entry is one store into the driver's memory and a step costs no GL call at all; a
// fence set after each draw that reads it is waited for before the next writes (normally already
// passed: the frame before has been drawn). Without it the buffer is a plain one and the owner
// sends its changes in runs (the older path, kept for GL 3.3 drivers).
// SANDGLASS_GL_BUFFER_STORAGE=0 in the environment turns the mapping off (to compare the two).

#include "view/render/gl_objects.hpp"

#include <cstddef>

namespace sandglass {

/// True when buffers are mapped persistently (the GL has ARB_buffer_storage, not turned off).
bool persistentMappingAvailable();

class MappedBuffer {
public:
    /// A buffer of at least 16 bytes (a buffer texture needs storage); mapped when `persistent`.
    explicit MappedBuffer(bool persistent);
    ~MappedBuffer();
    MappedBuffer(const MappedBuffer&) = delete;
    MappedBuffer& operator=(const MappedBuffer&) = delete;

    /// New storage of `bytes` holding `data` (null: undefined). A persistent buffer gets a new
    /// name (its storage is immutable): whoever refers to it (a buffer texture, a vertex array)
    /// must be pointed at get() again.
    void allocate(GLenum target, std::size_t bytes, const void* data);
    GLuint get() const { return buffer_.get(); } ///< the GL name
    std::size_t size() const { return bytes_; }  ///< bytes of storage
    /// The mapped storage to write into (persistent only; else null). Call waitForDraws() first.
    void* mapped() const { return mapped_; }
    bool persistent() const { return persistent_; } ///< as constructed

private:
    GlBuffer buffer_;
    std::size_t bytes_ = 0;
    void* mapped_ = nullptr;
    bool persistent_ = false;
};

/// The fence after the last draw that read persistently mapped buffers: writes wait for it.
class DrawFence {
public:
    DrawFence() = default;
    ~DrawFence();
    DrawFence(const DrawFence&) = delete;
    DrawFence& operator=(const DrawFence&) = delete;
    /// After a draw that reads the buffers.
    void drawn();
    /// Before writing into them: waits until the GPU has finished those draws.
    void waitForDraws();

private:
    GLsync fence_ = nullptr;
};

} // namespace sandglass
