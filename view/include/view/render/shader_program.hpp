// SPDX-License-Identifier: MIT
#pragma once
// GLSL programs loaded at run time from shaders/ (one file per stage), so a shader can be
// edited without rebuilding. The folder is found beside the executable (scene/data_paths.hpp).

#include "view/render/gl_objects.hpp"

#include <filesystem>
#include <string>

namespace sandglass {

/// The folder the shaders are read from: $SANDGLASS_SHADER_DIR if set, else the data folder's shaders/.
std::filesystem::path shaderDirectory();

/// Compiles and links a vertex and a fragment shader read from files; throws std::runtime_error
/// with one line naming the file and the compiler's first message on failure.
/// capturedVarying: a vertex output that transform feedback records (tests read positions back).
GlProgram loadShaderProgram(const std::filesystem::path& vertexFile, const std::filesystem::path& fragmentFile,
                            const char* capturedVarying = nullptr);

} // namespace sandglass
