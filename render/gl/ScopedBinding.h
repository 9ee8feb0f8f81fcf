#pragma once
// Binds a GL object for the scope of an edit and puts back whatever was bound before, so that the
// wrappers in render/gl leave the caller's bindings as they found them (as Magnum's state tracker
// does, without the cache: a glGet per edit is cheap next to the upload it guards).
#include <epoxy/gl.h>

namespace radiant::render::gl {

/// `Target` is the binding point (GL_ARRAY_BUFFER, GL_TEXTURE_2D, or 0 for the vertex array).
template <GLenum Target>
class ScopedBinding {
public:
    explicit ScopedBinding(GLuint id) {
        glGetIntegerv(query(), &previous_);
        bind(id);
    }
    ~ScopedBinding() { bind(static_cast<GLuint>(previous_)); }
    ScopedBinding(const ScopedBinding&) = delete;
    ScopedBinding& operator=(const ScopedBinding&) = delete;
    ScopedBinding(ScopedBinding&&) = delete;
    ScopedBinding& operator=(ScopedBinding&&) = delete;

private:
    static constexpr GLenum query() {
        if constexpr (Target == GL_ARRAY_BUFFER) return GL_ARRAY_BUFFER_BINDING;
        else if constexpr (Target == GL_TEXTURE_2D) return GL_TEXTURE_BINDING_2D;
        else return GL_VERTEX_ARRAY_BINDING;
    }
    static void bind(GLuint id) {
        if constexpr (Target == GL_ARRAY_BUFFER) glBindBuffer(GL_ARRAY_BUFFER, id);
        else if constexpr (Target == GL_TEXTURE_2D) glBindTexture(GL_TEXTURE_2D, id);
        else glBindVertexArray(id);
    }
    GLint previous_ = 0;
};

using ScopedArrayBuffer = ScopedBinding<GL_ARRAY_BUFFER>;
/// On the active texture unit.
using ScopedTexture2D = ScopedBinding<GL_TEXTURE_2D>;
using ScopedVertexArray = ScopedBinding<0>;

} // namespace radiant::render::gl
