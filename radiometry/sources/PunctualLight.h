#pragma once
// Lights without area (glTF's KHR_lights_punctual) in SI units, per band:
//  - point: the lecture's isotropic point source, E = I cos(theta) / r^2 at a surface that sees it;
//  - spot: the same with I falling off across glTF's cone, full inside innerCone, zero beyond
//    outerCone, and in between glTF's recommended smooth step: t = (cos a - cos outer) /
//    (cos inner - cos outer) clamped to [0, 1], then t^2, for a the angle off the spot's axis;
//  - directional (glTF's sun): a distant source, E = E_normal cos(theta) wherever nothing shades it.
// Every solver takes their direct irradiance H as a source term (B = E + rho (H + F B)): the light
// reaches each surface once, and its reflection joins the radiosity system like emission.
#include <string>

#include <glm/vec3.hpp>

#include "radiometry/units/Quantity.h"

namespace radiant {

enum class PunctualLightType { Point, Spot, Directional };

struct PunctualLight {
    std::string name;
    PunctualLightType type = PunctualLightType::Point;
    glm::dvec3 position{0.0};         ///< m; point and spot
    glm::dvec3 direction{0, 0, -1};   ///< unit, where the light goes; spot and directional
    IntensityRgb intensity{};         ///< W/sr per band; point and spot (on the spot's axis)
    IrradianceRgb normalIrradiance{}; ///< W/m^2 per band on a surface facing it; directional
    double innerConeAngle = 0;        ///< rad, spot
    double outerConeAngle = 0.7853981633974483;  ///< rad, spot (glTF's default, pi / 4)
};

} // namespace radiant
