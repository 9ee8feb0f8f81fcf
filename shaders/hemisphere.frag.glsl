#version 330 core
// Paints the dome with what the point sees: an equidistant fisheye image of the hemicube, plus the
// theta/phi grid of d omega cells drawn here, about a pixel wide at any zoom. The image is
// sRGB-encoded, as the framebuffer expects (no GL_FRAMEBUFFER_SRGB).
in vec2 imagePosition;
in vec2 gridCells;
in float facing;

uniform sampler2D sky;
uniform float frontOpacity;
uniform float backOpacity;
uniform int grid;

out vec4 fragColour;

// Coverage of a line about 1.5 px wide where the coordinate u crosses an integer.
float lineAt(float u, float pixelsPerUnit) {
    float distancePx = abs(fract(u + 0.5) - 0.5) * pixelsPerUnit;
    return 1.0 - smoothstep(0.5, 1.3, distancePx);
}

void main() {
    vec4 seen = texture(sky, imagePosition);
    vec3 colour = seen.rgb;
    float line = 0.0;
    if (grid != 0) {
        vec2 cellsPerPixel = max(fwidth(gridCells), vec2(1e-6));
        float onTheta = lineAt(gridCells.x, 1.0 / cellsPerPixel.x);
        // Where the meridians crowd together at the zenith they fade instead of filling it grey.
        float pixelsPerPhiCell = 1.0 / cellsPerPixel.y;
        float onPhi = lineAt(gridCells.y, pixelsPerPhiCell) * smoothstep(3.0, 6.0, pixelsPerPhiCell);
        line = max(onTheta, onPhi);
        colour = mix(colour, vec3(0.77, 0.77, 0.8), 0.6 * line);
    }
    // A little darker where the dome turns away from the eye, so it reads as a dome.
    colour *= mix(0.75, 1.0, facing);
    float opacity = gl_FrontFacing ? frontOpacity : backOpacity;
    // The image is see-through where the point sees open sky; the grid stays visible there.
    fragColour = vec4(colour, opacity * max(seen.a, 0.8 * line));
}
