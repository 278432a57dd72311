// SPDX-License-Identifier: MIT
#pragma once
// Owning handles for OpenGL objects: each deletes its object once, when it goes out of scope,
// so renderer classes hold no raw names they must remember to free.

#include <GL/glew.h>

#include <utility>

namespace sandglass {

/// A GL object name plus the function that deletes it (glDeleteBuffers, glDeleteTextures, ...).
template <void (*Delete)(GLuint)>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(GLuint name) : name_(name) {}
    ~GlHandle() { reset(); }
    GlHandle(GlHandle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;

    GLuint get() const { return name_; } ///< the GL name (0 = none)
    void reset() {
        if (name_ != 0) Delete(name_);
        name_ = 0;
    }

private:
    GLuint name_ = 0;
};

inline void deleteBuffer(GLuint name) { glDeleteBuffers(1, &name); }
inline void deleteVertexArray(GLuint name) { glDeleteVertexArrays(1, &name); }
inline void deleteTexture(GLuint name) { glDeleteTextures(1, &name); }
inline void deleteFramebuffer(GLuint name) { glDeleteFramebuffers(1, &name); }
inline void deleteRenderbuffer(GLuint name) { glDeleteRenderbuffers(1, &name); }
inline void deleteProgram(GLuint name) { glDeleteProgram(name); }

using GlBuffer = GlHandle<deleteBuffer>;             ///< a buffer object
using GlVertexArray = GlHandle<deleteVertexArray>;   ///< a vertex array object
using GlTexture = GlHandle<deleteTexture>;           ///< a texture
using GlFramebuffer = GlHandle<deleteFramebuffer>;   ///< a framebuffer object
using GlRenderbuffer = GlHandle<deleteRenderbuffer>; ///< a renderbuffer
using GlProgram = GlHandle<deleteProgram>;           ///< a linked shader program

/// A new buffer, vertex array, texture, framebuffer or renderbuffer name.
inline GLuint newBuffer() { GLuint n = 0; glGenBuffers(1, &n); return n; }
inline GLuint newVertexArray() { GLuint n = 0; glGenVertexArrays(1, &n); return n; }   ///< as above
inline GLuint newTexture() { GLuint n = 0; glGenTextures(1, &n); return n; }           ///< as above
inline GLuint newFramebuffer() { GLuint n = 0; glGenFramebuffers(1, &n); return n; }   ///< as above
inline GLuint newRenderbuffer() { GLuint n = 0; glGenRenderbuffers(1, &n); return n; } ///< as above

} // namespace sandglass
