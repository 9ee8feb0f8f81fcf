#version 330 core
// Scene faces in world space (metres), one colour per face.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
layout(location = 3) in float emissive;

uniform mat4 viewProjection;

out vec3 worldPosition;
flat out vec3 faceNormal;
flat out vec3 faceColour;
flat out float faceEmissive;

void main() {
    worldPosition = position;
    faceNormal = normal;
    faceColour = colour;
    faceEmissive = emissive;
    gl_Position = viewProjection * vec4(position, 1.0);
}
