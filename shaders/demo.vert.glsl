#version 330 core
// A lecture demo's triangles (render/demo/DemoRenderer): world positions in metres, colours as given.
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;
layout(location = 2) in float contour;

uniform mat4 viewProjection;

out vec4 vertexColour;
out float contourCoordinate;

void main() {
    vertexColour = colour;
    contourCoordinate = contour;
    gl_Position = viewProjection * vec4(position, 1.0);
}
