#version 330 core
// Per pixel only what cannot be interpolated: viridis of the interpolated colour-map position,
// isolines, and patch edges (wireframe, shooter outline) from the barycentric edge distance.
// Compiled in variants (FALSE_COLOUR, ISOLINES, EDGES defined or not) so that software GL pays per
// pixel only for what is shown. The framebuffer is not GL_FRAMEBUFFER_SRGB: colours written are
// already sRGB-encoded.
#ifdef LIGHT_MAP
// A grid face's colours, looked up per pixel: texel (i, atlas row + j) holds grid vertex (i, j)
// in vertexColours (bilinear filtering between vertices is Gouraud's interpolation on the
// grid), and cell (i, j) in patchColours and patchTints.
in vec2 gridCoordinate;
flat in vec3 layoutOfGrid;  // first atlas row, columns, rows
in float shade;
uniform sampler2D vertexColours;
uniform sampler2D patchColours;
uniform sampler2D patchTints;
uniform vec2 atlasSize;
#else
in vec3 displayColour;
in float legendT;
in vec4 tint;
in vec3 edge;
flat in int outlined;
#endif

uniform int wireframe;
// Isolines: u = colour-map position * scale + offset; linear legends tick at integer u, log legends
// (isolineLog = 1, u = log10 of the value) at 1, 2 and 5 of each decade. ColourLegend::isolineCoordinate
// (render/ColourScale.cpp) is the same function.
uniform float isolineScale;
uniform float isolineOffset;
uniform int isolineLog;

out vec4 fragColour;

#ifdef FALSE_COLOUR
// matplotlib's viridis at t = 0, 1/8, ..., 1 (sRGB-encoded), linearly interpolated as
// render/ColourScale.cpp does; a chain of clamped mixes, which software GL runs faster than an
// indexed table.
vec3 viridis(float t) {
    float s = clamp(t, 0.0, 1.0) * 8.0;
    vec3 c = mix(vec3(68, 1, 84), vec3(71, 45, 123), clamp(s, 0.0, 1.0));
    c = mix(c, vec3(59, 82, 139), clamp(s - 1.0, 0.0, 1.0));
    c = mix(c, vec3(44, 114, 142), clamp(s - 2.0, 0.0, 1.0));
    c = mix(c, vec3(33, 145, 140), clamp(s - 3.0, 0.0, 1.0));
    c = mix(c, vec3(40, 174, 128), clamp(s - 4.0, 0.0, 1.0));
    c = mix(c, vec3(94, 201, 98), clamp(s - 5.0, 0.0, 1.0));
    c = mix(c, vec3(173, 220, 48), clamp(s - 6.0, 0.0, 1.0));
    c = mix(c, vec3(253, 231, 37), clamp(s - 7.0, 0.0, 1.0));
    return c / 255.0;
}

#ifdef ISOLINES
// Integer exactly at each legend tick, continuous in between.
float isolineCoordinate(float t) {
    float u = t * isolineScale + isolineOffset;
    if (isolineLog == 0) return u;
    float decade = floor(u);
    float m = pow(10.0, u - decade);
    float piece = m < 2.0 ? m - 1.0 : (m < 5.0 ? 1.0 + (m - 2.0) / 3.0 : 2.0 + (m - 5.0) / 5.0);
    return 3.0 * decade + piece;
}
#endif
#endif

void main() {
#ifdef LIGHT_MAP
    ivec2 cell = ivec2(clamp(floor(gridCoordinate), vec2(0.0), layoutOfGrid.yz - 1.0)) + ivec2(0, int(layoutOfGrid.x));
    // One lookup per pixel: each is a good part of what software GL spends on a pixel.
#ifdef FLAT
    vec4 sampled = texelFetch(patchColours, cell, 0);
#else
    vec4 sampled = texture(vertexColours, (gridCoordinate + vec2(0.5, layoutOfGrid.x + 0.5)) / atlasSize);
#endif
    vec3 displayColour = sampled.rgb * shade;
    float legendT = sampled.a;
#ifdef TINTS
    vec4 tintAndOutline = texelFetch(patchTints, cell, 0);
#else
    vec4 tintAndOutline = vec4(0.0);  // no patch is tinted or outlined
#endif
    // 8-bit texels: alpha = amount / 2, + 1/2 when outlined (tintTexel, render/display/DisplayBuffers.h).
    int outlined = tintAndOutline.a >= 0.5 ? 1 : 0;
    vec4 tint = vec4(tintAndOutline.rgb, 2.0 * (tintAndOutline.a - 0.5 * float(outlined)));
#endif
#ifdef FALSE_COLOUR
    vec3 colour = viridis(legendT);
#ifdef ISOLINES
    // A line about one pixel wide where the coordinate crosses an integer (a legend tick).
    float isolineU = isolineCoordinate(legendT);
    float linePixels = abs(fract(isolineU + 0.5) - 0.5) / max(fwidth(isolineU), 1e-6);
    colour = mix(colour, vec3(0.02), 0.75 * (1.0 - smoothstep(0.5, 1.5, linePixels)));
#endif
#else
    vec3 colour = displayColour;
#endif
    colour = mix(colour, tint.rgb, tint.a);
#ifdef EDGES
    // Distance to the patch's drawn edges in pixels (a quad's diagonal never gets near 0).
#ifdef LIGHT_MAP
    // The patch edges are the grid's lines.
    vec2 toLine = min(fract(gridCoordinate), 1.0 - fract(gridCoordinate)) / max(fwidth(gridCoordinate), vec2(1e-6));
    float edgeDistance = min(toLine.x, toLine.y);
#else
    vec3 edgePixels = edge / max(fwidth(edge), vec3(1e-6));
    float edgeDistance = min(min(edgePixels.x, edgePixels.y), edgePixels.z);
#endif
    if (outlined != 0) colour = mix(colour, vec3(1.0, 0.35, 0.0), 1.0 - smoothstep(2.0, 3.5, edgeDistance));
    if (wireframe != 0) colour = mix(colour, vec3(0.06, 0.07, 0.09), 0.6 * (1.0 - smoothstep(0.4, 1.4, edgeDistance)));
#endif
    fragColour = vec4(colour, 1.0);
}
