#version 330 core
// Patch triangles in world space (metres). Display colours arrive ready-made as vertex attributes
// (render/display/DisplayModel works them out on the CPU when the radiosity or the display settings change:
// ACES-fitted tone curve and sRGB encoding, or the position on the colour map): software GL
// (llvmpipe) runs shaders on the CPU, where a pow() or a buffer-texture fetch per vertex or pixel
// per frame cost several times the whole frame. Smooth shading is Gouraud's: the colours of the
// per-vertex radiosity interpolated across the conforming mesh; flat shading gives a patch's
// vertices its own colour.
// LIGHT_MAP: a grid face (render/display/FaceGrids.h) drawn as one quad; its colours come per pixel from
// atlas textures (patch.frag.glsl), so this passes on only the grid coordinates.
// Back faces are culled (PatchRenderer): every face drawn is seen from its front, the side its
// normal points to, so two coincident sides of a two-sided face need no test here.
#ifdef LIGHT_MAP
layout(location = 0) in vec3 position;
layout(location = 2) in vec3 normal;      // the face's, unit
layout(location = 5) in vec2 grid;        // grid coordinates, (0, 0) .. (columns, rows)
layout(location = 6) in vec3 gridLayout;  // first atlas row, columns, rows

uniform mat4 viewProjection;
uniform int hasRadiosity;
uniform vec3 eye;
uniform vec3 keyDirection;

out vec2 gridCoordinate;
flat out vec3 layoutOfGrid;
out float shade;

void main() {
    shade = 1.0;
    if (hasRadiosity == 0) {
        vec3 toEye = normalize(eye - position);
        vec3 n = normalize(normal);
        shade = 0.45 + 0.35 * dot(n, toEye) + 0.2 * max(dot(n, keyDirection), 0.0);
    }
    gridCoordinate = grid;
    layoutOfGrid = gridLayout;
    gl_Position = viewProjection * vec4(position, 1.0);
}
#else
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 edgeCoordinate;  // barycentric; held at 1 for a fan's inner diagonal
layout(location = 2) in vec3 normal;          // the patch's, unit
layout(location = 3) in vec4 colour;          // rgb: sRGB display colour; a: position on the colour map
layout(location = 4) in vec4 tintAndOutline;  // rgb: colour to mix toward; a: amount, +2 when outlined

uniform mat4 viewProjection;
uniform int hasRadiosity;
uniform vec3 eye;
uniform vec3 keyDirection;   // unit: a key light fixed to the camera, for the base view only

out vec3 displayColour;  // sRGB-encoded
out float legendT;
out vec4 tint;
out vec3 edge;
flat out int outlined;

void main() {
    displayColour = colour.rgb;
    if (hasRadiosity == 0) {
        // No solution yet: the materials, dimmed where the face turns away (a display aid, so the
        // dimming acts on the encoded colour).
        vec3 toEye = normalize(eye - position);
        vec3 n = normalize(normal);
        displayColour *= 0.45 + 0.35 * dot(n, toEye) + 0.2 * max(dot(n, keyDirection), 0.0);
    }
    legendT = colour.a;
    outlined = tintAndOutline.a >= 2.0 ? 1 : 0;
    tint = vec4(tintAndOutline.rgb, tintAndOutline.a - 2.0 * float(outlined));
    edge = edgeCoordinate;
    gl_Position = viewProjection * vec4(position, 1.0);
}
#endif
