#include "app/version.hpp"

#include "scene/library_versions.hpp"

#include <CLI/Version.hpp>
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace sandglass {

std::string versionText() {
    return std::string("sandglass ") + SANDGLASS_VERSION + " (commit " + SANDGLASS_COMMIT + ")\n" +
           "Dear ImGui " + IMGUI_VERSION + ", GLFW " + glfwGetVersionString() + ", " + sceneLibraryVersions() +
           ", CLI11 " + CLI11_VERSION;
}

} // namespace sandglass
