// ctest-labels: threads
// Hierarchical radiosity scaled by element count (hierarchicalSetupForElements): the leaves reach
// the requested resolution and the links grow linearly with them, not quadratically. These are
// properties of the algorithm (Hanrahan, Salzman, Aupperle 1991, Section 4), not closed forms; the
// physics of the same solver is tested against closed forms in test_hierarchical.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "radiometry/geometry/RayCaster.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/HierarchicalSolver.h"

using namespace radiant;

namespace {

struct Scaled {
    std::size_t leaves = 0, links = 0;
    double largestLeaf = 0;
    std::size_t steps = 0;
};

Scaled solveFor(const Scene& scene, const PatchMesh& mesh, std::size_t elements) {
    const HierarchicalSetup setup = hierarchicalSetupForElements(scene, elements);
    HierarchicalSolver solver(scene, mesh, setup.options, nullptr, setup.refinement);
    Scaled result;
    for (result.steps = 1; result.steps <= 60; ++result.steps)
        if (solver.step().residual <= 1e-3) break;
    const ElementTree& tree = solver.elements();
    for (const ElementIndex e : tree.leaves()) result.largestLeaf = std::max(result.largestLeaf, tree.area(e));
    result.leaves = tree.leafCount();
    result.links = solver.links().size();
    return result;
}

} // namespace

TEST_SUITE("hierarchical") {

// ctest-case-labels: heavy
TEST_CASE("hierarchical scaling: the furnace gives E / (1 - rho) on every leaf") {
    // Most leaves, split for resolution alone, have no links of their own: their rows gather over
    // their ancestors' links with the leaf's own form factors (buildLeafRows). In a furnace every leaf
    // must then show the closed form, corners included; before the rows, ancestors' means pushed down
    // as constants left corner leaves 20-25% off.
    const Scene scene = makeFurnace();
    const double rho = scene.materials[0].reflectance.x, exitance = scene.materials[0].exitance.value().x;
    const double expected = exitance / (1 - rho);
    MeshingOptions meshing;
    meshing.maxPatchArea = 0.1;
    const PatchMesh mesh = meshScene(scene, meshing);
    for (const std::size_t elements : {std::size_t{8000}, std::size_t{32000}}) {
        CAPTURE(elements);
        const HierarchicalSetup setup = hierarchicalSetupForElements(scene, elements);
        HierarchicalSolver solver(scene, mesh, setup.options, nullptr, setup.refinement);
        std::size_t steps = 1;
        while (steps < 200 && solver.step().residual > 1e-6) ++steps;
        CHECK(steps < 200);
        const ElementTree& tree = solver.elements();
        double sum = 0, squares = 0, worst = 0;
        for (const ElementIndex e : tree.leaves()) {
            const double off = tree.radiosity()[e].x / expected - 1;
            sum += tree.area(e) * tree.radiosity()[e].x;
            squares += tree.area(e) * off * off;
            worst = std::max(worst, std::abs(off));
        }
        const double rmsLeaf = std::sqrt(squares / scene.totalArea());
        CHECK(sum / scene.totalArea() == doctest::Approx(expected).scale(0).epsilon(0.001));
        CHECK(rmsLeaf < 0.005);
        CHECK(worst < 0.02);
        // Per patch (0.1 m^2, what the window shows).
        double worstPatch = 0;
        for (const Rgb& b : solver.solution()) worstPatch = std::max(worstPatch, std::abs(b.x / expected - 1));
        CHECK(worstPatch < 0.02);
        MESSAGE(tree.leafCount() << " leaves: mean off by " << sum / scene.totalArea() / expected - 1
                                 << ", worst patch by " << worstPatch << ", leaves rms " << rmsLeaf
                                 << ", worst leaf " << worst);
    }
}

TEST_CASE("hierarchical scaling: the floor under the Cornell blocks stays dark") {
    // Floor leaves wholly under a block see nothing: their irradiance is 0 but for what ancestors
    // straddling the block's edge push down. Links refined from fully visible ones check visibility
    // with one ray: taking the parent's word without it lit them like the open floor.
    const Scene scene = makeCornellBox();
    MeshingOptions meshing;
    meshing.maxPatchArea = 0.05;
    const PatchMesh mesh = meshScene(scene, meshing);
    const HierarchicalSetup setup = hierarchicalSetupForElements(scene, 8000);
    HierarchicalSolver solver(scene, mesh, setup.options, nullptr, setup.refinement);
    for (int k = 0; k < 60 && solver.step().residual > 1e-3; ++k) {
    }
    const RayCaster caster(scene);
    const ElementTree& tree = solver.elements();
    std::uint32_t floor = 0;
    while (scene.surfaces[floor].name != "floor") ++floor;
    double underArea = 0, under = 0, openArea = 0, open = 0;
    for (const ElementIndex e : tree.leaves()) {
        if (tree.surface(e) != floor) continue;
        const PatchPolygon& leaf = tree.polygon(e);
        bool covered = true;  // every corner has a block face just above it
        for (const glm::dvec3& corner : leaf.corners()) {
            const glm::dvec3 x = 0.98 * corner + 0.02 * leaf.centroid + 1e-6 * leaf.normal;
            covered = covered && caster.occluded(x, x + 0.35 * leaf.normal);
        }
        (covered ? under : open) += tree.area(e) * tree.radiosity()[e].y;
        (covered ? underArea : openArea) += tree.area(e);
    }
    REQUIRE(underArea > 0.01);  // the two blocks cover about 0.06 m^2
    MESSAGE("floor under the blocks: " << under / underArea << " W/m^2, open floor " << open / openArea);
    // Measured 4% of the open floor's mean (what straddling ancestors push down). Without the ray
    // check the floor's mean rose from 0.11 to 0.19 W/m^2 (Gauss-Seidel: 0.11).
    CHECK(under / underArea < 0.1 * open / openArea);
}

TEST_CASE("hierarchical scaling: 4x the elements, links per leaf at most 4^(1/3) x") {
    const Scene scene = makeCornellBox();
    MeshingOptions meshing;
    meshing.maxPatchArea = 0.05;
    const PatchMesh mesh = meshScene(scene, meshing);
    const Scaled coarse = solveFor(scene, mesh, 2000);
    const Scaled fine = solveFor(scene, mesh, 8000);
    CHECK(coarse.steps <= 60);
    CHECK(fine.steps <= 60);
    // Every leaf at least as fine as asked (twice the mean area, see hierarchicalSetupForElements).
    CHECK(coarse.largestLeaf <= 2 * scene.totalArea() / 2000);
    CHECK(fine.largestLeaf <= 2 * scene.totalArea() / 8000);
    CHECK(fine.leaves > 3 * coarse.leaves);
    const double coarsePerLeaf = static_cast<double>(coarse.links) / static_cast<double>(coarse.leaves);
    const double finePerLeaf = static_cast<double>(fine.links) / static_cast<double>(fine.leaves);
    // Nearly linear memory: with the radiosity tolerance proportional to the leaf's edge h, a level
    // of elements of size s links each to sources within about s / h^(1/3), so links per leaf grow
    // at most like h^(-2/3), i.e. elements^(1/3) (Hanrahan et al. 1991, Section 4's count); measured
    // 4.0 -> 5.4 here. A fixed threshold, as before this scaling, took them from 17 to 105 between
    // 10k and 236k elements.
    CHECK(finePerLeaf <= std::cbrt(4.0) * coarsePerLeaf);
    MESSAGE(coarse.leaves << " leaves, " << coarsePerLeaf << " links per leaf; " << fine.leaves << " leaves, "
                          << finePerLeaf << " links per leaf");
}

} // TEST_SUITE

#include <algorithm>
#include <numbers>
#include <random>

#include <initializer_list>
#include <vector>

#include <glm/geometric.hpp>

#include "radiometry/mesh/ElementTree.h"
#include "radiometry/solver/HierarchicalFormFactor.h"
#include "tests/support/CatalogViewFactors.h"
#include "tests/support/Relative.h"

namespace {

/// The far-field and gather-kernel tests' receivers: for a 0.1 m square and a triangle source,
/// points at distance distance(source, k) from its centroid for each k, from oblique directions,
/// the receiver facing the source turned by up to 75 degrees about a side axis.
template <class Distance, class Visit>
void forEachObliqueReceiver(std::initializer_list<double> ks, Distance distance, Visit visit) {
    const double side = 0.1;
    const std::vector<glm::dvec3> square = {{0, 0, 0}, {side, 0, 0}, {side, side, 0}, {0, side, 0}};
    const std::vector<glm::dvec3> triangle = {{0, 0, 0}, {side, 0, 0}, {0.3 * side, 1.2 * side, 0}};
    for (const auto* corners : {&square, &triangle}) {
        const PatchPolygon source = makeElementPolygon(*corners);
        REQUIRE(source.normal.z == doctest::Approx(1.0).scale(0));
        for (const double k : ks)
            for (const double tilt : {0.0, 0.4, 1.0, 1.3})
                for (const double offAxis : {0.0, 0.5, 1.0, 2.0, 3.0}) {
                    CAPTURE(k);
                    CAPTURE(tilt);
                    CAPTURE(offAxis);
                    const double r = distance(source, k);
                    const glm::dvec3 direction = glm::normalize(glm::dvec3(offAxis, 0.3 * offAxis, 1.0));
                    const glm::dvec3 across = glm::normalize(glm::cross(direction, glm::dvec3(0, 1, 0)));
                    const glm::dvec3 normal = glm::normalize(-std::cos(tilt) * direction + std::sin(tilt) * across);
                    visit(source, source.centroid + r * direction, normal, r);
                }
    }
}

} // namespace

TEST_SUITE("hierarchical") {

TEST_CASE("hierarchical far field: within 0.2% of Lambert's exact kernel where refinement uses it") {
    // A 0.1 m square (and a triangle) source seen from points at distance r with r^2 = 32 A (the
    // threshold) and beyond; the reference is Lambert's exact contour integral (clipped at the
    // horizon). The one-point disk estimate was 1.5-2.7% low here.
    int compared = 0;
    forEachObliqueReceiver(
        {32.0, 50.0, 100.0, 1000.0}, [](const PatchPolygon& source, double r2OverA) { return std::sqrt(r2OverA * source.area); },
        [&](const PatchPolygon& source, const glm::dvec3& x, const glm::dvec3& normal, double r) {
            const double exact = hierarchical::pointToElementFormFactor(x, normal, source);
            const double estimate = hierarchical::farFieldFormFactor(x, normal, source);
            REQUIRE(exact > 0);
            if (estimate < 0) return;  // straddles the horizon: the exact kernel is used
            ++compared;
            CHECK(estimate == doctest::Approx(exact).scale(0).epsilon(0.002));
            // The rows' precomputed nodes give the same rule (in float there: within 1e-6).
            CHECK(hierarchical::ruleFormFactor(x, normal, source, hierarchical::makeSourceRule(source), true) ==
                  doctest::Approx(estimate).scale(0).epsilon(1e-6));
            // No point sees more than a differential source facing it squarely would give.
            CHECK(exact <= source.area / (std::numbers::pi * r * r) * 1.01);
        });
    CHECK(compared > 120);
    // A source straddling the receiver's horizon is left to the exact kernel.
    // (Above the source's centre, its tangent plane nearly vertical: half the source lies behind it.)
    const PatchPolygon source = makeElementPolygon(std::vector<glm::dvec3>{{0, 0, 0}, {0.1, 0, 0}, {0.1, 0.1, 0}, {0, 0.1, 0}});
    const glm::dvec3 x = source.centroid + glm::dvec3(0, 0, 0.5);
    const glm::dvec3 steep = glm::normalize(glm::dvec3(1, 0, -0.02));
    CHECK(hierarchical::farFieldFormFactor(x, steep, source) < 0);
    CHECK(hierarchical::pointToElementFormFactor(x, steep, source, true) ==
          hierarchical::pointToElementFormFactor(x, steep, source));
}

TEST_CASE("hierarchical gather kernel: the 3 x 3 Gauss rule within 0.02% of Lambert's kernel where the rows use it") {
    // The gather rows' kernel between the exact contour integral and the far field: points whose
    // distance from the source's centroid, less sqrt(A), is sqrt(6 A) and beyond. The 2 x 2 rule is
    // 0.45% off at the nearest of them.
    int compared = 0;
    forEachObliqueReceiver(
        {hierarchical::kGaussDistanceSquaredOverArea, 10.0, 20.0, 32.0},
        [](const PatchPolygon& source, double nearest2OverA) {
            return std::sqrt(nearest2OverA * source.area) + std::sqrt(source.area);
        },
        [&](const PatchPolygon& source, const glm::dvec3& x, const glm::dvec3& normal, double) {
            const double exact = hierarchical::pointToElementFormFactor(x, normal, source);
            const double estimate = hierarchical::gaussFormFactor(x, normal, source);
            REQUIRE(exact > 0);
            if (estimate < 0) return;  // straddles the horizon: the exact kernel is used
            ++compared;
            CHECK(estimate == doctest::Approx(exact).scale(0).epsilon(2e-4));
            CHECK(hierarchical::ruleFormFactor(x, normal, source, hierarchical::makeSourceRule(source), false) ==
                  doctest::Approx(estimate).scale(0).epsilon(1e-6));
        });
    CHECK(compared > 120);
}

TEST_CASE("hierarchical link kernel: the source's rules give the catalog's form factors, as Lambert's integral did") {
    // Refinement's link kernel with the source's precomputed rules (each point by the rule its distance
    // allows, Lambert's integral nearer than 1 A or across the horizon) against the catalog: unit squares
    // directly opposed and perpendicular along a shared edge, whole and as quarter elements; and
    // against the kernel without rules (Lambert's integral at every point nearer than 32 A).
    const auto square = [](glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v) {
        return makeElementPolygon(std::vector<glm::dvec3>{origin, origin + u, origin + u + v, origin + v});
    };
    const glm::dvec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    for (const double c : {0.25, 0.5, 1.0, 2.0, 4.0}) {
        CAPTURE(c);
        const PatchPolygon lower = square(glm::dvec3(0.0), x, y), upper = square(c * z, y, x);
        const hierarchical::SourceRule rule = hierarchical::makeSourceRule(upper);
        const hierarchical::LinkKernel withRules = hierarchical::linkKernel(lower, upper, &rule);
        const hierarchical::LinkKernel exact = hierarchical::linkKernel(lower, upper);
        // The receiver's own 4-point or 3 x 3 rule leaves up to ~0.5% (the same without the source's rules).
        CHECK(withRules.mean == test::relativeTo(test::parallelRectangles(1, 1, c), 1e-2));
        CHECK(withRules.mean == test::relativeTo(exact.mean, 1e-4));
        CHECK(withRules.spread == doctest::Approx(exact.spread).scale(0).epsilon(1e-3));
        // A quarter of the upper square, seen from the lower square's opposite quarter: the rule's
        // distances count from the element's own size.
        const PatchPolygon quarter = square(c * z + 0.5 * x + 0.5 * y, 0.5 * y, 0.5 * x);
        const PatchPolygon receiver = square(glm::dvec3(0.0), 0.5 * x, 0.5 * y);
        const hierarchical::SourceRule quarterRule = hierarchical::makeSourceRule(quarter);
        CHECK(hierarchical::linkKernel(receiver, quarter, &quarterRule).mean ==
              test::relativeTo(hierarchical::linkKernel(receiver, quarter).mean, 1e-4));
    }
    for (const double h : {0.5, 1.0, 2.0}) {
        CAPTURE(h);
        const PatchPolygon floor = square(glm::dvec3(0.0), x, y), wall = square(glm::dvec3(0.0), y, h * z);
        const hierarchical::SourceRule rule = hierarchical::makeSourceRule(wall);
        const hierarchical::LinkKernel withRules = hierarchical::linkKernel(floor, wall, &rule);
        CHECK(withRules.mean == test::relativeTo(test::perpendicularRectangles(1, h, 1), 1e-2));
        CHECK(withRules.mean == test::relativeTo(hierarchical::linkKernel(floor, wall).mean, 1e-4));
    }
}

TEST_CASE("hierarchical gather kernel: the 5 x 5 Gauss rule within 0.02% of Lambert's kernel where the rows use it") {
    // Closer than the 3 x 3 rule's distance: points whose distance from the source's centroid, less
    // sqrt(A), is sqrt(A) (kNearGaussDistanceSquaredOverArea) up to the 3 x 3 rule's sqrt(6 A). On
    // random pairs at the nearest of them the 3 x 3 rule was up to 1.6% off (scratch study).
    int compared = 0;
    forEachObliqueReceiver(
        {hierarchical::kNearGaussDistanceSquaredOverArea, 2.0, 4.0, hierarchical::kGaussDistanceSquaredOverArea},
        [](const PatchPolygon& source, double nearest2OverA) {
            return std::sqrt(nearest2OverA * source.area) + std::sqrt(source.area);
        },
        [&](const PatchPolygon& source, const glm::dvec3& x, const glm::dvec3& normal, double) {
            const double exact = hierarchical::pointToElementFormFactor(x, normal, source);
            const hierarchical::SourceRule rule = hierarchical::makeSourceRule(source);
            const double estimate = hierarchical::ruleFormFactor(x, normal, source, rule, hierarchical::RuleOrder::Near);
            REQUIRE(exact > 0);
            if (estimate < 0) return;  // straddles the horizon: the exact kernel is used
            ++compared;
            CHECK(estimate == doctest::Approx(exact).scale(0).epsilon(2e-4));
        });
    CHECK(compared > 120);
}

TEST_CASE("hierarchical gather kernel: a source touching the point's tangent plane keeps the rules, within their accuracy") {
    // A point on a floor (normal +z) and a 0.1 m wall element standing on the floor's plane (the plane
    // x = d, facing -x, y in [y0, y0 + 0.1], z in [0, 0.1]): the element's lower corners lie on the
    // point's tangent plane, up to round-off once the whole pair is turned. The reference is the
    // catalog's differential element to a perpendicular rectangle with an edge on the element's
    // plane (Howell's B-3), by differences in y: F = G(y1) - G(y0) with
    //   G(b) = (atan(b / d) - d / sqrt(d^2 + c^2) atan(b / sqrt(d^2 + c^2))) / (2 pi).
    const auto catalog = [](double y0, double y1, double c, double d) {
        const double s = std::sqrt(d * d + c * c);
        const auto g = [&](double b) { return (std::atan(b / d) - d / s * std::atan(b / s)) / (2 * std::numbers::pi); };
        return g(y1) - g(y0);
    };
    const double side = 0.1;
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi);
    int gaussCompared = 0, farCompared = 0;
    for (int turn = 0; turn < 8; ++turn) {
        // A rotation about a random axis (the identity first): corners on the plane up to round-off.
        const glm::dvec3 axis = turn == 0 ? glm::dvec3(0, 0, 1)
                                          : glm::normalize(glm::dvec3(std::cos(angle(random)), std::sin(angle(random)), std::cos(angle(random))));
        const double by = turn == 0 ? 0.0 : angle(random);
        const auto turned = [&](const glm::dvec3& v) {
            return v * std::cos(by) + glm::cross(axis, v) * std::sin(by) + axis * glm::dot(axis, v) * (1 - std::cos(by));
        };
        // d = 0.01: the point almost under the wall's plane, beside the element along the floor.
        for (const double d : {0.01, 0.2, 0.35, 0.6, 1.0, 2.0})
            for (const double y0 : {-0.05, 0.1, 0.4, 1.0}) {
                CAPTURE(turn);
                CAPTURE(d);
                CAPTURE(y0);
                const double y1 = y0 + side;
                const std::vector<glm::dvec3> corners = {turned({d, y0, 0}), turned({d, y0, side}), turned({d, y1, side}), turned({d, y1, 0})};
                const PatchPolygon wall = makeElementPolygon(corners);
                REQUIRE(glm::dot(wall.normal, turned({-1, 0, 0})) == doctest::Approx(1.0).scale(0).epsilon(1e-12));
                const glm::dvec3 x = turned({0, 0, 0}), n = turned({0, 0, 1});
                const hierarchical::SourceRule rule = hierarchical::makeSourceRule(wall);
                const glm::dvec3 apart = wall.centroid - x;
                const double distance2 = glm::dot(apart, apart);
                const double exact = catalog(y0, y1, side, d);
                REQUIRE(exact > 0);
                if (distance2 > rule.gaussDistance2) {
                    ++gaussCompared;
                    const double gauss = hierarchical::ruleFormFactor(x, n, wall, rule, false);
                    CHECK(gauss == doctest::Approx(exact).scale(0).epsilon(2e-4));
                }
                if (distance2 > rule.farDistance2) {
                    ++farCompared;
                    const double far = hierarchical::ruleFormFactor(x, n, wall, rule, true);
                    CHECK(far == doctest::Approx(exact).scale(0).epsilon(2e-3));
                }
                // Lowered by a millimetre the element straddles the horizon: left to the exact kernel.
                const glm::dvec3 down = turned({0, 0, -0.001});
                const std::vector<glm::dvec3> lowered = {corners[0] + down, corners[1] + down, corners[2] + down, corners[3] + down};
                CHECK(hierarchical::ruleFormFactor(x, n, makeElementPolygon(lowered), rule, false) < 0);
            }
    }
    CHECK(gaussCompared >= 60);
    CHECK(farCompared >= 30);
}

TEST_CASE("hierarchical exact kernel in float: within 5e-6 of the double contour integral near the source, clipped polygons in double") {
    // The rows and refinement take Lambert's integral in float near a source (their weights are
    // floats), nearer than the 5 x 5 rule's distance (kNearGaussDistanceSquaredOverArea = 1): against
    // the double routine at points from a hundredth of sqrt(A) beyond the source's extent to four
    // times the rule's distance, tilted receivers, a quad and a triangle, and the same far from the
    // origin (offsets are taken in double before the float arithmetic). Farther, the edges' terms
    // cancel more (their sum is small against each) and float keeps 1e-4 at 1,000 A: the rules
    // stand in there anyway.
    int inFloat = 0, clipped = 0;
    for (const glm::dvec3 shift : {glm::dvec3(0.0), glm::dvec3(120.0, -80.0, 45.0)})
        forEachObliqueReceiver(
            {0.0001, 0.01, 0.1, 0.5, 1.0, 4.0, 32.0, 1000.0},
            [](const PatchPolygon& source, double nearest2OverA) { return std::sqrt(nearest2OverA * source.area) + std::sqrt(source.area); },
            [&](const PatchPolygon& unshifted, const glm::dvec3& point, const glm::dvec3& normal, double) {
                std::vector<glm::dvec3> corners;
                for (const glm::dvec3& corner : unshifted.corners()) corners.push_back(corner + shift);
                const PatchPolygon source = makeElementPolygon(corners);
                const glm::dvec3 x = point + shift;
                const double exact = hierarchical::pointToElementFormFactor(x, normal, source);
                const double single = hierarchical::pointToElementFormFactorFloat(x, normal, source);
                bool below = false;
                for (const glm::dvec3& corner : source.corners()) below = below || glm::dot(normal, corner - x) < 0;
                if (below) {
                    ++clipped;
                    CHECK(single == exact);  // clipped in double
                    return;
                }
                ++inFloat;
                REQUIRE(exact > 0);
                const double nearest2OverA = std::pow(glm::length(x - source.centroid) / std::sqrt(source.area) - 1, 2);
                CHECK(single == doctest::Approx(exact).scale(0).epsilon(nearest2OverA <= 4.01 ? 5e-6 : 1e-4));
            });
    CHECK(inFloat > 200);
    CHECK(clipped > 20);
    // Behind the source's emitting side: nothing, as the double routine.
    const PatchPolygon square = makeElementPolygon(std::vector<glm::dvec3>{{0, 0, 0}, {0.1, 0, 0}, {0.1, 0.1, 0}, {0, 0.1, 0}});
    CHECK(hierarchical::pointToElementFormFactorFloat({0.05, 0.05, -0.2}, {0, 0, 1}, square) == 0);
    // Straight above the square's centre, facing it: the catalog's parallel coaxial square.
    const double h = 0.1, a = 0.05 / h;
    const double catalog = 2 / std::numbers::pi * (a / std::sqrt(1 + a * a) * std::atan(a / std::sqrt(1 + a * a))) * 2;
    CHECK(hierarchical::pointToElementFormFactorFloat({0.05, 0.05, h}, {0, 0, -1}, square) == doctest::Approx(catalog).scale(0).epsilon(5e-6));
}

TEST_CASE("hierarchical exact kernel: its angle agrees with std::atan2 to 1e-15 over every quadrant used") {
    // angleOf replaces libm's atan2 in Lambert's contour integral: y >= 0, x of either sign, over 12
    // decades of the ratio, both on the branch boundaries (x = y, x = -y, x = 0) and between them.
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> uniform(-1, 1);
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
        const double y = std::abs(uniform(random)) * std::pow(10.0, 6 * uniform(random));
        double x = uniform(random) * std::pow(10.0, 6 * uniform(random));
        if (i % 7 == 0) x = 0;
        if (i % 11 == 0) x = y;
        if (i % 13 == 0) x = -y;
        if (i % 17 == 0) x = 2.41421356237309504880 * y * (1 + 1e-15);
        if (y == 0 && x == 0) continue;
        worst = std::max(worst, std::abs(hierarchical::angleOf(y, x) - std::atan2(y, x)));
    }
    CHECK(worst < 1e-15);
    CHECK(hierarchical::angleOf(1, 0) == doctest::Approx(std::numbers::pi / 2).scale(0).epsilon(1e-15));
    CHECK(hierarchical::angleOf(0, -1) == doctest::Approx(std::numbers::pi).scale(0).epsilon(1e-15));
    CHECK(hierarchical::angleOf(0, 1) == 0);
}

} // TEST_SUITE
