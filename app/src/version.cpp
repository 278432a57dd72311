// SPDX-License-Identifier: MIT
#include "app/version.hpp"

#include "scene/data_paths.hpp"
#include "scene/library_versions.hpp"

#include <CLI/Version.hpp>
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace sandglass {

std::string versionText() {
    return std::string("sandglass ") + SANDGLASS_VERSION + " (commit " + SANDGLASS_COMMIT + ")\n" +
           "Dear ImGui " + IMGUI_VERSION + ", GLFW " + glfwGetVersionString() + ", " + sceneLibraryVersions() +
           ", CLI11 " + CLI11_VERSION + "\n" +
           // I2: where this copy finds its data, so an installed or moved one can be checked.
           "data: " + dataFolder().string() + ", model importer: " + importHelperPath().string();
}

} // namespace sandglass
