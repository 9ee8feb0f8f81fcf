#version 330 core
// A lecture demo's line segment as a quad of widthPixels on screen (core GL draws only 1-pixel lines):
// each corner knows both ends, finds the segment's direction in pixels and steps out half the width
// sideways, and half the width past its end so joined segments meet without notches.
layout(location = 0) in vec3 from;
layout(location = 1) in vec3 to;
layout(location = 2) in vec4 colour;
layout(location = 3) in vec2 corner;  // x: 0 at from, 1 at to; y: the side, -1 or +1
layout(location = 4) in float widthPixels;

uniform mat4 viewProjection;
uniform vec2 viewportPixels;

out vec4 vertexColour;
out float contourCoordinate;

void main() {
    vec4 a = viewProjection * vec4(from, 1.0);
    vec4 b = viewProjection * vec4(to, 1.0);
    // Ends behind the eye would flip on the screen; the demos keep their lines in front of it.
    a.w = max(a.w, 1e-4);
    b.w = max(b.w, 1e-4);
    vec2 halfViewport = 0.5 * viewportPixels;
    vec2 screenA = a.xy / a.w * halfViewport;
    vec2 screenB = b.xy / b.w * halfViewport;
    vec2 along = screenB - screenA;
    along = length(along) > 1e-4 ? normalize(along) : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    vec4 clip = corner.x < 0.5 ? a : b;
    float lengthwise = corner.x < 0.5 ? -1.0 : 1.0;
    vec2 offsetPixels = 0.5 * widthPixels * (corner.y * across + lengthwise * along);
    clip.xy += offsetPixels / halfViewport * clip.w;
    // A hair nearer than the surfaces they lie on, so lines win the depth test against them.
    clip.z -= 2e-4 * clip.w;
    gl_Position = clip;
    vertexColour = colour;
    contourCoordinate = -1.0;
}
