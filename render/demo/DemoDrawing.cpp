#include "render/demo/DemoDrawing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace radiant::render {

void DemoDrawing::quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                       const glm::vec4& colour) {
    triangle({a, colour}, {b, colour}, {c, colour});
    triangle({a, colour}, {c, colour}, {d, colour});
}

void DemoDrawing::dashedLine(const glm::vec3& from, const glm::vec3& to, float dash, const glm::vec4& colour,
                             float widthPixels) {
    const float length = glm::length(to - from);
    if (!(length > 0.0f) || !(dash > 0.0f)) return;
    const glm::vec3 step = (to - from) / length;
    for (float s = 0.0f; s < length; s += 2.0f * dash) line(from + s * step, from + std::min(s + dash, length) * step, colour, widthPixels);
}

void DemoDrawing::loop(const std::vector<glm::vec3>& points, const glm::vec4& colour, float widthPixels) {
    for (std::size_t i = 0; i < points.size(); ++i) line(points[i], points[(i + 1) % points.size()], colour, widthPixels);
}

void DemoDrawing::circle(const glm::vec3& centre, const glm::vec3& u, const glm::vec3& v, float radius,
                         const glm::vec4& colour, float widthPixels, int count) {
    std::vector<glm::vec3> points;
    for (int i = 0; i < count; ++i) {
        const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(count);
        points.push_back(centre + radius * (std::cos(phi) * u + std::sin(phi) * v));
    }
    loop(points, colour, widthPixels);
}

void DemoDrawing::sphere(const glm::vec3& centre, float radius, const glm::vec4& colour, int rings) {
    const auto at = [&](int ring, int segment) {
        const float theta = std::numbers::pi_v<float> * static_cast<float>(ring) / static_cast<float>(rings);
        const float phi = std::numbers::pi_v<float> * static_cast<float>(segment) / static_cast<float>(rings);
        const glm::vec3 n{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
        // Lit from above-front so the ball reads as round, not as a flat disc.
        const float shade = 0.55f + 0.45f * std::max(0.0f, glm::dot(n, glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f))));
        return DemoVertex{centre + radius * n, glm::vec4(glm::vec3(colour) * shade, colour.w)};
    };
    for (int ring = 0; ring < rings; ++ring)
        for (int segment = 0; segment < 2 * rings; ++segment) {
            const DemoVertex a = at(ring, segment), b = at(ring + 1, segment), c = at(ring + 1, segment + 1),
                             d = at(ring, segment + 1);
            triangle(a, b, c);
            triangle(a, c, d);
        }
}

void DemoDrawing::arrow(const glm::vec3& from, const glm::vec3& to, float head, const glm::vec4& colour,
                        float widthPixels) {
    line(from, to, colour, widthPixels);
    const glm::vec3 along = to - from;
    const float length = glm::length(along);
    if (!(length > 0.0f)) return;
    const glm::vec3 d = along / length;
    // Two barbs in a plane that contains the shaft; any side vector not parallel to it will do.
    const glm::vec3 helper = std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 side = glm::normalize(glm::cross(d, helper));
    const glm::vec3 side2 = glm::cross(d, side);
    for (const glm::vec3& s : {side, -side, side2, -side2}) line(to, to - head * d + 0.45f * head * s, colour, widthPixels);
}

} // namespace radiant::render
