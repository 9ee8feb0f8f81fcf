#include "render/hemicube/HemicubeFrame.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace radiant::render {

HemicubeFrame::HemicubeFrame(const glm::dvec3& normal, double twist) {
    const HemisphereFrame untwisted(normal);
    const double c = std::cos(twist), s = std::sin(twist);
    tangent_ = c * untwisted.tangent() + s * untwisted.bitangent();
    bitangent_ = -s * untwisted.tangent() + c * untwisted.bitangent();
    normal_ = untwisted.normal();
}

glm::dvec3 HemicubeFrame::toWorld(const glm::dvec3& local) const {
    return local.x * tangent_ + local.y * bitangent_ + local.z * normal_;
}

glm::dvec3 HemicubeFrame::toLocal(const glm::dvec3& world) const {
    return {glm::dot(world, tangent_), glm::dot(world, bitangent_), glm::dot(world, normal_)};
}

} // namespace radiant::render
