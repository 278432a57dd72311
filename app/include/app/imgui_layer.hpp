#pragma once
// The Dear ImGui context with its GLFW and OpenGL 3 backends, sized for the monitor's content
// scale (HiDPI). GLFW callbacks are not installed by the backend: the application forwards
// events to it first and then routes them by ImGui's capture flags (input_routing.hpp).

struct GLFWwindow;

namespace sandglass {

class ImGuiLayer {
public:
    /// Creates the context for a window whose GL context is current; contentScale enlarges the
    /// font and every style size.
    ImGuiLayer(GLFWwindow* window, float contentScale);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void newFrame();             ///< starts a frame: backends, then ImGui::NewFrame
    void render(bool drawPanels); ///< ends the frame; draws it into the bound framebuffer when drawPanels
};

} // namespace sandglass
