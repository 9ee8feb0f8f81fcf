#include "radiometry/scene/View.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "radiometry/geometry/RayCaster.h"

namespace radiant {

View cornellView() {
    constexpr double focalLengthMm = 35.0, filmHeightMm = 25.0;
    return {{0.278, 0.273, -0.8}, {0.278, 0.273, 0.0}, {0, 1, 0}, 2.0 * std::atan(filmHeightMm / 2.0 / focalLengthMm), 1.0};
}

View framingView(const glm::dvec3& lo, const glm::dvec3& hi) {
    View view = cornellView();
    const glm::dvec3 forward = glm::normalize(glm::dvec3(-0.55, -0.45, 1.0));
    const glm::dvec3 centre = (lo + hi) / 2.0;
    const double radius = std::max(glm::length(hi - lo) / 2.0, 1e-3);
    const double distance = radius / std::sin(view.verticalFov / 2.0);
    view.eye = centre - forward * distance;
    view.target = centre;
    return view;
}

bool sceneBounds(const Scene& scene, glm::dvec3& lo, glm::dvec3& hi) {
    lo = glm::dvec3(std::numeric_limits<double>::max());
    hi = -lo;
    bool any = false;
    for (const Surface& surface : scene.surfaces)
        for (const Face& face : surface.faces)
            for (const glm::dvec3& v : face.vertices) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
                any = true;
            }
    return any;
}

namespace {

/// Share of a coarse grid of eye rays through the view that land on a face's front: a face's back
/// is no surface that reflects anything, so a closed room seen from outside shows nothing.
double frontHitShare(const RayCaster& rays, const View& view) {
    constexpr int n = 24;
    const glm::dvec3 forward = glm::normalize(view.target - view.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, view.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double halfHeight = std::tan(view.verticalFov / 2.0);
    int front = 0;
    for (int row = 0; row < n; ++row)
        for (int column = 0; column < n; ++column) {
            const double u = (2.0 * (column + 0.5) / n - 1.0) * halfHeight * view.aspect;
            const double v = (2.0 * (row + 0.5) / n - 1.0) * halfHeight;
            const glm::dvec3 direction = forward + u * right + v * up;
            const auto hit = rays.intersect(view.eye, direction);
            if (hit && glm::dot(hit->normal, direction) < 0) ++front;
        }
    return static_cast<double>(front) / (n * n);
}

/// From inside the box [lo, hi], as one stands in a doorway: at mid-height near its -z, +x side
/// (the framing view's side), looking level at the centre with a wide field, so floor and ceiling
/// are both in view.
View insideView(const glm::dvec3& lo, const glm::dvec3& hi) {
    const View outside = framingView(lo, hi);
    const glm::dvec3 centre = (lo + hi) / 2.0;
    glm::dvec3 level = centre - outside.eye;
    level.y = 0;
    View view = outside;
    view.eye = centre - 0.8 * (hi - lo) / 2.0 * glm::normalize(level);
    view.target = centre;
    view.verticalFov = 1.4;
    return view;
}

} // namespace

namespace {

/// The Cornell camera or the scene's own glTF camera, when the scene has one of them.
std::optional<View> givenView(const Scene& scene) {
    if (scene.name == "cornell-box") return cornellView();
    // A glTF camera is where the scene's author meant it to be seen from.
    if (!scene.cameras.empty() && scene.cameras.front().verticalFieldOfView > 0) {
        const SceneCamera& camera = scene.cameras.front();
        View view;
        view.eye = camera.position;
        view.target = camera.position + camera.forward;
        view.up = camera.up;
        view.verticalFov = camera.verticalFieldOfView;
        if (camera.aspectRatio > 0) view.aspect = camera.aspectRatio;
        return view;
    }
    return std::nullopt;
}

} // namespace

View homeViewWithoutRays(const Scene& scene) {
    if (const std::optional<View> given = givenView(scene)) return *given;
    glm::dvec3 lo, hi;
    if (!sceneBounds(scene, lo, hi)) return cornellView();
    return framingView(lo, hi);
}

View homeView(const Scene& scene, const RayCaster* rays) {
    if (const std::optional<View> given = givenView(scene)) return *given;
    glm::dvec3 lo, hi;
    if (!sceneBounds(scene, lo, hi)) return cornellView();
    const View outside = framingView(lo, hi);
    // A closed scene (a room, a furnace) shows only the backs of its walls from outside, and two
    // plates facing each other mostly their backs: look from inside the bounds when that shows
    // more front faces (an object's inside shows none, so objects keep the outside view).
    std::optional<RayCaster> own;
    if (!rays) rays = &own.emplace(scene);
    const View inside = insideView(lo, hi);
    return frontHitShare(*rays, inside) > frontHitShare(*rays, outside) ? inside : outside;
}

} // namespace radiant
