#include "radiometry/scene/GltfCameras.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "radiometry/common/Error.h"

namespace radiant::detail {

std::optional<SceneCamera> readCamera(const tinygltf::Model& model, int index, const std::string& nodeName,
                                      const glm::dmat4& world, const std::string& file, std::vector<std::string>& warnings) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.cameras.size())
        throw RadiantError({file, "node '" + nodeName + "'"}, "camera " + std::to_string(index) + " out of range (camera count " +
                                                                 std::to_string(model.cameras.size()) + ")");
    const tinygltf::Camera& source = model.cameras[static_cast<std::size_t>(index)];
    SceneCamera camera;
    camera.name = !source.name.empty() ? source.name : !nodeName.empty() ? nodeName : "camera " + std::to_string(index);
    const std::string where = SourceLocation{file, "camera " + std::to_string(index) + " '" + camera.name + "'"}.str();
    if (source.type != "perspective") {
        warnings.push_back(where + ": a " + (source.type.empty() ? std::string("typeless") : source.type) +
                           " camera is ignored; only perspective cameras are read");
        return std::nullopt;
    }
    const double yfov = source.perspective.yfov;
    if (!(yfov > 0 && yfov < std::numbers::pi)) {
        warnings.push_back(where + ": yfov " + std::to_string(yfov) + " rad is not in (0, pi); camera ignored");
        return std::nullopt;
    }
    const glm::dmat3 axes(world);
    const glm::dvec3 forward = axes * glm::dvec3(0, 0, -1);
    const glm::dvec3 up = axes * glm::dvec3(0, 1, 0);
    const glm::dvec3 side = glm::cross(forward, up);
    if (!(glm::length(forward) > 0) || !(glm::length(side) > 1e-12 * glm::length(forward) * glm::length(up)) ||
        !std::isfinite(side.x + side.y + side.z)) {
        warnings.push_back(where + ": its node's transform collapses the view direction; camera ignored");
        return std::nullopt;
    }
    camera.position = glm::dvec3(world * glm::dvec4(0, 0, 0, 1));
    camera.forward = glm::normalize(forward);
    camera.up = glm::normalize(glm::cross(glm::normalize(side), camera.forward));  // square to forward under shear
    camera.verticalFieldOfView = yfov;
    camera.aspectRatio = source.perspective.aspectRatio > 0 ? source.perspective.aspectRatio : 0;
    return camera;
}

} // namespace radiant::detail
