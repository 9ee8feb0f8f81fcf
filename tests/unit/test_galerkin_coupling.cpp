// A link's Galerkin coupling coefficients (radiometry/galerkin/Coupling.h) against closed forms:
// the constant coefficient K_00 against Howell's catalog form factors (parallel coaxial squares,
// perpendicular rectangles sharing an edge and, by the catalog's inclusion-exclusion, apart) and the
// receiver moments K_i0 against Lambert's exact point-to-polygon integral under a fine outer rule;
// the others against a 16 x 16 rule per side of the same integrand; a linear source's gathered
// moments against a direct fine integration of its radiosity; reciprocity.
//
// Each rule's error is asserted below a bound a little above what it measured (messages print the
// measured errors; docs/ARCHITECTURE.md quotes them), so a regression in a rule shows as a failure.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/galerkin/Coupling.h"
#include "radiometry/mesh/ElementTree.h"

#include "tests/support/CatalogViewFactors.h"
#include "tests/support/Relative.h"

// A namespace of its own: unity builds put test files together, and no using-directive leaks out.
namespace radiant::galerkin::coupling_tests {

using radiant::test::relativeTo;

namespace {

/// A rectangle or triangle from corners, its normal turned to `facing` (its corners reordered, not
/// the map's orientation, so the basis still runs from corner 0).
PatchPolygon element(std::initializer_list<glm::dvec3> corners, const glm::dvec3& facing) {
    std::vector<glm::dvec3> points(corners);
    PatchPolygon polygon = makeElementPolygon(points);
    if (glm::dot(polygon.normal, facing) < 0) {
        std::reverse(points.begin() + 1, points.end());
        polygon = makeElementPolygon(points);
    }
    return polygon;
}

CouplingCoefficients coupling(const PatchPolygon& receiver, const PatchPolygon& source, std::size_t level) {
    return couplingCoefficients(elementNodes(receiver, elementRule(shapeOf(receiver), level)),
                                elementNodes(source, elementRule(shapeOf(source), level)));
}

double relativeError(double actual, double expected) { return std::abs(actual - expected) / std::abs(expected); }

/// The largest |K_ij - reference_ij| over all i, j, relative to the reference's K_00.
double coefficientsError(const CouplingCoefficients& k, const CouplingCoefficients& reference) {
    double worst = 0;
    for (std::size_t i = 0; i < kMaxBasisSize; ++i)
        for (std::size_t j = 0; j < kMaxBasisSize; ++j) worst = std::max(worst, std::abs(k[i][j] - reference[i][j]));
    return worst / reference[0][0];
}

/// K_i0 with Lambert's exact inner integral: (1/A_r) int phi_i(x) F(dA_x -> source) dA_x by a fine
/// rule over the receiver only (phi_0 = 1 on the source makes the inner integral a point form factor).
BasisCoefficients receiverMomentsByLambert(const PatchPolygon& receiver, const PatchPolygon& source) {
    const ElementShape shape = shapeOf(receiver);
    const QuadratureRule fine = elementRule(shape, 32);
    BasisCoefficients moments{};
    for (const QuadratureNode& node : fine) {
        const double pointFactor = pointToPolygonFormFactor(pointAt(receiver, node.at), receiver.normal, source.corners());
        const BasisCoefficients phi = basisValues(shape, node.at);
        for (std::size_t i = 0; i < kMaxBasisSize; ++i)
            moments[i] += node.weight * areaDensity(receiver, node.at) * pointFactor * phi[i];
    }
    return moments;
}

struct Configuration {
    const char* name;
    PatchPolygon receiver;
    PatchPolygon source;
    double closedForm;  ///< F(receiver -> source) from the catalog
    double distanceSquaredOverArea;  ///< r^2 / A: centre distance squared over the larger area
    double bound2, bound3, bound16;  ///< the rules' relative errors on K_00 must stay below these
    /// The rules' worst error over all 16 coefficients relative to K_00, against the 16 x 16 rule
    /// (used where that rule is itself exact to 1e-6: not next to the shared edge).
    double higherBound2 = 0, higherBound3 = 0;
};

double centreDistanceSquaredOverArea(const PatchPolygon& a, const PatchPolygon& b) {
    const glm::dvec3 d = a.centroid - b.centroid;
    return glm::dot(d, d) / std::max(a.area, b.area);
}

std::vector<Configuration> catalogConfigurations() {
    // Bounds: the measured relative error of each rule times 1.5 (a floor of 1e-12 where the rule is
    // exact to round-off). Measured: docs/ARCHITECTURE.md, session 19.
    struct Bounds { double two, three, sixteen, higherTwo, higherThree; };
    std::vector<Configuration> list;
    const glm::dvec3 up(0, 0, 1), down(0, 0, -1), east(1, 0, 0);
    const double distances[] = {0.25, 0.5, 1.0, 2.0, 4.0};
    const Bounds parallelBounds[] = {{1.7, 0.48, 1.2e-6, 2.3, 0.48},
                                     {0.16, 0.016, 1e-12, 0.51, 0.016},
                                     {0.016, 5e-4, 1e-12, 0.077, 3.9e-3},
                                     {3.9e-3, 6e-5, 1e-12, 9e-3, 2.2e-4},
                                     {3.5e-4, 1.7e-6, 1e-12, 7.1e-4, 5.3e-6}};
    for (std::size_t n = 0; n < std::size(distances); ++n) {
        const double c = distances[n];
        const Bounds& b = parallelBounds[n];
        list.push_back({"parallel unit squares", element({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, up),
                        element({{0, 0, c}, {1, 0, c}, {1, 1, c}, {0, 1, c}}, down), test::parallelRectangles(1, 1, c), 0,
                        b.two, b.three, b.sixteen, b.higherTwo, b.higherThree});
    }
    // Receiver: the strip x in [d, d + w] of the floor (y in [0, l]); source: the wall x = 0, z in
    // [0, h]. For d = 0 they share an edge (the catalog's case); for d > 0, by inclusion-exclusion,
    // F = ((d + w) F(d + w, h, l) - d F(d, h, l)) / w.
    const double w = 1, h = 1, l = 1;
    const double gaps[] = {0.0, 0.1, 0.5, 2.0};
    const Bounds perpendicularBounds[] = {{0.77, 0.69, 0.3, 0, 0}, {0.43, 0.17, 8e-5, 0, 0}, {0.015, 5e-3, 1e-12, 0.098, 0.018},
                                          {5.4e-3, 4.2e-5, 1e-12, 0.014, 1.2e-4}};
    for (std::size_t n = 0; n < std::size(gaps); ++n) {
        const double d = gaps[n];
        const Bounds& b = perpendicularBounds[n];
        const double closed = d == 0 ? test::perpendicularRectangles(w, h, l)
                                     : ((d + w) * test::perpendicularRectangles(d + w, h, l) - d * test::perpendicularRectangles(d, h, l)) / w;
        list.push_back({d == 0 ? "perpendicular rectangles sharing an edge" : "perpendicular rectangles apart",
                        element({{d, 0, 0}, {d + w, 0, 0}, {d + w, l, 0}, {d, l, 0}}, up),
                        element({{0, 0, 0}, {0, l, 0}, {0, l, h}, {0, 0, h}}, east), closed, 0, b.two, b.three, b.sixteen,
                        b.higherTwo, b.higherThree});
    }
    for (Configuration& k : list) k.distanceSquaredOverArea = centreDistanceSquaredOverArea(k.receiver, k.source);
    return list;
}

} // namespace

TEST_CASE("galerkin: K_00 is the catalog's form factor, each rule to its stated error") {
    for (const Configuration& k : catalogConfigurations()) {
        const double e2 = relativeError(coupling(k.receiver, k.source, 2)[0][0], k.closedForm);
        const double e3 = relativeError(coupling(k.receiver, k.source, 3)[0][0], k.closedForm);
        const double e16 = relativeError(coupling(k.receiver, k.source, 16)[0][0], k.closedForm);
        MESSAGE(std::string(k.name) << ", r^2/A = " << k.distanceSquaredOverArea << ": F = " << k.closedForm
                                    << ", relative error 2x2 " << e2 << ", 3x3 " << e3 << ", 16x16 " << e16);
        CHECK(e2 < k.bound2);
        CHECK(e3 < k.bound3);
        CHECK(e16 < k.bound16);
    }
}

TEST_CASE("galerkin: with Lambert's inner integral K_00 holds where the point-pair rules fail") {
    // constantSourceMoments samples the receiver only; the shared edge's kernel singularity is then
    // inside Lambert's closed form. Bounds as above (measured x 1.5).
    const double bounds2[] = {0.083, 3.4e-3, 0.011, 2e-3, 1.8e-4, 2.8e-3, 3.4e-3, 0.011, 2.1e-3};
    const double bounds3[] = {6.7e-3, 4.2e-3, 1.5e-4, 2.9e-5, 8.4e-7, 3.7e-5, 2.5e-3, 1.8e-4, 1.1e-5};
    std::size_t n = 0;
    for (const Configuration& k : catalogConfigurations()) {
        const ElementShape shape = shapeOf(k.receiver);
        const double e2 = relativeError(constantSourceMoments(elementNodes(k.receiver, elementRule(shape, 2)), k.source)[0], k.closedForm);
        const double e3 = relativeError(constantSourceMoments(elementNodes(k.receiver, elementRule(shape, 3)), k.source)[0], k.closedForm);
        MESSAGE(std::string(k.name) << ", r^2/A = " << k.distanceSquaredOverArea << ": Lambert inner, relative error 2x2 " << e2
                                    << ", 3x3 " << e3);
        CHECK(e2 < bounds2[n]);
        CHECK(e3 < bounds3[n]);
        ++n;
    }
}

TEST_CASE("galerkin: the higher coefficients converge to the 16 x 16 rule's, and K_i0 to Lambert's") {
    // Where the 16 x 16 rule itself is exact to 1e-6 on K_00 (not at the shared edge, see above). The
    // error is the largest |K_ij - K16_ij| over i, j relative to K_00.
    for (const Configuration& k : catalogConfigurations()) {
        const CouplingCoefficients reference = coupling(k.receiver, k.source, 16);
        if (relativeError(reference[0][0], k.closedForm) > 1e-6) continue;
        const double e2 = coefficientsError(coupling(k.receiver, k.source, 2), reference);
        const double e3 = coefficientsError(coupling(k.receiver, k.source, 3), reference);
        MESSAGE(std::string(k.name) << ", r^2/A = " << k.distanceSquaredOverArea << ": all 16 coefficients, worst error / K_00: 2x2 "
                                    << e2 << ", 3x3 " << e3);
        // The higher moments weight the same kernel by basis functions of size up to 3, so their
        // errors run above K_00's by up to 5x (2 x 2) and 10x (3 x 3) relative to K_00.
        CHECK(e2 < k.higherBound2);
        CHECK(e3 < k.higherBound3);
        // The receiver moments of a constant source, with the inner integral exact (Lambert), agree
        // with the 16 x 16 point-pair rule: the oracle for the i > 0 rows.
        const BasisCoefficients lambert = receiverMomentsByLambert(k.receiver, k.source);
        for (std::size_t i = 0; i < kMaxBasisSize; ++i) {
            INFO("K_" << i << "0 = " << reference[i][0] << ", by Lambert " << lambert[i]);
            CHECK(std::abs(reference[i][0] - lambert[i]) < 1e-6 * reference[0][0]);
        }
        // Symmetry of the squares: coefficients odd in a mirror plane vanish, e.g. K_10 and K_30.
        if (std::string(k.name) == "parallel unit squares") {
            CHECK(std::abs(reference[1][0]) < 1e-12 * reference[0][0]);
            CHECK(std::abs(reference[3][0]) < 1e-12 * reference[0][0]);
        }
    }
}

TEST_CASE("galerkin: triangles' couplings against Lambert's inner integral") {
    // A triangle above a quad and a triangle beside a triangle (tilted, no symmetry): K_i0 by the
    // point-pair rules against the receiver moments with Lambert's exact inner integral and a
    // collapsed 32 x 32 outer rule.
    const glm::dvec3 up(0, 0, 1), down(0, 0, -1);
    const PatchPolygon floor = element({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, up);
    const PatchPolygon roof = element({{0.1, 0.2, 0.9}, {1.2, 0.1, 1.1}, {0.4, 1.3, 1.0}}, down);
    const PatchPolygon leaning = element({{1.5, 0, 0.1}, {1.6, 1, 0.2}, {1.4, 0.5, 1.1}}, glm::dvec3(-1, 0, 0.2));
    struct Pair { const PatchPolygon& receiver; const PatchPolygon& source; double bound2, bound3; };
    const Pair pairs[] = {{roof, floor, 0.023, 1.05e-3}, {floor, roof, 0.023, 1.05e-3}, {roof, leaning, 0.17, 0.0105},
                          {leaning, roof, 0.17, 0.0105}};
    for (const Pair& pair : pairs) {
        const BasisCoefficients lambert = receiverMomentsByLambert(pair.receiver, pair.source);
        const CouplingCoefficients k2 = coupling(pair.receiver, pair.source, 2), k3 = coupling(pair.receiver, pair.source, 3);
        const CouplingCoefficients k16 = coupling(pair.receiver, pair.source, 16);
        double e2 = 0, e3 = 0, e16 = 0;
        for (std::size_t i = 0; i < kMaxBasisSize; ++i) {
            e2 = std::max(e2, std::abs(k2[i][0] - lambert[i]) / lambert[0]);
            e3 = std::max(e3, std::abs(k3[i][0] - lambert[i]) / lambert[0]);
            e16 = std::max(e16, std::abs(k16[i][0] - lambert[i]) / lambert[0]);
        }
        MESSAGE("receiver corners " << int(pair.receiver.count) << ", source corners " << int(pair.source.count) << ": F = "
                                    << lambert[0] << ", worst K_i0 error / F: 2-level " << e2 << ", 3-level " << e3 << ", 16-level " << e16);
        CHECK(e2 < pair.bound2);
        CHECK(e3 < pair.bound3);
        CHECK(e16 < 1e-6);
        // A triangle's fourth basis function does not exist: its row or column stays 0.
        for (std::size_t j = 0; j < kMaxBasisSize; ++j) {
            if (pair.receiver.count == 3) CHECK(k3[3][j] == 0.0);
            if (pair.source.count == 3) CHECK(k3[j][3] == 0.0);
        }
    }
}

TEST_CASE("galerkin: a linear source's gathered moments match a direct fine integration") {
    // A source whose radiosity is linear in space, B(y) = 1 + 0.8 g . (y - c) with |g| = 1 / size:
    // its coefficients are exact in the basis (projected by the 2 x 2 rule), and K b must give the
    // receiver's irradiance moments (1 / A_r) int phi_i(x) int G B(y) dA_y dA_x computed here
    // directly, B evaluated in space, by 16 x 16 points per side.
    const glm::dvec3 up(0, 0, 1), down(0, 0, -1), east(1, 0, 0);
    const PatchPolygon floor = element({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, up);
    const PatchPolygon ceiling = element({{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, down);
    const PatchPolygon wall = element({{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, east);
    const PatchPolygon floorApart = element({{0.5, 0, 0}, {1.5, 0, 0}, {1.5, 1, 0}, {0.5, 1, 0}}, up);
    const glm::dvec3 gradient = glm::normalize(glm::dvec3(0.6, -0.5, 0.9));
    struct Pair { const PatchPolygon& receiver; const PatchPolygon& source; double bound2, bound3; };
    const Pair pairs[] = {{floor, ceiling, 0.016, 5e-4}, {floorApart, wall, 0.042, 4.2e-3}, {wall, floorApart, 0.084, 0.0123}};
    for (const Pair& pair : pairs) {
        const auto radiosity = [&](const glm::dvec3& y) { return 1 + 0.8 * glm::dot(gradient, y - pair.source.centroid); };
        const ElementShape sourceShape = shapeOf(pair.source);
        const BasisCoefficients b = projectOntoBasis(sourceShape, elementRule(sourceShape, 2),
                                                     [&](ElementParameter at) { return radiosity(pointAt(pair.source, at)); });
        const ElementNodes receiverFine = elementNodes(pair.receiver, elementRule(shapeOf(pair.receiver), 16));
        const ElementNodes sourceFine = elementNodes(pair.source, elementRule(sourceShape, 16));
        BasisCoefficients direct{};
        for (std::size_t p = 0; p < receiverFine.points.size(); ++p) {
            double irradiance = 0;
            for (std::size_t q = 0; q < sourceFine.points.size(); ++q)
                irradiance += sourceFine.areas[q] * radiosity(sourceFine.points[q]) *
                              pointToPointKernel(receiverFine.points[p], receiverFine.normal, sourceFine.points[q], sourceFine.normal);
            for (std::size_t i = 0; i < kMaxBasisSize; ++i)
                direct[i] += receiverFine.areas[p] / receiverFine.area * receiverFine.basis[p][i] * irradiance;
        }
        const BasisCoefficients h2 = gatheredMoments(coupling(pair.receiver, pair.source, 2), b);
        const BasisCoefficients h3 = gatheredMoments(coupling(pair.receiver, pair.source, 3), b);
        const BasisCoefficients h16 = gatheredMoments(coupling(pair.receiver, pair.source, 16), b);
        double e2 = 0, e3 = 0, e16 = 0;
        for (std::size_t i = 0; i < kMaxBasisSize; ++i) {
            e2 = std::max(e2, std::abs(h2[i] - direct[i]) / direct[0]);
            e3 = std::max(e3, std::abs(h3[i] - direct[i]) / direct[0]);
            e16 = std::max(e16, std::abs(h16[i] - direct[i]) / direct[0]);
        }
        MESSAGE("linear source, r^2/A = " << centreDistanceSquaredOverArea(pair.receiver, pair.source)
                                          << ": worst moment error / h_0: 2x2 " << e2 << ", 3x3 " << e3 << ", 16x16 " << e16);
        CHECK(e16 < 1e-12);  // K b is the same integral: the basis holds the linear source exactly
        CHECK(e2 < pair.bound2);
        CHECK(e3 < pair.bound3);
    }
}

TEST_CASE("galerkin: couplings are reciprocal, A_r K_ij(r, s) = A_s K_ji(s, r)") {
    const PatchPolygon square = element({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, glm::dvec3(0, 0, 1));
    const PatchPolygon trapezoid = element({{0.2, 0.1, 0.8}, {1.3, -0.1, 1.0}, {1.1, 0.9, 1.2}, {0.1, 0.7, 0.9}}, glm::dvec3(0, 0, -1));
    const PatchPolygon triangle = element({{1.4, 0, 0.2}, {1.5, 1, 0.3}, {1.3, 0.5, 1.2}}, glm::dvec3(-1, 0, 0.1));
    const PatchPolygon* elements[] = {&square, &trapezoid, &triangle};
    for (const PatchPolygon* r : elements)
        for (const PatchPolygon* s : elements) {
            if (r == s) continue;
            for (std::size_t level : {2, 3}) {
                const CouplingCoefficients forward = coupling(*r, *s, level), backward = coupling(*s, *r, level);
                for (std::size_t i = 0; i < kMaxBasisSize; ++i)
                    for (std::size_t j = 0; j < kMaxBasisSize; ++j)
                        CHECK(std::abs(r->area * forward[i][j] - s->area * backward[j][i]) < 1e-14 * r->area * forward[0][0]);
            }
        }
}

} // namespace radiant::galerkin::coupling_tests
