#version 330 core
// The dome over the probe point: a unit hemisphere in the point's local frame (z = the normal),
// placed at the point and scaled to its radius in world space (metres). Everything that varies
// smoothly over the dome is worked out here, per vertex (16 x 64 of them), and interpolated: the
// picture's disk position, the grid's coordinates and the shading by facing. Per pixel, trigonometry
// was most of the dome's cost on software GL.
layout(location = 0) in vec3 localDirection;
layout(location = 1) in vec2 thetaPhi;  // radians, phi running on to 2 pi at the last segment

uniform mat4 viewProjection;
uniform vec3 centre;
uniform vec3 tangent;
uniform vec3 bitangent;
uniform vec3 normal;
uniform float radius;
uniform vec3 eye;
uniform vec3 imageRight;   // the image's axes in the local tangent plane (x, y; z unused)
uniform vec3 imageUp;
uniform float imageSize;   // pixels per side
uniform float phiOfImageRight;

out vec2 imagePosition;  // where the equidistant fisheye image shows this direction, texture coordinates
out vec2 gridCells;      // theta in 15-degree cells, phi in 30-degree cells from the image's right
out float facing;        // |cos| between the dome's normal and the view: it darkens where it turns away

const float HALF_PI = 1.5707963268;
const float PI = 3.1415926536;

void main() {
    vec3 worldNormal = localDirection.x * tangent + localDirection.y * bitangent + localDirection.z * normal;
    vec3 worldPosition = centre + radius * worldNormal;
    // Equidistant: radius theta / (pi / 2), kept a pixel inside the rim (outside, the image is transparent).
    float diskRadius = min(thetaPhi.x / HALF_PI, 1.0 - 1.0 / imageSize);
    vec2 disk = vec2(cos(thetaPhi.y), sin(thetaPhi.y)) * diskRadius;
    vec2 image = vec2(dot(disk, imageRight.xy), dot(disk, imageUp.xy));
    imagePosition = vec2(0.5 + 0.5 * image.x, 0.5 - 0.5 * image.y);
    gridCells = vec2(thetaPhi.x / (PI / 12.0), (thetaPhi.y - phiOfImageRight) / (PI / 6.0));
    facing = abs(dot(normalize(eye - worldPosition), worldNormal));
    gl_Position = viewProjection * vec4(worldPosition, 1.0);
}
