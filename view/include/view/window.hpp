// SPDX-License-Identifier: MIT
#pragma once
// The GLFW window with an OpenGL 3.3 core context (GLEW loads the functions). One window per
// process at a time: it initialises GLFW when made and terminates it when destroyed.

#include <stdexcept>
#include <string>

struct GLFWwindow;

namespace sandglass {

/// No window or GL context could be made (no display, no OpenGL 3.3).
class WindowError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// What kind of window to open.
struct WindowOptions {
    int width = 1280;                 ///< client width in screen coordinates (scaled by the monitor's content scale)
    int height = 800;                 ///< client height in screen coordinates
    bool visible = true;              ///< false: a hidden window, for offscreen rendering
    bool vsync = true;                ///< wait for the display's refresh; off for benchmarks
    std::string title = "sandglass";  ///< window title
};

class Window {
public:
    /// Opens the window and makes its context current; throws WindowError with one line.
    explicit Window(const WindowOptions& options);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }   ///< the GLFW window
    float contentScale() const;                        ///< HiDPI factor of the monitor (1 = 96 dpi)
    void framebufferSize(int& width, int& height) const; ///< drawable size in pixels
    bool shouldClose() const;                          ///< the user asked to close it
    void swapBuffers();                                ///< shows the frame drawn
    /// GL_RENDERER and GL_VERSION of the context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    std::string glRenderer() const;
    std::string glVersion() const; ///< as above, GL_VERSION

private:
    GLFWwindow* window_ = nullptr;
};

} // namespace sandglass
