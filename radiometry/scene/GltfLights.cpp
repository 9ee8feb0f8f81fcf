#include "radiometry/scene/GltfLights.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "radiometry/common/Error.h"
#include "radiometry/units/Photometry.h"

namespace radiant::detail {

namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

} // namespace

int nodeLightIndex(const tinygltf::Node& node, const std::string& nodeName, const std::string& file) {
    const auto extension = node.extensions.find("KHR_lights_punctual");
    if (extension == node.extensions.end()) return -1;
    const tinygltf::Value& light = extension->second.Get("light");
    if (!light.IsNumber() || light.GetNumberAsDouble() != std::floor(light.GetNumberAsDouble()))
        throw RadiantError({file, "node '" + nodeName + "'"}, "KHR_lights_punctual names no light index");
    const double index = light.GetNumberAsDouble();
    if (index < 0 || index > 1e9)
        throw RadiantError({file, "node '" + nodeName + "'"}, "KHR_lights_punctual light " + number(index) + " out of range");
    return static_cast<int>(index);
}

std::optional<PunctualLight> readLight(const tinygltf::Model& model, int index, const std::string& nodeName,
                                       const glm::dmat4& world, const std::string& file, std::vector<std::string>& warnings) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.lights.size())
        throw RadiantError({file, "node '" + nodeName + "'"}, "KHR_lights_punctual light " + std::to_string(index) +
                                                                 " out of range (light count " + std::to_string(model.lights.size()) + ")");
    const tinygltf::Light& source = model.lights[static_cast<std::size_t>(index)];
    PunctualLight light;
    light.name = !source.name.empty() ? source.name : !nodeName.empty() ? nodeName : "light " + std::to_string(index);
    const SourceLocation where{file, "light " + std::to_string(index) + " '" + light.name + "'"};
    if (source.type == "point") {
        light.type = PunctualLightType::Point;
    } else if (source.type == "spot") {
        light.type = PunctualLightType::Spot;
    } else if (source.type == "directional") {
        light.type = PunctualLightType::Directional;
    } else {
        warnings.push_back(where.str() + ": type '" + source.type + "' is not point, spot or directional; light ignored");
        return std::nullopt;
    }
    if (!std::isfinite(source.intensity) || source.intensity < 0)
        throw RadiantError(where, "intensity " + number(source.intensity) + " must be a finite value >= 0 (" +
                                      (light.type == PunctualLightType::Directional ? "lx" : "cd") + ")");
    Rgb colour(1.0);
    if (!source.color.empty()) {
        if (source.color.size() != 3) throw RadiantError(where, "color has " + std::to_string(source.color.size()) + " values, expected 3");
        for (int band = 0; band < 3; ++band) {
            const double c = source.color[static_cast<std::size_t>(band)];
            if (!std::isfinite(c) || c < 0) throw RadiantError(where, "color band " + std::to_string(band) + " is " + number(c) + ", expected >= 0");
            colour[band] = c;
        }
    }
    if (source.intensity == 0 || !(luminanceWeighted(colour) > 0)) {
        warnings.push_back(where.str() + ": gives no light (intensity " + number(source.intensity) + ", colour luminance " +
                           number(luminanceWeighted(colour)) + "); light ignored");
        return std::nullopt;
    }
    if (source.range > 0)
        warnings.push_back(where.str() + ": range " + number(source.range) +
                           " m ignored: the light falls off by the inverse-square law at every distance");

    const glm::dvec3 direction = glm::dmat3(world) * glm::dvec3(0, 0, -1);
    const double length = glm::length(direction);
    if (light.type != PunctualLightType::Point && !(length > 0 && std::isfinite(length))) {
        warnings.push_back(where.str() + ": its node's transform collapses the light's direction; light ignored");
        return std::nullopt;
    }
    if (light.type != PunctualLightType::Point) light.direction = direction / length;
    light.position = glm::dvec3(world * glm::dvec4(0, 0, 0, 1));
    if (!std::isfinite(light.position.x + light.position.y + light.position.z))
        throw RadiantError(where, "its node's transform places it at a non-finite position");
    if (light.type == PunctualLightType::Directional) {
        light.normalIrradiance = IrradianceRgb(bandsForLuminous(source.intensity, colour));
        return light;
    }
    light.intensity = IntensityRgb(bandsForLuminous(source.intensity, colour));
    if (light.type == PunctualLightType::Spot) {
        const double inner = source.spot.innerConeAngle, outer = source.spot.outerConeAngle;
        if (!(inner >= 0 && inner < outer && outer <= std::numbers::pi / 2))
            throw RadiantError(where, "spot cone angles inner " + number(inner) + " and outer " + number(outer) +
                                          " rad must satisfy 0 <= inner < outer <= pi/2");
        light.innerConeAngle = inner;
        light.outerConeAngle = outer;
    }
    return light;
}

} // namespace radiant::detail
