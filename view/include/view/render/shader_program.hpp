#pragma once
// GLSL programs loaded at run time from shaders/ (one file per stage), so a shader can be
// edited without rebuilding. The folder is baked in at configure time (SANDGLASS_SOURCE_DIR).

#include "view/render/gl_objects.hpp"

#include <filesystem>
#include <initializer_list>
#include <string>

namespace sandglass {

/// The folder the shaders are read from: $SANDGLASS_SHADER_DIR if set, else <source>/shaders.
std::filesystem::path shaderDirectory();

/// Compiles and links a vertex and a fragment shader read from files; throws std::runtime_error
/// with one line naming the file and the compiler's first message on failure.
/// capturedVarying: a vertex output that transform feedback records (tests read positions back).
GlProgram loadShaderProgram(const std::filesystem::path& vertexFile, const std::filesystem::path& fragmentFile,
                            const char* capturedVarying = nullptr);

/// A vertex shader alone whose outputs transform feedback records, each into its own buffer
/// (binding 0, 1, ... in the order given): a pass that computes and draws nothing. Throws as
/// loadShaderProgram.
GlProgram loadTransformFeedbackProgram(const std::filesystem::path& vertexFile,
                                       std::initializer_list<const char*> capturedVaryings);

} // namespace sandglass
