// Limits: requests too big for the machine are refused with the numbers before anything is
// allocated, allocation failures become errors, and non-finite radiosity never reaches the display.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <new>
#include <string>

#include "app/solver/SolverThread.h"
#include "radiometry/common/Error.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "radiometry/solver/FormFactorMatrix.h"
#include "radiometry/solver/FormFactorMatrixBudget.h"
#include "tests/support/Common.h"

using namespace radiant;
using namespace radiant::app;

namespace {

using radiant::test::contains;

/// A scene of one unit square (reflectance 0.5, exitance 1 W/m^2).
std::shared_ptr<const Scene> unitSquare() {
    auto scene = std::make_shared<Scene>();
    scene->name = "square";
    scene->materials.push_back({"grey", Rgb(0.5), ExitanceRgb(Rgb(1.0))});
    Face face;
    face.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    face.updateGeometry();
    scene->surfaces.push_back({"square", 0, {face}, "test"});
    return scene;
}

/// Multiplies every patch's radiosity by `factor` each step: finite for a while, then not (an
/// unstable iteration, as a reflectance above one would make).
class ExplodingSolver final : public Solver {
public:
    ExplodingSolver(std::size_t patches, double factor) : factor_(factor), b_(patches, Rgb(1.0)) {}
    [[nodiscard]] SolverMethod method() const override { return SolverMethod::Jacobi; }
    IterationStats step() override {
        for (Rgb& b : b_) b *= factor_;
        stats_.iteration += 1;
        stats_.residual = 1;
        return stats_;
    }
    [[nodiscard]] const std::vector<Rgb>& solution() const override { return b_; }
    void setMaterial(std::size_t, const Rgb&, const ExitanceRgb&) override {}
    void reset() override {
        stats_ = {};
        for (Rgb& b : b_) b = Rgb(1.0);
    }
    [[nodiscard]] const IterationStats& lastStats() const override { return stats_; }

private:
    double factor_;
    std::vector<Rgb> b_;
    IterationStats stats_;
};

bool allFinite(const std::vector<Rgb>& values) {
    for (const Rgb& b : values)
        if (!std::isfinite(b.x) || !std::isfinite(b.y) || !std::isfinite(b.z)) return false;
    return true;
}

} // namespace

TEST_SUITE("limits") {

TEST_CASE("meshing over the patch budget is refused with the numbers") {
    const Scene box = makeCornellBox();
    MeshingOptions options;
    options.maxPatchArea = 1e-8;  // ~ 10^8 patches on the box's few m^2
    options.patchBudget = 2'000'000;
    try {
        (void)meshScene(box, options);
        FAIL("meshing 1e-8 m^2 patches should have been refused");
    } catch (const BudgetError& e) {
        INFO(e.what());
        CHECK(contains(e.what(), "2e+06"));  // the budget, as the message prints it
    }
    // Sizes that are not sizes are refused too, not meshed into nothing or forever.
    for (const double area : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
        CHECK_THROWS_AS((void)meshScene(box, MeshingOptions{area, 1000}), RadiantError);
}

TEST_CASE("the form-factor memory estimate bounds what a computed matrix holds") {
    // Two facing unit squares 1 m apart, each cut into 4 x 4: every cross pair is visible.
    const Scene plates = makeParallelPlates();
    const PatchMesh mesh = meshScene(plates, MeshingOptions{1.0 / 16, 1000});
    REQUIRE(mesh.size() == 32);
    const FormFactorMatrix matrix = FormFactorMatrix::compute(mesh, nullptr, {}, 0.0);
    // 16 x 16 pairs, both directions kept: the entries alone.
    CHECK(matrix.entryCount() == 2 * 16 * 16);
    CHECK(static_cast<double>(matrix.bytes()) <= formFactorMatrixPeakBytes(mesh.size()));
    // The estimate grows as n^2: a quarter of the patches, about a sixteenth of the bytes.
    CHECK(formFactorMatrixPeakBytes(40'000) / formFactorMatrixPeakBytes(10'000) == doctest::Approx(16).epsilon(0.01).scale(0));
}

TEST_CASE("a gathering solver whose matrix exceeds the memory budget is refused before allocating") {
    // ~ 40 000 patches on the unit cube's six square metres.
    const Scene cube = makeUnitCube();
    const PatchMesh mesh = meshScene(cube, MeshingOptions{6.0 / 40'000, 1'000'000});
    REQUIRE(mesh.size() > 30'000);
    for (const SolverMethod method : {SolverMethod::Jacobi, SolverMethod::GaussSeidel}) {
        try {
            (void)makeSolver(method, cube, mesh, SolverOptions{});
            FAIL("a matrix of " << mesh.size() << " patches should exceed the 4 GB budget");
        } catch (const BudgetError& e) {
            const std::string message = e.what();
            INFO(message);
            CHECK(contains(message, std::to_string(mesh.size()) + " patches"));
            CHECK(contains(message, "the budget is 4"));
            CHECK(contains(message, "progressive or hierarchical"));
        }
    }
    // A budget is a setting: the same small mesh builds under a large budget and not under a tiny one.
    const PatchMesh small = meshScene(cube, MeshingOptions{0.25, 1000});
    SolverOptions tiny;
    tiny.matrixBudgetBytes = 1000;
    CHECK_THROWS_AS((void)makeSolver(SolverMethod::GaussSeidel, cube, small, tiny), BudgetError);
    CHECK_NOTHROW((void)makeSolver(SolverMethod::GaussSeidel, cube, small, SolverOptions{}));
}

TEST_CASE("radiant solve reports an over-budget matrix as a one-line error, exit status 2") {
    const std::string command = std::string("'") + RADIANT_BINARY +
                                "' solve cornell-box --method jacobi --max-patch-area 0.00005 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe);
    std::string output;
    std::array<char, 512> chunk{};
    while (std::fgets(chunk.data(), static_cast<int>(chunk.size()), pipe)) output += chunk.data();
    const int status = pclose(pipe);
    INFO(output);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 2);
    CHECK(contains(output, "form-factor matrix"));
    CHECK(contains(output, "budget"));
}

TEST_CASE("std::bad_alloc while building a solver becomes the snapshot's error, and the thread goes on") {
    // Under AddressSanitizer a real giant allocation aborts instead of throwing, so the failure is
    // injected where form factors would be computed.
    const SolverFactory factory = [](SolverMethod method, const Scene& scene, const PatchMesh& mesh,
                                     const SolverOptions& options, Progress* progress) -> std::unique_ptr<Solver> {
        if (method == SolverMethod::Jacobi) throw std::bad_alloc();
        return makeSolver(method, scene, mesh, options, progress);
    };
    SolverThread thread({}, factory);
    thread.send(command::SetMethod{SolverMethod::Jacobi});
    thread.send(command::LoadScene{unitSquare(), MeshingOptions{0.25, 1000}});
    thread.waitUntilIdle();
    auto snapshot = thread.snapshot();
    INFO(snapshot->error);
    CHECK(contains(snapshot->error, "bad_alloc"));
    CHECK(!snapshot->running);

    // The worker survived: another method builds and solves (one square: B = E, nothing to gather).
    thread.send(command::SetMethod{SolverMethod::GaussSeidel});
    thread.send(command::Step{2});
    thread.waitUntilIdle();
    snapshot = thread.snapshot();
    CHECK(snapshot->error.empty());
    CHECK(snapshot->stats.iteration == 2);
    REQUIRE(snapshot->radiosity.size() == 4);
    CHECK(snapshot->radiosity[0].x == doctest::Approx(1.0).scale(0));
}

TEST_CASE("non-finite radiosity is never published: the error shows and stepping stops") {
    // x 1e100 per step: 1e100, 1e200, then inf (and inf stays inf) on the third step.
    const SolverFactory factory = [](SolverMethod, const Scene&, const PatchMesh& mesh, const SolverOptions&,
                                     Progress*) { return std::make_unique<ExplodingSolver>(mesh.size(), 1e100); };
    SolverThread thread({}, factory);
    thread.send(command::LoadScene{unitSquare(), MeshingOptions{0.25, 1000}});
    thread.send(command::Step{2});
    thread.waitUntilIdle();
    auto snapshot = thread.snapshot();
    REQUIRE(snapshot->error.empty());
    REQUIRE(snapshot->radiosity.size() == 4);
    CHECK(snapshot->radiosity[0].x == doctest::Approx(1e200).scale(0));

    thread.send(command::Run{});
    thread.waitUntilIdle();  // returns: the guard stops the run although the residual never drops
    snapshot = thread.snapshot();
    INFO(snapshot->error);
    CHECK(contains(snapshot->error, "no longer finite"));
    CHECK(!snapshot->running);
    CHECK(allFinite(snapshot->radiosity));
    // The last finite picture of this mesh stays on screen.
    REQUIRE(snapshot->radiosity.size() == 4);
    CHECK(snapshot->radiosity[0].x == doctest::Approx(1e200).scale(0));

    // NaN as well as infinity.
    const SolverFactory nanFactory = [](SolverMethod, const Scene&, const PatchMesh& mesh, const SolverOptions&,
                                        Progress*) {
        return std::make_unique<ExplodingSolver>(mesh.size(), std::numeric_limits<double>::quiet_NaN());
    };
    SolverThread nanThread({}, nanFactory);
    nanThread.send(command::LoadScene{unitSquare(), MeshingOptions{0.25, 1000}});
    nanThread.send(command::Step{5});
    nanThread.waitUntilIdle();
    snapshot = nanThread.snapshot();
    CHECK(contains(snapshot->error, "no longer finite"));
    CHECK(allFinite(snapshot->radiosity));
    CHECK(!snapshot->running);
}

} // TEST_SUITE
