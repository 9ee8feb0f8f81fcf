#include "render/SceneTriangles.h"

#include <algorithm>

namespace radiant::render {

glm::vec3 displayColour(const Material& material) {
    if (material.emits()) {
        const Rgb& e = material.exitance.value();
        return glm::vec3(e / std::max({e.x, e.y, e.z}));
    }
    return glm::vec3(material.reflectance);
}

std::vector<FlatVertex> flatTriangles(const Scene& scene) {
    std::vector<FlatVertex> vertices;
    for (const Surface& surface : scene.surfaces) {
        const Material& material = scene.materials.at(surface.material);
        const glm::vec3 colour = displayColour(material);
        const float emissive = material.emits() ? 1.0f : 0.0f;
        for (const Face& face : surface.faces) {
            const glm::vec3 normal(face.normal);
            for (std::size_t i = 1; i + 1 < face.vertices.size(); ++i)
                for (const glm::dvec3& corner : {face.vertices[0], face.vertices[i], face.vertices[i + 1]})
                    vertices.push_back({glm::vec3(corner), normal, colour, emissive});
        }
    }
    return vertices;
}

} // namespace radiant::render
