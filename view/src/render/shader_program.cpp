// SPDX-License-Identifier: MIT
#include "view/render/shader_program.hpp"

#include "scene/data_paths.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace sandglass {

namespace {
std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read shader " + file.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The driver's log can span many lines; the first names the problem.
std::string firstLine(const std::string& log) {
    const auto end = log.find('\n');
    return end == std::string::npos ? log : log.substr(0, end);
}

// A line `#include "name"` is replaced by the text of that file beside the shader, its own
// includes replaced too (the shaders share look.glsl so that every surface is lit alike). GLSL
// has no includes of its own.
std::string withIncludes(const std::filesystem::path& file) {
    std::istringstream in(readText(file));
    std::string source, line;
    while (std::getline(in, line)) {
        constexpr std::string_view directive = "#include \"";
        if (line.rfind(directive, 0) == 0) {
            const auto end = line.find('"', directive.size());
            source += withIncludes(file.parent_path() / line.substr(directive.size(), end - directive.size()));
        } else
            source += line;
        source += '\n';
    }
    return source;
}

GLuint compile(GLenum stage, const std::filesystem::path& file) {
    const std::string source = withIncludes(file);
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(std::size_t(std::max(length, 1)));
        glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
        glDeleteShader(shader);
        throw std::runtime_error("shader " + file.filename().string() + ": " + firstLine(log.data()));
    }
    return shader;
}
} // namespace

std::filesystem::path shaderDirectory() { return shaderFolder(); }

GlProgram loadShaderProgram(const std::filesystem::path& vertexFile, const std::filesystem::path& fragmentFile,
                            const char* capturedVarying) {
    const GLuint vertex = compile(GL_VERTEX_SHADER, vertexFile);
    GLuint fragment = 0;
    try {
        fragment = compile(GL_FRAGMENT_SHADER, fragmentFile);
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    GlProgram program(glCreateProgram());
    glAttachShader(program.get(), vertex);
    glAttachShader(program.get(), fragment);
    if (capturedVarying != nullptr) glTransformFeedbackVaryings(program.get(), 1, &capturedVarying, GL_INTERLEAVED_ATTRIBS);
    glLinkProgram(program.get());
    glDeleteShader(vertex); // flagged for deletion; freed with the program
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::vector<char> log(1024);
        glGetProgramInfoLog(program.get(), GLsizei(log.size()), nullptr, log.data());
        throw std::runtime_error("linking " + vertexFile.filename().string() + " + " +
                                 fragmentFile.filename().string() + ": " + firstLine(log.data()));
    }
    return program;
}

} // namespace sandglass
