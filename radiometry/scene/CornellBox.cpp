#include <algorithm>
#include <array>

#include <glm/geometric.hpp>

#include "radiometry/scene/BuiltinScenes.h"

namespace radiant {
namespace {

constexpr double kMillimetre = 0.001;

Face faceFromMillimetres(std::initializer_list<glm::dvec3> cornersMm) {
    Face face;
    for (const glm::dvec3& c : cornersMm) face.vertices.push_back(c * kMillimetre);
    face.updateGeometry();
    return face;
}

/// A block: its top (given counter-clockwise seen from above) and four sides down to the floor,
/// each side wound so its normal points out of the block.
std::vector<Face> blockFaces(const std::array<glm::dvec3, 4>& topMm) {
    std::vector<Face> faces{faceFromMillimetres({topMm[0], topMm[1], topMm[2], topMm[3]})};
    glm::dvec3 centre(0.0);
    for (const auto& v : topMm) centre += glm::dvec3(v.x, v.y / 2, v.z) * kMillimetre / 4.0;
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec3 a = topMm[i], b = topMm[(i + 1) % 4];
        Face side = faceFromMillimetres({a, {a.x, 0, a.z}, {b.x, 0, b.z}, b});
        glm::dvec3 sideCentre(0.0);
        for (const auto& v : side.vertices) sideCentre += v / 4.0;
        if (glm::dot(side.normal, sideCentre - centre) < 0) {
            std::reverse(side.vertices.begin(), side.vertices.end());
            side.updateGeometry();
        }
        faces.push_back(std::move(side));
    }
    return faces;
}

} // namespace

Scene makeCornellBox() {
    Scene scene;
    scene.name = "cornell-box";
    // Common RGB stand-ins for the measured spectra; the light's exitance keeps the (17, 12, 4) ratio.
    scene.materials = {
        {"white", {0.73, 0.71, 0.68}, ExitanceRgb{}},
        {"red", {0.63, 0.065, 0.05}, ExitanceRgb{}},
        {"green", {0.14, 0.45, 0.09}, ExitanceRgb{}},
        {"light", {0.78, 0.78, 0.78}, ExitanceRgb{Rgb{17.0, 12.0, 4.0}}},
    };
    constexpr std::size_t white = 0, red = 1, green = 2, light = 3;
    const auto add = [&](std::string name, std::size_t material, std::vector<Face> faces) {
        scene.surfaces.push_back({std::move(name), material, std::move(faces), "built-in cornell-box"});
    };

    add("floor", white, {faceFromMillimetres({{552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2}})});

    // The ceiling with the light's rectangle cut out: a 3 x 3 grid of quads without its centre, so
    // every shared edge is a whole edge and meshing stays conforming.
    const double xs[] = {556, 343, 213, 0};
    const double zs[] = {0, 227, 332, 559.2};
    std::vector<Face> ceiling;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
            if (i == 1 && k == 1) continue;
            ceiling.push_back(faceFromMillimetres({{xs[i], 548.8, zs[k]},
                                                   {xs[i], 548.8, zs[k + 1]},
                                                   {xs[i + 1], 548.8, zs[k + 1]},
                                                   {xs[i + 1], 548.8, zs[k]}}));
        }
    add("ceiling", white, std::move(ceiling));
    add("light", light, {faceFromMillimetres({{343, 548.8, 227}, {343, 548.8, 332}, {213, 548.8, 332}, {213, 548.8, 227}})});
    add("back wall", white,
        {faceFromMillimetres({{549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556, 548.8, 559.2}})});
    add("right wall", green, {faceFromMillimetres({{0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}})});
    // The measured left wall is not quite planar (its corners leave a plane by about 1.6 mm): two
    // triangles keep it watertight with the floor and ceiling, where flattening it would open a gap.
    add("left wall", red,
        {faceFromMillimetres({{552.8, 0, 0}, {549.6, 0, 559.2}, {556, 548.8, 559.2}}),
         faceFromMillimetres({{552.8, 0, 0}, {556, 548.8, 559.2}, {556, 548.8, 0}})});
    add("short block", white, blockFaces({{{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}}));
    add("tall block", white, blockFaces({{{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}}));
    return scene;
}

} // namespace radiant
