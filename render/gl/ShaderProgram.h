#pragma once
// Move-only owner of a linked GLSL program built from shaders/ files embedded in the binary.
// A compile or link failure throws RadiantError naming the file, with the driver's log.
#include <epoxy/gl.h>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <string_view>

namespace radiant::render::gl {

class ShaderProgram {
public:
    /// Compiles shaders/<vertexFile> and shaders/<fragmentFile> and links them.
    ShaderProgram(std::string_view vertexFile, std::string_view fragmentFile);
    /// As above with `defines` ("#define X 1\n" lines) inserted after each file's #version line:
    /// specialised variants, so software GL does not pay per pixel for features that are off.
    ShaderProgram(std::string_view vertexFile, std::string_view fragmentFile, std::string_view defines);
    ~ShaderProgram();
    ShaderProgram(ShaderProgram&& other) noexcept;
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    [[nodiscard]] GLuint id() const { return id_; }
    void use() const;

    // Setters act on this program (made current); a name the linker optimised away is ignored, as GL does.
    void set(const char* uniform, const glm::mat4& value) const;
    void set(const char* uniform, const glm::vec2& value) const;
    void set(const char* uniform, const glm::vec3& value) const;
    void set(const char* uniform, const glm::vec4& value) const;
    void set(const char* uniform, float value) const;
    void set(const char* uniform, int value) const;

private:
    GLint location(const char* uniform) const;

    GLuint id_ = 0;
    std::string name_;  ///< "flat.vert.glsl + flat.frag.glsl", for messages
};

} // namespace radiant::render::gl
