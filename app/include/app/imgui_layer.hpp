// SPDX-License-Identifier: MIT
#pragma once
// The Dear ImGui context with its GLFW and OpenGL 3 backends, sized for the monitor's content
// scale (HiDPI) and the user's UI scale. GLFW callbacks are not installed by the backend: the
// application forwards events to it first and then routes them by ImGui's capture flags
// (input_routing.hpp).

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace sandglass {

/// One press or release of a mouse button, where the cursor was at that moment (window units).
struct MouseTransition {
    int button = 0;       ///< 0 left, 1 right, 2 middle (GLFW and ImGui agree)
    bool pressed = false; ///< true: pressed, false: released
    double x = 0.0, y = 0.0;
};

class ImGuiLayer {
public:
    /// Creates the context for a window whose GL context is current; contentScale enlarges the
    /// font and every style size.
    ImGuiLayer(GLFWwindow* window, float contentScale);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void newFrame();             ///< starts a frame: backends, then ImGui::NewFrame
    /// Starts a frame in which no click is lost: ImGui 1.86 sees one button state per frame, so
    /// when several presses and releases came since the last frame (a slow frame), each but the
    /// last gets a frame of its own in which `buildWindows` runs without drawing; the frame
    /// started last sees the last one. Call `buildWindows` once more after this for the real frame.
    void newFrame(const std::function<void()>& buildWindows);
    /// Records a press or release (the GLFW mouse-button callback calls this).
    void queueMouseTransition(const MouseTransition& transition) { pending_.push_back(transition); }
    void render(bool drawPanels); ///< ends the frame; draws it into the bound framebuffer when drawPanels

    static constexpr float kMinUiScale = 0.75f, kMaxUiScale = 2.5f;
    /// The user's text and control size, on top of the content scale, clamped to
    /// kMinUiScale..kMaxUiScale; call between frames. Returns the value in use.
    float setUiScale(float scale);
    /// I4: keep the panels' layout in this imgui.ini (read at the first frame, written when the
    /// layer closes); call before the first frame.
    void setIniFile(const std::filesystem::path& file);

private:
    void startFrame(const MouseTransition* replayed);
    void applyScale();

    std::vector<MouseTransition> pending_;
    bool buttonsDown_[5] = {};   // the button states after the transitions replayed so far
    float contentScale_ = 1.0f;
    float uiScale_ = 1.0f;
    bool backendReady_ = false;
    std::string iniFile_; // ImGui keeps a pointer to it
};

} // namespace sandglass
