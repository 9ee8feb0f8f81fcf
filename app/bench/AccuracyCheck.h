#pragma once
// What the accuracy tables share: points on a Cornell-like box at least 5 cm from their faces'
// edges, the path-traced reference there, and a method's distance from it (at the points) and from
// converged Gauss-Seidel on the same mesh (per patch).
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/reference/ReferencePoint.h"
#include "radiometry/reference/ReferenceRun.h"
#include "radiometry/scene/Scene.h"
#include "radiometry/solver/SolverMethods.h"

namespace radiant {
class RayCaster;
}

namespace radiant::app {

struct AccuracyPoint {
    std::string label;
    ReferencePoint at;
    ReferenceEstimate reference;
};

/// A point on `surface` near `approximate`: projected onto the plane of the surface's face whose
/// polygon it falls in (the measured left wall is two triangles out of one plane).
ReferencePoint pointOnSurface(const Scene& scene, const std::string& surface, const glm::dvec3& approximate);

/// A block's side (faces 1-4 of a block; face 0 is its top) at its centre, or at `height` (m above the
/// floor) on the vertical through its centre.
ReferencePoint blockSide(const Scene& scene, const std::string& block, std::size_t side, double height = -1);

/// Floor, ceiling, back, green and red walls (two points each) and the four sides of each block:
/// every point at least 5 cm from its face's edges. Metres; the Cornell box is 0.55 m across.
std::vector<AccuracyPoint> accuracyPoints(const Scene& scene);

/// Traces each point's reference (seeds 1000 + k) until its standard error is under `wantedError` of E
/// in every band or `perPoint` has passed.
struct ReferenceTrace {
    double seconds = 0, worstError = 0;
    std::uint64_t paths = 0;
};
ReferenceTrace traceReferences(const Scene& scene, const RayCaster& rays, std::vector<AccuracyPoint>& points,
                               double wantedError, std::chrono::duration<double> perPoint);

struct MethodErrors {
    double meanB = 0, worstB = 0, meanE = 0, worstE = 0;
    std::string worstBAt;
};
/// A method's B and E at the points against the path tracer's, over every point and band.
MethodErrors errorsAgainstReference(const std::vector<AccuracyPoint>& points, const std::vector<ProbeReading>& readings);

/// Issue 14's accuracy targets for a method (hierarchical 0.5% / 1.5%, the rest 1% / 3%), as the
/// tables' target column words them, and whether its errors meet them in B and E.
struct AccuracyTarget {
    double mean = 0.01, worst = 0.03;
    std::string text = "1% / 3%";
    [[nodiscard]] bool met(const MethodErrors& errors) const {
        return errors.meanB <= mean && errors.worstB <= worst && errors.meanE <= mean && errors.worstE <= worst;
    }
};
AccuracyTarget accuracyTarget(SolverMethod method);

/// The band mean of (value / reference - 1): signed, so the notes show which way a point is off.
double signedError(const Rgb& value, const Rgb& reference);
std::string signedPercent(double fraction);

/// A solution's distance from another on the same mesh, patch by patch: each patch's largest relative
/// band error, averaged by area over the patches the reference lights (B above 1e-9 W/m^2 in some band).
struct PatchDistance {
    double mean = 0;
    std::size_t over5Percent = 0;
};
PatchDistance patchDistance(const PatchMesh& mesh, const std::vector<Rgb>& solution, const std::vector<Rgb>& reference);

} // namespace radiant::app
