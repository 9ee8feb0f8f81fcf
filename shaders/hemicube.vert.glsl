#version 330 core
// Patches in world space (metres) for the hemicube's item buffer: each vertex carries its patch's
// item (patch index + 1) and the patch's front normal.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in uint item;

uniform mat4 viewProjection;

out vec3 worldPosition;
flat out vec3 patchNormal;
flat out uint patchItem;

void main() {
    worldPosition = position;
    patchNormal = normal;
    patchItem = item;
    gl_Position = viewProjection * vec4(position, 1.0);
}
