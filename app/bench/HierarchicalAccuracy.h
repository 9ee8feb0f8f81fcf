#pragma once
// How right a hierarchical solve of the Cornell box is, for the bench tables that time one: its
// surface means against a fine Gauss-Seidel solve, and the same setup's leaves in the furnace against
// the closed form. Shared so that every hierarchical table states accuracy by the same yardstick.
#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/ElementTree.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/units/Quantity.h"

namespace radiant {
class HierarchicalSolver;
}

namespace radiant::app {

/// The Cornell box and the patches the window shows (0.01 m^2), which a hierarchical solver maps
/// its leaves to: every hierarchical table times its solves on these.
struct CornellBoxAsShown {
    Scene scene;
    PatchMesh mesh;
};
CornellBoxAsShown cornellBoxAsShown();

/// Per surface, the area-weighted mean radiosity (W/m^2 per band).
std::vector<Rgb> surfaceMeans(const Scene& scene, const PatchMesh& mesh, const std::vector<Rgb>& radiosity);

/// The largest relative difference of a surface's mean radiosity, over surfaces and bands.
double worstDeviation(const ElementTree& tree, const std::vector<Rgb>& reference, const Scene& scene);

/// The Cornell box's surface means from Gauss-Seidel to residual 1e-9, on patches small enough that
/// their own meshing error stays below the hierarchical solver's (coarser under --quick).
struct GaussSeidelReference {
    double patchArea = 0;           ///< m^2
    std::vector<Rgb> surfaceMeans;  ///< W/m^2 per band, one per surface of makeCornellBox()
};
/// Solved once per process and per `quick`: the fine one takes seconds and several tables compare with it.
const GaussSeidelReference& cornellGaussSeidelReference(bool quick);

/// Where the hierarchical tables read the Cornell box at points: floor, ceiling, the three walls,
/// both blocks' sides and the short block's top, corners and penumbrae included.
struct ProbePoint {
    const char* where;
    glm::dvec3 point, normal;  ///< m; the normal points out of the surface
};
const std::vector<ProbePoint>& cornellProbePoints();

/// The reference radiosity at cornellProbePoints (W/m^2 per band): the path tracer of
/// radiometry/reference (independent of every radiosity code path), run at each point until its
/// relative standard error is at most `targetStandardError` (or 30 s).
struct PointReference {
    double targetStandardError = 0;
    std::vector<Rgb> radiosity;
    double worstStandardError = 0;  ///< relative, over points and bands, as reached
};
/// Traced once per process and per `quick` (the full one takes a minute or two).
const PointReference& cornellPointReference(bool quick);

/// A hierarchical solve's value at the points (radiosityAt) against the reference: mean and worst
/// relative difference over points and bands, and where the worst is.
struct PointError {
    double mean = 0, worst = 0;
    std::string worstWhere;
};
PointError pointError(const HierarchicalSolver& solver, const CornellBoxAsShown& box, const PointReference& reference);
/// Per point, the worst relative difference over the bands.
std::vector<double> pointErrors(const HierarchicalSolver& solver, const CornellBoxAsShown& box,
                                const PointReference& reference);

/// Issue #20 item 6's case: a 32 x 16 UV sphere (radius 0.5 m, reflectance 0.5) in a closed 2 m box
/// room (reflectance 0.5) under a 0.6 m ceiling lamp of 50 W/m^2, built as
/// tests/data/make_sphere_room.py writes tests/data/curved/sphere_room.gltf. The hierarchical solve
/// (SolverOptions defaults) on 0.02 m^2 patches against Gauss-Seidel on the same mesh (per surface,
/// relative), and its point values on the sphere (top, equator, bottom) against the path tracer.
struct SphereRoomAccuracy {
    double worstSurface = 0;  ///< relative, surface means against Gauss-Seidel
    std::string worstSurfaceName;
    double sphereMean = 0, sphereMeanGaussSeidel = 0;  ///< W/m^2
    std::vector<std::string> points;                  ///< per point: where, reference, point and patch values
    double worstPoint = 0, worstPatch = 0;             ///< relative, against the path tracer
    std::size_t leaves = 0, links = 0;
};
SphereRoomAccuracy sphereRoomAccuracy(bool quick);

/// A leaf's radiosity in the furnace against its closed form E / (1 - rho): area-weighted rms and
/// worst relative difference over the leaves.
struct FurnaceError {
    double rms = 0, worst = 0;
};
/// The furnace solved to residual 1e-6 with hierarchicalSetupForElements(furnace, elements), its
/// linkEpsilon multiplied by `linkEpsilonScale`.
FurnaceError furnaceError(std::size_t elements, double linkEpsilonScale = 1);

} // namespace radiant::app
