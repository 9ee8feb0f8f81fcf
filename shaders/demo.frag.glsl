#version 330 core
// A lecture demo's triangles and lines: the interpolated colour (sRGB-encoded, as the framebuffer
// expects), darkened along an isoline where the contour coordinate crosses an integer, about 1.5
// pixels wide at any zoom (negative coordinates: no isolines).
in vec4 vertexColour;
in float contourCoordinate;

out vec4 fragColour;

void main() {
    vec3 colour = vertexColour.rgb;
    if (contourCoordinate >= 0.0) {
        float pixelsPerUnit = 1.0 / max(fwidth(contourCoordinate), 1e-6);
        float distancePx = abs(fract(contourCoordinate + 0.5) - 0.5) * pixelsPerUnit;
        float line = 1.0 - smoothstep(0.6, 1.4, distancePx);
        colour = mix(colour, vec3(0.05), 0.75 * line);
    }
    fragColour = vec4(colour, vertexColour.a);
}
