#version 330 core
// Reflectance as colour, dimmed a little where the face turns away from the eye so creases read
// (a "headlight"; not a radiometric quantity). Colours are linear; the framebuffer wants sRGB.
in vec3 worldPosition;
flat in vec3 faceNormal;
flat in vec3 faceColour;
flat in float faceEmissive;

uniform vec3 eye;

out vec4 fragColour;

vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    float facing = abs(dot(normalize(faceNormal), normalize(eye - worldPosition)));
    float headlight = mix(0.55 + 0.45 * facing, 1.0, faceEmissive);
    fragColour = vec4(linearToSrgb(faceColour * headlight), 1.0);
}
