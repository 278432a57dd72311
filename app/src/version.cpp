// SPDX-License-Identifier: MIT
#include "app/version.hpp"

#include "scene/data_paths.hpp"
#include "scene/library_versions.hpp"

#include "sandcore/sweep_code.hpp"

#include <CLI/Version.hpp>
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace sandglass {

namespace {

// Which builds of the sweep this binary holds and which one granular steps run here (sweep_code.hpp).
std::string sweepBuilds() {
    if (!sandcore::bmi2SweepBuilt()) return "sweep: the portable build only";
    return std::string("sweep: portable and BMI2 builds; granular steps run the ") +
           (sandcore::bmi2SweepAvailable() ? "BMI2 one on this CPU" : "portable one (this CPU lacks BMI1 or BMI2)");
}

} // namespace

std::string versionText() {
    return std::string("sandglass ") + SANDGLASS_VERSION + " (commit " + SANDGLASS_COMMIT + ")\n" +
           "Dear ImGui " + IMGUI_VERSION + ", GLFW " + glfwGetVersionString() + ", " + sceneLibraryVersions() +
           ", CLI11 " + CLI11_VERSION + "\n" + sweepBuilds() + "\n" +
           // I2: where this copy finds its data, so an installed or moved one can be checked.
           "data: " + dataFolder().string() + ", model importer: " + importHelperPath().string();
}

} // namespace sandglass
