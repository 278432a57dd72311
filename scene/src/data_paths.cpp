// SPDX-License-Identifier: MIT
#include "scene/data_paths.hpp"

#include <cstdlib>
#include <system_error>
#include <unistd.h>

namespace sandglass {

namespace {

std::filesystem::path environmentPath(const char* name) {
    const char* value = std::getenv(name);
    return value != nullptr && *value != '\0' ? std::filesystem::path(value) : std::filesystem::path();
}

bool isFolder(const std::filesystem::path& path) {
    std::error_code error;
    return std::filesystem::is_directory(path, error);
}

} // namespace

std::filesystem::path executableFolder() {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : self.parent_path();
}

std::filesystem::path dataFolder() {
    if (auto overridden = environmentPath("SANDGLASS_DATA_DIR"); !overridden.empty()) return overridden;
    // The installed layout beside the executable wins, so a moved or copied install finds its own data.
    if (const std::filesystem::path exe = executableFolder(); !exe.empty()) {
        const std::filesystem::path installed = (exe / SANDGLASS_DATA_FROM_BINARY).lexically_normal();
        if (isFolder(installed / "shaders")) return installed;
    }
    return SANDGLASS_SOURCE_DIR;
}

std::filesystem::path modelsFolder() { return dataFolder() / "models"; }

std::filesystem::path shaderFolder() {
    if (auto overridden = environmentPath("SANDGLASS_SHADER_DIR"); !overridden.empty()) return overridden;
    return dataFolder() / "shaders";
}

std::filesystem::path importHelperPath() {
    if (const std::filesystem::path exe = executableFolder(); !exe.empty()) {
        const std::filesystem::path installed = (exe / SANDGLASS_HELPER_FROM_BINARY).lexically_normal();
        if (::access(installed.c_str(), X_OK) == 0) return installed;
    }
    if (::access(SANDGLASS_BUILT_IMPORT_HELPER, X_OK) == 0) return SANDGLASS_BUILT_IMPORT_HELPER;
    return {};
}

} // namespace sandglass
