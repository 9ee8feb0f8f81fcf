#include "render/gl/ShaderProgram.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <optional>
#include <utility>
#include <vector>

#include "radiometry/common/Error.h"
#include "render/EmbeddedShaders.h"

namespace radiant::render::gl {
namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.data();
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.data();
}

GLuint compile(GLenum stage, std::string_view fileName, std::string_view defines) {
    const std::optional<std::string_view> source = embeddedShader(fileName);
    if (!source)
        throw RadiantError({"shaders/" + std::string(fileName), ""}, "no such shader was embedded in the binary");
    // The defines go right after the #version line, which must stay first.
    std::string text(*source);
    const std::size_t afterVersion = text.find('\n') == std::string::npos ? text.size() : text.find('\n') + 1;
    text.insert(afterVersion, std::string(defines));
    const GLuint shader = glCreateShader(stage);
    const char* chars = text.data();
    const auto length = static_cast<GLint>(text.size());
    glShaderSource(shader, 1, &chars, &length);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = shaderLog(shader);
        glDeleteShader(shader);
        throw RadiantError({"shaders/" + std::string(fileName), "compile"}, "GLSL compile failed:\n" + log);
    }
    return shader;
}

} // namespace

ShaderProgram::ShaderProgram(std::string_view vertexFile, std::string_view fragmentFile)
    : ShaderProgram(vertexFile, fragmentFile, {}) {}

ShaderProgram::ShaderProgram(std::string_view vertexFile, std::string_view fragmentFile, std::string_view defines)
    : name_(std::string(vertexFile) + " + " + std::string(fragmentFile)) {
    const GLuint vertex = compile(GL_VERTEX_SHADER, vertexFile, defines);
    GLuint fragment = 0;
    try {
        fragment = compile(GL_FRAGMENT_SHADER, fragmentFile, defines);
    } catch (...) {
        glDeleteShader(vertex);
        throw;
    }
    id_ = glCreateProgram();
    glAttachShader(id_, vertex);
    glAttachShader(id_, fragment);
    glLinkProgram(id_);
    // The program keeps the compiled stages alive; our names are no longer needed.
    glDetachShader(id_, vertex);
    glDetachShader(id_, fragment);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = programLog(id_);
        glDeleteProgram(id_);
        id_ = 0;
        throw RadiantError({"shaders/" + name_, "link"}, "GLSL link failed:\n" + log);
    }
}

ShaderProgram::~ShaderProgram() {
    if (id_ != 0) glDeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept
    : id_(std::exchange(other.id_, 0)), name_(std::move(other.name_)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        if (id_ != 0) glDeleteProgram(id_);
        id_ = std::exchange(other.id_, 0);
        name_ = std::move(other.name_);
    }
    return *this;
}

void ShaderProgram::use() const { glUseProgram(id_); }

GLint ShaderProgram::location(const char* uniform) const {
    glUseProgram(id_);
    return glGetUniformLocation(id_, uniform);
}

void ShaderProgram::set(const char* uniform, const glm::mat4& value) const {
    glUniformMatrix4fv(location(uniform), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(const char* uniform, const glm::vec2& value) const {
    glUniform2fv(location(uniform), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* uniform, const glm::vec3& value) const {
    glUniform3fv(location(uniform), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* uniform, const glm::vec4& value) const {
    glUniform4fv(location(uniform), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* uniform, float value) const { glUniform1f(location(uniform), value); }
void ShaderProgram::set(const char* uniform, int value) const { glUniform1i(location(uniform), value); }

} // namespace radiant::render::gl
