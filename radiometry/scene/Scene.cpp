#include "radiometry/scene/Scene.h"

#include <glm/geometric.hpp>

namespace radiant {

void Face::updateGeometry() {
    // Newell's method: robust for any planar polygon, and its length is twice the area.
    glm::dvec3 n(0.0);
    const std::size_t count = vertices.size();
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3& a = vertices[i];
        const glm::dvec3& b = vertices[(i + 1) % count];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    const double len = glm::length(n);
    area = 0.5 * len;
    if (len > 0) normal = n / len;
}

double Surface::area() const {
    double sum = 0;
    for (const Face& f : faces) sum += f.area;
    return sum;
}

double Scene::totalArea() const {
    double sum = 0;
    for (const Surface& s : surfaces) sum += s.area();
    return sum;
}

std::size_t Scene::faceCount() const {
    std::size_t n = 0;
    for (const Surface& s : surfaces) n += s.faces.size();
    return n;
}

std::size_t Scene::doubleSidedSurfaceCount() const {
    std::size_t n = 0;
    for (const Surface& s : surfaces) n += s.side == FaceSide::Front ? 1 : 0;
    return n;
}

bool Scene::emits() const {
    for (const Surface& s : surfaces)
        if (s.material < materials.size() && materials[s.material].emits() && s.area() > 0) return true;
    return false;
}

std::size_t Scene::findSurface(const std::string& surfaceName) const {
    for (std::size_t i = 0; i < surfaces.size(); ++i)
        if (surfaces[i].name == surfaceName) return i;
    return npos;
}

} // namespace radiant
