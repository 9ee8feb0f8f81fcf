// The one table of methods: a sixth method is its own files plus a row in the table. A method this
// test registers (a Gauss-Seidel in disguise, so its answer has a closed form) must reach every list
// the program shows — the command line's help and parser, the solver thread, the bench's and the
// Solver panel's iteration over solverMethods() — with no other file changed.
// ctest-labels: threads
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli/CommandLine.h"
#include "app/solver/SolverThread.h"
#include "radiometry/common/Check.h"
#include "radiometry/common/Error.h"
#include "radiometry/scene/SceneLibrary.h"
#include "radiometry/solver/Solver.h"
#include "radiometry/solver/SolverFactories.h"
#include "radiometry/solver/SolverMethods.h"
#include "tests/support/Relative.h"

using namespace radiant;

namespace {

constexpr SolverMethod kDummy = static_cast<SolverMethod>(100);

/// Reports itself as the dummy method and lets Gauss-Seidel do the work.
class DummySolver final : public Solver {
public:
    explicit DummySolver(std::unique_ptr<Solver> inner) : inner_(std::move(inner)) {}
    [[nodiscard]] SolverMethod method() const override { return kDummy; }
    IterationStats step() override { return inner_->step(); }
    [[nodiscard]] const std::vector<Rgb>& solution() const override { return inner_->solution(); }
    void setMaterial(std::size_t surface, const Rgb& reflectance, const ExitanceRgb& exitance) override {
        inner_->setMaterial(surface, reflectance, exitance);
    }
    void reset() override { inner_->reset(); }
    [[nodiscard]] const IterationStats& lastStats() const override { return inner_->lastStats(); }

private:
    std::unique_ptr<Solver> inner_;
};

std::unique_ptr<Solver> makeDummySolver(const Scene& scene, const PatchMesh& mesh, const SolverOptions& options,
                                        Progress* progress) {
    return std::make_unique<DummySolver>(makeGaussSeidelSolver(scene, mesh, options, progress));
}

constexpr SolverMethodInfo kDummyRow = {kDummy,           "dummy", "Dummy (test)", "as Gauss-Seidel's",
                                        {.formFactorMatrix = true}, makeDummySolver};

} // namespace

TEST_SUITE("method table") {

TEST_CASE("a registered method joins the table, the names and the parser, and leaves with its registration") {
    const std::size_t builtins = solverMethods().size();
    CHECK(builtins == 5);
    {
        const SolverMethodRegistration registration = registerSolverMethod(kDummyRow);
        REQUIRE(solverMethods().size() == builtins + 1);
        CHECK(solverMethods().back().name == "dummy");
        CHECK(parseMethod("dummy") == kDummy);
        CHECK(methodName(kDummy) == "dummy");
        CHECK(methodInfo(kDummy).label == "Dummy (test)");
        CHECK(methodNameList().ends_with("importance or dummy"));
        // A second row with a known id or name is a bug in the caller, caught with both values.
        CHECK_THROWS_AS((void)registerSolverMethod(kDummyRow), InvariantError);
    }
    CHECK(solverMethods().size() == builtins);
    CHECK(methodNameList().ends_with("hierarchical or importance"));
    CHECK_THROWS_AS(parseMethod("dummy"), RadiantError);
}

TEST_CASE("the command line solves with a registered method: the furnace's B = E / (1 - rho)") {
    const SolverMethodRegistration registration = registerSolverMethod(kDummyRow);
    const std::filesystem::path json = std::filesystem::temp_directory_path() / "radiant-test-dummy-method.json";
    const std::string jsonArgument = json.string();
    const char* argv[] = {"radiant", "solve", "furnace", "--method", "dummy", "--max-patch-area", "0.25",
                          "--tolerance", "1e-9", "--json", jsonArgument.c_str()};
    REQUIRE(app::runCommandLine(static_cast<int>(std::size(argv)), const_cast<char**>(argv)) == 0);
    std::ifstream in(json);
    const nlohmann::json report = nlohmann::json::parse(in);
    std::filesystem::remove(json);
    CHECK(report["method"] == "dummy");
    REQUIRE(report["surfaces"].size() == 6);
    // Every face of the furnace emits 1 W/m^2 with rho 0.5: B = 2 W/m^2, up to the form factors'
    // row sums (within 0.5% on this mesh, as the solver tests measure).
    for (const auto& surface : report["surfaces"])
        for (int band = 0; band < 3; ++band)
            CHECK(surface["radiosity_W_m2"][band].get<double>() == test::relativeTo(2.0, 5e-3));
}

TEST_CASE("the solver thread runs a registered method from SetMethod") {
    const SolverMethodRegistration registration = registerSolverMethod(kDummyRow);
    auto furnace = std::make_shared<const Scene>(loadScene("furnace").scene);
    app::SolverThread thread;
    thread.send(app::command::LoadScene{furnace, MeshingOptions{0.25}});
    thread.send(app::command::SetMethod{kDummy});
    thread.send(app::command::Step{40});
    thread.waitUntilIdle();
    const auto snapshot = thread.snapshot();
    REQUIRE(snapshot->error.empty());
    CHECK(snapshot->method == kDummy);
    REQUIRE_FALSE(snapshot->radiosity.empty());
    for (const Rgb& b : snapshot->radiosity) CHECK(b.x == test::relativeTo(2.0, 5e-3));
}

} // TEST_SUITE
