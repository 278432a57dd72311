// SPDX-License-Identifier: MIT
#include "view/window.hpp"

#include <GL/glew.h>
#include <GLFW/glfw3.h>

#include <chrono>
#include <thread>

namespace sandglass {

namespace {
std::string glfwProblem() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description != nullptr ? description : "unknown GLFW error";
}

std::string glString(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text != nullptr ? text : "unknown";
}
} // namespace

Window::Window(const WindowOptions& options) {
    // An X server refuses a small share of connections that follow each other quickly (seen with
    // Xvfb when tests open many windows, and with two processes on one display): try a few times.
    bool initialised = false;
    for (int attempt = 0; attempt < 8 && !initialised; ++attempt) {
        if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(25 * attempt));
        initialised = glfwInit() == GLFW_TRUE;
    }
    if (!initialised)
        throw WindowError("cannot open a window: " + glfwProblem() + " (is DISPLAY set? try xvfb-run -a)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE); // HiDPI: the window grows with the content scale
    glfwWindowHint(GLFW_SAMPLES, 0);
    window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) {
        const std::string problem = glfwProblem();
        glfwTerminate();
        throw WindowError("cannot create an OpenGL 3.3 core context: " + problem);
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(options.vsync ? 1 : 0);
    glewExperimental = GL_TRUE; // core profiles need it with GLEW 2.1
    const GLenum glewStatus = glewInit();
    if (glewStatus != GLEW_OK && glewStatus != GLEW_ERROR_NO_GLX_DISPLAY) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw WindowError(std::string("cannot load OpenGL functions: ") +
                          reinterpret_cast<const char*>(glewGetErrorString(glewStatus)));
    }
    while (glGetError() != GL_NO_ERROR) {
        // glewInit asks for core-removed strings and leaves GL_INVALID_ENUM behind.
    }
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

float Window::contentScale() const {
    float x = 1.0f, y = 1.0f;
    glfwGetWindowContentScale(window_, &x, &y);
    return x > 0.0f ? x : 1.0f;
}

void Window::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

bool Window::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

void Window::swapBuffers() { glfwSwapBuffers(window_); }

std::string Window::glRenderer() const { return glString(GL_RENDERER); }

std::string Window::glVersion() const { return glString(GL_VERSION); }

} // namespace sandglass
