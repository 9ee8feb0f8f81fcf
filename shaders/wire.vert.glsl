#version 330 core
// Patch edges in world space (metres).
layout(location = 0) in vec3 position;
uniform mat4 viewProjection;

void main() {
    // Faces are drawn with a polygon offset, so edges win the depth test against their own faces.
    gl_Position = viewProjection * vec4(position, 1.0);
}
