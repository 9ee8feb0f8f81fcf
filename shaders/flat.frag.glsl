#version 330 core
// Reflectance as colour, dimmed a little where the face turns away from the eye and from a key
// direction fixed to the camera (above, behind, to the right), so creases and parallel faces at
// different depths read apart. A display aid, not a radiometric quantity: the patch renderer shows
// radiosity instead. Colours are linear; the framebuffer wants sRGB.
in vec3 worldPosition;
flat in vec3 faceNormal;
flat in vec3 faceColour;
flat in float faceEmissive;

uniform vec3 eye;
uniform vec3 keyDirection;  // unit, toward the key

out vec4 fragColour;

vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    vec3 n = normalize(faceNormal);
    vec3 toEye = normalize(eye - worldPosition);
    // Light the side the viewer sees: walls are viewed from inside, blocks from outside.
    if (dot(n, toEye) < 0.0) n = -n;
    float shade = 0.45 + 0.35 * dot(n, toEye) + 0.2 * max(dot(n, keyDirection), 0.0);
    fragColour = vec4(linearToSrgb(faceColour * mix(shade, 1.0, faceEmissive)), 1.0);
}
