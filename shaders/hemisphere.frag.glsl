#version 330 core
// Paints the dome with what the point sees: the local direction -> an equidistant fisheye image of
// the hemicube (radius theta / (pi / 2)), plus the theta/phi grid of d omega cells drawn here, about
// a pixel wide at any zoom. The image is sRGB-encoded, as the framebuffer expects (no GL_FRAMEBUFFER_SRGB).
in vec3 direction;
in vec3 worldPosition;
in vec3 worldNormal;

uniform sampler2D sky;
uniform vec3 imageRight;   // the image's axes in the local tangent plane (x, y; z unused)
uniform vec3 imageUp;
uniform float imageSize;   // pixels per side
uniform vec3 eye;
uniform float frontOpacity;
uniform float backOpacity;
uniform int grid;

out vec4 fragColour;

const float HALF_PI = 1.5707963268;
const float PI = 3.1415926536;

// Coverage of a line about 1.5 px wide where the coordinate u crosses an integer.
float lineAt(float u, float pixelsPerUnit) {
    float distancePx = abs(fract(u + 0.5) - 0.5) * pixelsPerUnit;
    return 1.0 - smoothstep(0.5, 1.3, distancePx);
}

void main() {
    vec3 d = normalize(direction);
    float theta = acos(clamp(d.z, -1.0, 1.0));
    float horizontal = length(d.xy);
    // Kept a pixel inside the rim: outside the disk the image is transparent.
    float diskRadius = min(theta / HALF_PI, 1.0 - 1.0 / imageSize);
    vec2 disk = horizontal > 1e-6 ? d.xy / horizontal * diskRadius : vec2(0.0);
    vec2 image = vec2(dot(disk, imageRight.xy), dot(disk, imageUp.xy));
    vec4 seen = texture(sky, vec2(0.5 + 0.5 * image.x, 0.5 - 0.5 * image.y));
    vec3 colour = seen.rgb;
    float line = 0.0;
    if (grid != 0) {
        vec2 planar = vec2(dot(d.xy, imageRight.xy), dot(d.xy, imageUp.xy));
        float thetaCells = theta / (PI / 12.0);  // 15 degrees
        float onTheta = lineAt(thetaCells, 1.0 / max(fwidth(thetaCells), 1e-6));
        // phi from the image's right, as the panel draws it; two branch cuts so fwidth never sees the jump.
        float phiA = atan(planar.y, planar.x) / (PI / 6.0);      // 30 degrees
        float phiB = atan(-planar.y, -planar.x) / (PI / 6.0);
        float phiWidth = min(fwidth(phiA), fwidth(phiB));
        float pixelsPerCell = 1.0 / max(phiWidth, 1e-6);
        // Where the meridians crowd together at the zenith they fade instead of filling it grey.
        float onPhi = lineAt(phiA, pixelsPerCell) * smoothstep(3.0, 6.0, pixelsPerCell);
        line = max(onTheta, onPhi);
        colour = mix(colour, vec3(0.77, 0.77, 0.8), 0.6 * line);
    }

    // A little darker where the dome turns away from the eye, so it reads as a dome.
    float facing = abs(dot(normalize(eye - worldPosition), normalize(worldNormal)));
    colour *= mix(0.75, 1.0, facing);
    float opacity = gl_FrontFacing ? frontOpacity : backOpacity;
    // The image is see-through where the point sees open sky; the grid stays visible there.
    fragColour = vec4(colour, opacity * max(seen.a, 0.8 * line));
}
