#pragma once
// Two unit squares with a black half-plane between them, whose shadow on the upper square has a
// closed form: the differential-area-to-rectangle form factor of the part of the lamp each point
// sees. Shared by the hierarchical and progressive penumbra tests.
#include <algorithm>
#include <initializer_list>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/solver/HierarchicalFormFactor.h"
#include "tests/support/CatalogViewFactors.h"

namespace radiant::test {

inline Face quadFace(std::initializer_list<glm::dvec3> corners) {
    Face face;
    face.vertices = corners;
    face.updateGeometry();
    return face;
}

/// Unit squares: "lower" at z = 0 facing +z, "upper" at z = 1 facing -z. With `blocker`, a black
/// plate in the plane z = 1/2 covers x < 1/2 (and y < 1/2 too when `quadrant`): a segment between
/// the squares crosses that plane at the mean of its ends, so it is blocked with probability 1/2
/// (resp. 1/4) for ends uniform on the squares, and by the mirror symmetry x -> 1 - x the blocked
/// share of the form factor is 1/2 as well (half-plane blocker). `lampFrom` and `lampTo` shrink the
/// lower square to [lampFrom, lampTo]^2 (a small lamp: a narrow penumbra, x in [lampFrom, lampTo]).
inline Scene platesWithBlocker(bool blocker, bool quadrant, double lowerExitance, double upperReflectance,
                               double lampFrom = 0, double lampTo = 1) {
    Scene scene;
    scene.name = "half-blocked plates";
    scene.materials = {{"lamp", Rgb(0.0), ExitanceRgb(Rgb(lowerExitance))},
                       {"receiver", Rgb(upperReflectance), ExitanceRgb{}},
                       {"black", Rgb(0.0), ExitanceRgb{}}};
    const double a = lampFrom, b = lampTo;
    scene.surfaces.push_back({"lower", 0, {quadFace({{a, a, 0}, {b, a, 0}, {b, b, 0}, {a, b, 0}})}, "test"});
    scene.surfaces.push_back({"upper", 1, {quadFace({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}})}, "test"});
    if (blocker) {
        const double yEnd = quadrant ? 0.5 : 2.0;
        scene.surfaces.push_back(
            {"blocker", 2, {quadFace({{-1, -1, 0.5}, {0.5, -1, 0.5}, {0.5, yEnd, 0.5}, {-1, yEnd, 0.5}})}, "test"});
    }
    return scene;
}

/// The receiver's radiosity at x in platesWithBlocker's penumbra (a half-plane blocker, no quadrant,
/// unit exitance, black lamp and blocker): a segment from x to the lamp's point l passes the blocker
/// where (x + l) / 2 >= 1/2, so B = rho F(dx -> the lamp's part [max(from, 1 - x), to] x [from, to]).
inline double penumbraRadiosity(double rho, const glm::dvec3& x, double lampFrom = 0, double lampTo = 1) {
    const double seenFrom = std::max(lampFrom, 1 - x.x);
    if (seenFrom >= lampTo) return 0;
    return rho * overRectangle(pointToCornerRectangle, seenFrom - x.x, lampTo - x.x, lampFrom - x.y, lampTo - x.y, 1);
}

/// penumbraRadiosity averaged over each patch of the receiver (surface 1) by a 12 x 12 midpoint rule
/// over the patch's parameters, indexed like the mesh's patches (0 on the lamp's).
inline std::vector<double> penumbraPatchRadiosities(const PatchMesh& mesh, double rho, double lampFrom, double lampTo) {
    std::vector<double> exact(mesh.size(), 0.0);
    for (std::uint32_t i = mesh.surfaceFirstPatch[1]; i < mesh.surfaceFirstPatch[2]; ++i) {
        const PatchPolygon polygon = mesh.polygon(i);
        constexpr int kSide = 12;
        for (int a = 0; a < kSide; ++a)
            for (int b = 0; b < kSide; ++b)
                exact[i] += penumbraRadiosity(rho, hierarchical::pointOn(polygon, (a + 0.5) / kSide, (b + 0.5) / kSide), lampFrom, lampTo);
        exact[i] /= kSide * kSide;
    }
    return exact;
}

} // namespace radiant::test
