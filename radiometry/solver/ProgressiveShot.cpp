// The form factors of one progressive shot, from the shooter to every receiver. Three routes,
// cheapest first: a plane test culls pairs that cannot see each other before any ray; a receiver
// small for its distance takes the exact point-to-polygon (Lambert) factor at its centroid to the
// whole shooter, which is F_{j->s} up to the receiver's own extent (the route of Wallace, Elmquist,
// Haines, "A ray tracing algorithm for progressive radiosity", SIGGRAPH 1989); closer receivers
// average that exact kernel over 2 x 2 or 4 x 4 Gauss points of their own area - a fixed cost, where
// the adaptive area quadrature spends thousands of cells on touching pairs. Times the ray-cast
// visibility. F_{j->s} comes out directly, so no reciprocity division by a small receiver's area.
#include <algorithm>
#include <array>
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

/// Gauss-Legendre nodes and weights on [0, 1] for orders 1, 2 and 4.
struct ReceiverRule {
    int order;
    std::array<double, 4> node, weight;
};
constexpr ReceiverRule kCentroid{1, {0.5}, {1.0}};
constexpr ReceiverRule kGauss2{2, {0.2113248654051871, 0.7886751345948129}, {0.5, 0.5}};
constexpr ReceiverRule kGauss4{4,
                               {0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263},
                               {0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269}};

/// Receivers farther than this many of their own diameters take the centroid alone (the point
/// kernel's error from the receiver's extent falls like (diameter / distance)^2); closer than
/// kNearInDiameters, 4 x 4 points; between, 2 x 2.
constexpr double kFarInDiameters = 4.0;
constexpr double kNearInDiameters = 1.5;

struct ShotGeometry {
    std::vector<PatchPolygon> polygons;
    std::vector<Patch> patches;
    std::unique_ptr<RayCaster> rays;
    FormFactorOptions options;
};

/// (1/A_r) integral over the receiver of F(dA_r -> shooter) dA_r: the exact Lambert kernel to the
/// whole shooter at Gauss points of the receiver's bilinear map (a triangle is a quad with its last
/// corner doubled). Unoccluded.
double receiverAverage(const PatchPolygon& receiver, const PatchPolygon& shooter, const ReceiverRule& rule) {
    if (rule.order == 1) return pointToPolygonFormFactor(receiver.centroid, receiver.normal, shooter.corners());
    const glm::dvec3 a = receiver.vertices[0], b = receiver.vertices[1], c = receiver.vertices[2];
    const glm::dvec3 d = receiver.count == 4 ? receiver.vertices[3] : c;
    double sum = 0;
    for (int i = 0; i < rule.order; ++i) {
        const double u = rule.node[static_cast<std::size_t>(i)];
        const glm::dvec3 bottom = a + (b - a) * u;
        const glm::dvec3 alongV = d + (c - d) * u - bottom;
        for (int j = 0; j < rule.order; ++j) {
            const double v = rule.node[static_cast<std::size_t>(j)];
            const glm::dvec3 alongU = (b - a) + ((c - d) - (b - a)) * v;
            const double jacobian = glm::dot(receiver.normal, glm::cross(alongU, alongV));
            sum += rule.weight[static_cast<std::size_t>(i)] * rule.weight[static_cast<std::size_t>(j)] * jacobian *
                   pointToPolygonFormFactor(bottom + alongV * v, receiver.normal, shooter.corners());
        }
    }
    return sum / receiver.area;
}

double receiverToShooter(const ShotGeometry& g, std::size_t shooter, std::size_t receiver) {
    const PatchPolygon& s = g.polygons[shooter];
    const PatchPolygon& r = g.polygons[receiver];
    const Patch& ps = g.patches[shooter];
    const Patch& pr = g.patches[receiver];
    if (receiver == shooter || (ps.surface == pr.surface && ps.face == pr.face) || cannotSeeEachOther(s, r)) return 0;
    const double distance = glm::length(r.centroid - s.centroid);
    const double receiverDiameter = std::sqrt(2.0 * r.area);
    const ReceiverRule& rule = distance > kFarInDiameters * receiverDiameter    ? kCentroid
                               : distance > kNearInDiameters * receiverDiameter ? kGauss2
                                                                                : kGauss4;
    const double unoccluded = receiverAverage(r, s, rule);
    if (unoccluded <= 0) return 0;
    FormFactorOptions pairOptions = g.options;
    pairOptions.seed = pairSeed(g.options.seed, std::min(shooter, receiver), std::max(shooter, receiver));
    // A far receiver's shadow boundary is blurred over few of its own patches anyway; a quarter of
    // the rays keeps its visibility within a few per cent at a quarter of the shot's main cost.
    if (rule.order == 1) pairOptions.visibilityRays = std::max(1, g.options.visibilityRays / 4);
    return unoccluded * visibilityFraction(s, r, g.rays.get(), pairOptions);
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
