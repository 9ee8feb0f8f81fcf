// Progressive refinement against converged Gauss-Seidel on the same mesh (issue 14) in the narrow gap
// between the Cornell box's blocks: the short block's side 3 faces the tall block's front across
// 5-10 cm. Both methods solve the same equation on the same patches with the same kernel, so the
// converged progressive answer must agree there patch by patch and at the accuracy bench's point
// (app/bench/BenchAccuracy.cpp reads it as the probe does: E gathered from the patches, B = M + rho E).
#include <doctest/doctest.h>

#include <algorithm>
#include <memory>
#include <cmath>
#include <string>
#include <vector>

#include "radiometry/geometry/RayCaster.h"
#include "radiometry/probe/Probe.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/ProgressiveSolver.h"
#include "radiometry/solver/SolveDefaults.h"
#include "radiometry/solver/SolverFactories.h"

using namespace radiant;

namespace {

double brightness(const Rgb& b) { return b.x + b.y + b.z; }

struct FaceAgreement {
    std::size_t counted = 0;
    double mean = 0, worst = 0;
};

/// |B_progressive / B_reference - 1| (band sums) over the patches of one face of a surface.
FaceAgreement faceAgreement(const PatchMesh& mesh, std::size_t surface, std::uint32_t face,
                            const std::vector<Rgb>& solution, const std::vector<Rgb>& reference) {
    FaceAgreement agreement;
    for (std::size_t i = mesh.surfaceFirstPatch[surface]; i < mesh.surfaceFirstPatch[surface + 1]; ++i) {
        if (mesh.patches[i].face != face) continue;
        const double error = std::abs(brightness(solution[i]) / brightness(reference[i]) - 1);
        agreement.mean += error;
        agreement.worst = std::max(agreement.worst, error);
        ++agreement.counted;
    }
    if (agreement.counted > 0) agreement.mean /= static_cast<double>(agreement.counted);
    return agreement;
}

void solveGapTo(Solver& solver, double residual, std::size_t maxSteps = 200000) {
    for (std::size_t k = 0; k < maxSteps && solver.lastStats().residual > residual; ++k) solver.step();
    REQUIRE(solver.lastStats().residual <= residual);
}

/// The Cornell box at the default mesh (2,170 patches) and Gauss-Seidel on it stepped to 1e-8: the
/// oracle both test cases compare with, solved once.
struct GapFixture {
    Scene cornell = makeCornellBox();
    PatchMesh mesh;
    std::shared_ptr<const RayCaster> rays;
    std::vector<Rgb> converged;
    std::size_t shortBlock = 0, tallBlock = 0;

    GapFixture() {
        MeshingOptions meshing;
        meshing.maxPatchArea = kSolveDefaults.maxPatchArea;
        mesh = meshScene(cornell, meshing);
        rays = std::make_shared<const RayCaster>(cornell);
        SolverOptions options;
        options.rays = rays;
        auto reference = makeSolver(SolverMethod::GaussSeidel, cornell, mesh, options);
        solveGapTo(*reference, 1e-8);
        converged = reference->solution();
        shortBlock = cornell.findSurface("short block");
        tallBlock = cornell.findSurface("tall block");
    }
};

const GapFixture& gapFixture() {
    static const GapFixture fixture;
    return fixture;
}

struct GapAgreement {
    FaceAgreement shortSide, tallFront;
    double atPoint = 0;  ///< |B_progressive / B_converged - 1| at the bench's point, as the probe reads it
};

/// Progressive refinement with `block` x `block` shooters to the default tolerance, against the fixture.
GapAgreement progressiveInTheGap(std::size_t block) {
    const GapFixture& f = gapFixture();
    SolverOptions options;
    options.rays = f.rays;
    ProgressiveOptions progressive;
    progressive.shooterBlock = block;
    auto solver = makeProgressiveSolver(f.cornell, f.mesh, options, progressive);
    solveGapTo(*solver, kSolveDefaults.tolerance);
    GapAgreement agreement;
    // The short block's face 3 (towards the tall block) and the tall block's face 1 (its front).
    agreement.shortSide = faceAgreement(f.mesh, f.shortBlock, 3, solver->solution(), f.converged);
    agreement.tallFront = faceAgreement(f.mesh, f.tallBlock, 1, solver->solution(), f.converged);
    // The bench's point: the centre of the short block's side 3.
    const Face& side = f.cornell.surfaces[f.shortBlock].faces[3];
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& v : side.vertices) centre += v / static_cast<double>(side.vertices.size());
    const Probe probe(f.cornell, f.mesh, f.rays.get());
    const double converged = brightness(probe.measure(centre, side.normal, f.converged).radiosity.value());
    agreement.atPoint = std::abs(brightness(probe.measure(centre, side.normal, solver->solution()).radiosity.value()) / converged - 1);
    MESSAGE("block ", block, " (", solver->shooters().size(), " shooters): short block side 3 (",
            agreement.shortSide.counted, " patches) mean ", agreement.shortSide.mean, " worst ", agreement.shortSide.worst,
            "; tall block front (", agreement.tallFront.counted, ") mean ", agreement.tallFront.mean, " worst ",
            agreement.tallFront.worst, "; at the point ", agreement.atPoint);
    return agreement;
}

} // namespace

TEST_SUITE("progressive") {

// ctest-case-labels: heavy
TEST_CASE("Cornell box at the default mesh: default progressive matches converged Gauss-Seidel in the blocks' gap") {
    // The default shooter count gives blocks of 7 here (62 shooters; the short block's side is one).
    // With the full penumbra ray count only for shots of 25% of the emitted power or more, the few
    // shots of such blocks left their few-ray visibility noise in place (seed 1): at the point 1.5%,
    // side 3 patches mean 6.0% / worst 41%, tall front 4.0% / 48% (seed 7 alike). Not the unshot
    // tolerance (the same to 1e-6), nor the kernel (each member's exact kernel: the same). With
    // kFullPenumbraShare 0.02: 0.12%, 1.4% / 9.5%, 1.1% / 7.3%. For scale: 3 x 3 blocks at the old
    // share 0.17%, 1.1%, 1.1% (2.6x the solve time); every patch alone 0.095%, 0.54%, 0.43% (20x).
    const GapAgreement gap = progressiveInTheGap(0);
    CHECK(gap.atPoint < 0.005);
    CHECK(gap.shortSide.mean < 0.02);
    CHECK(gap.tallFront.mean < 0.02);
}

} // TEST_SUITE
