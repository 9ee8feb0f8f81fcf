#version 330 core
// Radiosity (W/m^2) to display colour. render/ColourScale.cpp holds the same formulas in C++ for the
// tests and the legend: keep the two in step.
//   tone-mapped: x = B * exposureScale per band, Narkowicz's ACES fit, then sRGB encoding;
//   false colour: total radiosity B_r + B_g + B_b on the legend's linear or log10 range, viridis.
// The framebuffer is not GL_FRAMEBUFFER_SRGB, so the colours written are already sRGB-encoded.
in vec3 worldPosition;
in vec3 smoothRadiosity;
in vec3 edge;
flat in int patchId;

uniform samplerBuffer patchRadiosity;  // rgb: W/m^2; a: 1 where it changed in the last update
uniform samplerBuffer patchStyle;      // rgb: linear base colour (no solution yet); a: importance in [0, 1]

uniform vec3 eye;
uniform vec3 keyDirection;  // unit: a key light fixed to the camera, for the base view only
uniform int hasRadiosity;
uniform int smoothShading;
uniform float exposureScale;  // 1/(W/m^2)
uniform int falseColour;
uniform int logScale;
uniform float legendMin;      // W/m^2
uniform float legendMax;      // W/m^2
uniform int isolines;
uniform float isolineStep;    // W/m^2 between lines on a linear legend (log legends: one per decade)
uniform int wireframe;
uniform int highlight;        // outline the shooter, tint what changed
uniform int shooter;          // patch index, or -1
uniform int showImportance;

out vec4 fragColour;

vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

vec3 acesFitted(vec3 x) {
    x = max(x, 0.0);
    return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// matplotlib's viridis at t = 0, 1/8, ..., 1 (sRGB-encoded).
const vec3 kViridis[9] = vec3[9](vec3(68, 1, 84) / 255.0, vec3(71, 45, 123) / 255.0, vec3(59, 82, 139) / 255.0,
                                 vec3(44, 114, 142) / 255.0, vec3(33, 145, 140) / 255.0, vec3(40, 174, 128) / 255.0,
                                 vec3(94, 201, 98) / 255.0, vec3(173, 220, 48) / 255.0, vec3(253, 231, 37) / 255.0);

vec3 viridis(float t) {
    float s = clamp(t, 0.0, 1.0) * 8.0;
    int i = min(int(s), 7);
    return mix(kViridis[i], kViridis[i + 1], s - float(i));
}

float legendPosition(float value) {
    if (logScale != 0) {
        float lo = log(legendMin) / log(10.0), hi = log(legendMax) / log(10.0);
        return value > 0.0 ? (log(value) / log(10.0) - lo) / (hi - lo) : 0.0;
    }
    return (value - legendMin) / (legendMax - legendMin);
}

// 1 on a line about one pixel wide where u crosses an integer, fading out over the next pixel.
float lineAt(float u) {
    float distancePixels = abs(fract(u + 0.5) - 0.5) / max(fwidth(u), 1e-6);
    return 1.0 - smoothstep(0.5, 1.5, distancePixels);
}

void main() {
    vec4 patchData = texelFetch(patchRadiosity, patchId);
    vec4 style = texelFetch(patchStyle, patchId);
    vec3 colour;
    if (hasRadiosity == 0) {
        // No solution yet: the materials, dimmed where the face turns away, as the flat view does.
        vec3 n = normalize(cross(dFdx(worldPosition), dFdy(worldPosition)));
        vec3 toEye = normalize(eye - worldPosition);
        if (dot(n, toEye) < 0.0) n = -n;
        float shade = 0.45 + 0.35 * dot(n, toEye) + 0.2 * max(dot(n, keyDirection), 0.0);
        colour = linearToSrgb(style.rgb * shade);
    } else {
        vec3 radiosity = smoothShading != 0 ? smoothRadiosity : patchData.rgb;
        if (falseColour != 0) {
            float total = radiosity.r + radiosity.g + radiosity.b;
            colour = viridis(legendPosition(total));
            if (isolines != 0) {
                float u = logScale != 0 ? log(max(total, 1e-30)) / log(10.0) : total / isolineStep;
                colour = mix(colour, vec3(0.02), 0.75 * lineAt(u));
            }
        } else {
            colour = linearToSrgb(acesFitted(radiosity * exposureScale));
        }
    }
    if (showImportance != 0) colour = mix(colour, vec3(1.0, 0.1, 0.8), 0.6 * style.a);

    // Distance to the patch's drawn edges in pixels (a quad's diagonal never gets near 0).
    vec3 edgePixels = edge / max(fwidth(edge), vec3(1e-6));
    float edgeDistance = min(min(edgePixels.x, edgePixels.y), edgePixels.z);
    if (highlight != 0 && hasRadiosity != 0) {
        if (patchData.a > 0.5) colour = mix(colour, vec3(1.0, 0.55, 0.15), 0.22);
        if (patchId == shooter) {
            colour = mix(colour, vec3(1.0, 0.45, 0.0), 0.35);
            colour = mix(colour, vec3(1.0, 0.35, 0.0), 1.0 - smoothstep(2.0, 3.5, edgeDistance));
        }
    }
    if (wireframe != 0) colour = mix(colour, vec3(0.06, 0.07, 0.09), 0.6 * (1.0 - smoothstep(0.4, 1.4, edgeDistance)));
    fragColour = vec4(colour, 1.0);
}
