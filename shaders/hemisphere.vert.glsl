#version 330 core
// The dome over the probe point: a unit hemisphere in the point's local frame (z = the normal),
// placed at the point and scaled to its radius in world space (metres).
layout(location = 0) in vec3 localDirection;

uniform mat4 viewProjection;
uniform vec3 centre;
uniform vec3 tangent;
uniform vec3 bitangent;
uniform vec3 normal;
uniform float radius;

out vec3 direction;      // local, interpolated: the direction from the point this fragment shows
out vec3 worldPosition;
out vec3 worldNormal;

void main() {
    direction = localDirection;
    worldNormal = localDirection.x * tangent + localDirection.y * bitangent + localDirection.z * normal;
    worldPosition = centre + radius * worldNormal;
    gl_Position = viewProjection * vec4(worldPosition, 1.0);
}
