#version 330 core
// Patch triangles in world space (metres). Smooth shading reads the per-vertex radiosity (the
// area-weighted mean of the vertex's patches on its surface, computed on upload) and lets the
// rasteriser interpolate it: Gouraud shading across the conforming mesh.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 edgeCoordinate;  // barycentric; 1 on every vertex for a quad's hidden diagonal
layout(location = 2) in int patchIndex;
layout(location = 3) in int vertexIndex;      // into the mesh's vertices

uniform mat4 viewProjection;
uniform samplerBuffer vertexRadiosity;  // rgb: W/m^2

out vec3 worldPosition;
out vec3 smoothRadiosity;
out vec3 edge;
flat out int patchId;

void main() {
    worldPosition = position;
    smoothRadiosity = texelFetch(vertexRadiosity, vertexIndex).rgb;
    edge = edgeCoordinate;
    patchId = patchIndex;
    gl_Position = viewProjection * vec4(position, 1.0);
}
