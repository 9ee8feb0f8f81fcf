#version 330 core
// Placeholder, replaced by the first window.
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
