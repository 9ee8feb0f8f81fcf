// The form factors of one progressive shot, from the shooter to every receiver. Three routes,
// cheapest first: a plane test culls pairs that cannot see each other before any ray; a receiver
// small for its distance takes the exact point-to-polygon (Lambert) factor at its centroid to the
// whole shooter, which is F_{j->s} up to the receiver's own extent (the route of Wallace, Elmquist,
// Haines, "A ray tracing algorithm for progressive radiosity", SIGGRAPH 1989); a close pair takes
// the area quadrature over the smaller patch and reciprocity. Both times the ray-cast visibility.
#include <algorithm>
#include <cmath>
#include <memory>

#include <glm/geometric.hpp>

#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/solver/FormFactorMatrix.h"
#include "radiometry/solver/ParallelFor.h"
#include "radiometry/solver/ProgressiveSolver.h"

namespace radiant {

namespace {

/// A receiver this many of its own diameters away is "small for its distance": the point kernel's
/// error from the receiver's extent is then below about 1e-3 relative for facing pairs.
constexpr double kFarInDiameters = 3.0;

struct ShotGeometry {
    std::vector<PatchPolygon> polygons;
    std::vector<Patch> patches;
    std::unique_ptr<RayCaster> rays;
    FormFactorOptions options;
};

double receiverToShooter(const ShotGeometry& g, std::size_t shooter, std::size_t receiver) {
    const PatchPolygon& s = g.polygons[shooter];
    const PatchPolygon& r = g.polygons[receiver];
    const Patch& ps = g.patches[shooter];
    const Patch& pr = g.patches[receiver];
    if (receiver == shooter || (ps.surface == pr.surface && ps.face == pr.face) || cannotSeeEachOther(s, r)) return 0;
    FormFactorOptions pairOptions = g.options;
    pairOptions.seed = pairSeed(g.options.seed, std::min(shooter, receiver), std::max(shooter, receiver));
    const double distance = glm::length(r.centroid - s.centroid);
    const double receiverDiameter = std::sqrt(2.0 * r.area);
    if (distance > kFarInDiameters * receiverDiameter) {
        const double unoccluded = pointToPolygonFormFactor(r.centroid, r.normal, s.corners());
        if (unoccluded <= 0) return 0;
        return unoccluded * visibilityFraction(s, r, g.rays.get(), pairOptions);
    }
    if (r.area <= s.area) return formFactor(r, s, g.rays.get(), pairOptions);
    return formFactor(s, r, g.rays.get(), pairOptions) * s.area / r.area;
}

} // namespace

ShotFormFactors makeRayCastShotFormFactors(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options) {
    auto geometry = std::make_shared<ShotGeometry>();
    geometry->polygons.resize(mesh.size());
    for (std::size_t i = 0; i < mesh.size(); ++i) geometry->polygons[i] = mesh.polygon(i);
    geometry->patches = mesh.patches;
    geometry->rays = std::make_unique<RayCaster>(scene);
    geometry->options = options.formFactors;
    geometry->options.seed = pairSeed(options.seed, options.formFactors.seed, 0);
    return [geometry](std::size_t shooter, std::span<double> toShooter) {
        parallelFor(toShooter.size(), 512, [&](std::size_t begin, std::size_t end) {
            for (std::size_t j = begin; j < end; ++j) toShooter[j] = receiverToShooter(*geometry, shooter, j);
        });
    };
}

} // namespace radiant
