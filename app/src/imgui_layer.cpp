// SPDX-License-Identifier: MIT
#include "app/imgui_layer.hpp"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>
#include <utility>

namespace sandglass {

namespace {

// Text of 15 px at a content scale of 1: ImGui's 13 px bitmap font reads small on today's screens.
constexpr float kFontPixels = 15.0f;
// A clear sans-serif where the system has it (Debian's fonts-dejavu-core); ImGui's own font otherwise.
constexpr const char* kFontFiles[] = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                      "/usr/share/fonts/TTF/DejaVuSans.ttf"};

void loadFont(float pixels) {
    ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
    atlas.Clear();
    for (const char* file : kFontFiles) {
        std::error_code error;
        if (std::filesystem::exists(file, error) && atlas.AddFontFromFileTTF(file, pixels)) return;
    }
    ImFontConfig font;
    font.SizePixels = pixels;
    atlas.AddFontDefault(&font);
}

void applyStyle(float scale) {
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.WindowRounding = 6.0f;
    style.FrameRounding = 3.0f;
    // Hints and disabled controls read on the dark panel: ImGui's default grey is too faint.
    style.Colors[ImGuiCol_TextDisabled] = ImVec4(0.72f, 0.72f, 0.74f, 1.0f);
    style.Colors[ImGuiCol_WindowBg] = ImVec4(0.07f, 0.07f, 0.08f, 0.94f);
    style.ScaleAllSizes(scale);
    ImGui::GetStyle() = style;
}

} // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window, float contentScale) : contentScale_(contentScale) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini next to wherever the user started the program
    applyScale();
    ImGui_ImplGlfw_InitForOpenGL(window, false);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    backendReady_ = true;
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::setIniFile(const std::filesystem::path& file) {
    std::error_code error;
    std::filesystem::create_directories(file.parent_path(), error);
    iniFile_ = file.string();
    ImGui::GetIO().IniFilename = iniFile_.c_str();
}

float ImGuiLayer::setUiScale(float scale) {
    scale = std::clamp(scale, kMinUiScale, kMaxUiScale);
    if (scale == uiScale_) return uiScale_;
    uiScale_ = scale;
    applyScale();
    return uiScale_;
}

void ImGuiLayer::applyScale() {
    // The font is rasterised at the size shown, so text stays sharp at every scale.
    loadFont(std::round(kFontPixels * contentScale_ * uiScale_));
    applyStyle(contentScale_ * uiScale_);
    if (backendReady_) {
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }
}

void ImGuiLayer::startFrame(const MouseTransition* replayed) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGuiIO& io = ImGui::GetIO();
    if (replayed) {
        // The button states as they were right after this transition, at its cursor position.
        buttonsDown_[replayed->button] = replayed->pressed;
        for (int button = 0; button < 5; ++button) io.MouseDown[button] = buttonsDown_[button];
        io.MousePos = ImVec2(float(replayed->x), float(replayed->y));
        io.DeltaTime = std::max(io.DeltaTime, 1e-4f);
    } else {
        for (int button = 0; button < 5; ++button) buttonsDown_[button] = io.MouseDown[button];
    }
    ImGui::NewFrame();
}

void ImGuiLayer::newFrame() {
    pending_.clear();
    startFrame(nullptr);
}

void ImGuiLayer::newFrame(const std::function<void()>& buildWindows) {
    std::vector<MouseTransition> transitions = std::exchange(pending_, {});
    std::erase_if(transitions, [](const MouseTransition& t) { return t.button < 0 || t.button >= 5; });
    for (std::size_t i = 0; i + 1 < transitions.size(); ++i) {
        startFrame(&transitions[i]);
        buildWindows();
        ImGui::EndFrame(); // built, never drawn
    }
    startFrame(transitions.empty() ? nullptr : &transitions.back());
}

void ImGuiLayer::render(bool drawPanels) {
    ImGui::Render();
    if (drawPanels) ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

} // namespace sandglass
