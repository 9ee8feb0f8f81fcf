// The convergence plot's GL-free parts: how steps are cut into per-method segments (restarts, material
// edits, a slider's drag), the CSV a student exports, and the axes' tick choice.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "app/solver/ConvergenceCsv.h"
#include "app/solver/ConvergenceRecord.h"
#include "app/ui/PlotAxes.h"

using namespace radiant;
using namespace radiant::app;

namespace {

IterationStats step(std::size_t iteration, double residual) {
    IterationStats stats;
    stats.iteration = iteration;
    stats.residual = residual;
    return stats;
}

/// Steps first .. first + count - 1 with residual 10^-k at the k-th.
void appendSteps(ConvergenceRecorder& recorder, std::size_t first, std::size_t count) {
    for (std::size_t k = 1; k <= count; ++k)
        recorder.append(step(first + k - 1, std::pow(10.0, -static_cast<double>(k))));
}

struct Shown {
    SolverMethod method;
    std::size_t index;
    std::string label;
    std::size_t steps;
};

std::vector<Shown> shown(const ConvergenceRecorder& recorder) {
    const ConvergenceRecord record = recorder.snapshot();
    const SolveHistory current = recorder.steps().snapshot();
    std::vector<Shown> out;
    for (const SegmentView& s : record.segments(current))
        out.push_back({s.info->method, s.info->index, s.info->label, s.steps->size()});
    return out;
}

} // namespace

TEST_SUITE("convergence record") {

TEST_CASE("convergence record: choosing another method keeps the first one's run to overlay, restarting a method replaces its own") {
    ConvergenceRecorder recorder(SolverMethod::Jacobi);
    appendSteps(recorder, 1, 14);
    recorder.restart(SolverMethod::GaussSeidel);
    appendSteps(recorder, 1, 8);
    std::vector<Shown> segments = shown(recorder);
    REQUIRE(segments.size() == 2);
    CHECK(segments[0].method == SolverMethod::Jacobi);
    CHECK(segments[0].label == "Jacobi");
    CHECK(segments[0].steps == 14);
    CHECK(segments[1].method == SolverMethod::GaussSeidel);
    CHECK(segments[1].label == "Gauss-Seidel");
    CHECK(segments[1].steps == 8);

    // Back to Jacobi: a new run from B = E replaces the old Jacobi curve, Gauss-Seidel's stays.
    recorder.restart(SolverMethod::Jacobi);
    appendSteps(recorder, 1, 3);
    segments = shown(recorder);
    REQUIRE(segments.size() == 2);
    CHECK(segments[0].method == SolverMethod::GaussSeidel);
    CHECK(segments[1].method == SolverMethod::Jacobi);
    CHECK(segments[1].steps == 3);

    // A new scene or mesh: nothing comparable is left.
    recorder.clear(SolverMethod::Jacobi);
    CHECK(shown(recorder).empty());
}

TEST_CASE("convergence record: a material edit starts a new labelled segment, and a drag stays one segment from its last value") {
    ConvergenceRecorder recorder(SolverMethod::GaussSeidel);
    appendSteps(recorder, 1, 6);
    recorder.materialEdited("light");
    appendSteps(recorder, 7, 2);
    recorder.materialEdited("light", true);  // the same slider, still dragged
    appendSteps(recorder, 9, 2);
    recorder.materialEdited("left wall");  // a new gesture
    appendSteps(recorder, 11, 4);
    const std::vector<Shown> segments = shown(recorder);
    REQUIRE(segments.size() == 3);
    CHECK(segments[0].index == 0);
    CHECK(segments[0].steps == 6);
    CHECK(segments[1].index == 1);
    CHECK(segments[1].label == "Gauss-Seidel, edit 1: light");
    CHECK(segments[1].steps == 2);  // from the drag's last value: no sawtooth inside the segment
    CHECK(segments[2].index == 2);
    CHECK(segments[2].label == "Gauss-Seidel, edit 2: left wall");
    CHECK(segments[2].steps == 4);

    // A restart after edits says the materials are not the scene's; restoring them says nothing.
    recorder.restart(SolverMethod::GaussSeidel);
    appendSteps(recorder, 1, 1);
    CHECK(shown(recorder).back().label == "Gauss-Seidel (edited materials)");
    CHECK(shown(recorder).size() == 1);
    recorder.materialsRestored(SolverMethod::GaussSeidel);
    appendSteps(recorder, 1, 1);
    CHECK(shown(recorder).back().label == "Gauss-Seidel");
}

TEST_CASE("convergence record: edits before any step fold into the segment they precede") {
    ConvergenceRecorder recorder(SolverMethod::Jacobi);
    recorder.materialEdited("light");  // before the first step: the run from B = E has these materials
    appendSteps(recorder, 1, 2);
    recorder.materialEdited("floor");
    recorder.materialEdited("ceiling");  // no step between: one segment, named by the last edit
    appendSteps(recorder, 3, 2);
    const std::vector<Shown> segments = shown(recorder);
    REQUIRE(segments.size() == 2);
    CHECK(segments[0].label == "Jacobi (edited materials)");
    CHECK(segments[0].index == 0);
    CHECK(segments[1].label == "Jacobi, edit 1: ceiling");
}

TEST_CASE("convergence record: a record handed out keeps its segments while the worker goes on") {
    ConvergenceRecorder recorder(SolverMethod::Jacobi);
    appendSteps(recorder, 1, 5);
    recorder.restart(SolverMethod::GaussSeidel);
    appendSteps(recorder, 1, 2);
    const ConvergenceRecord before = recorder.snapshot();
    const SolveHistory beforeSteps = recorder.steps().snapshot();
    recorder.restart(SolverMethod::Jacobi);  // drops Jacobi's run from the recorder's list
    appendSteps(recorder, 1, 1);
    const std::vector<SegmentView> old = before.segments(beforeSteps);
    REQUIRE(old.size() == 2);
    CHECK(old[0].info->method == SolverMethod::Jacobi);
    CHECK(old[0].steps->size() == 5);
    CHECK(old[1].steps->size() == 2);
}

TEST_CASE("convergence CSV: one row per step of every segment, the quantity named, values that read back exactly") {
    ConvergenceRecorder recorder(SolverMethod::Jacobi);
    recorder.append(step(1, 0.5));
    recorder.append(step(2, 0.1));
    recorder.materialEdited("light, \"north\"");
    recorder.append(step(3, 0.3));
    recorder.restart(SolverMethod::Progressive);
    recorder.append(step(1, 1.0 / 3.0));
    const std::string csv = convergenceCsv(recorder.snapshot(), recorder.steps().snapshot());
    CHECK(csv == "method,segment,label,iteration,solver_iteration,quantity,value\n"
                 "jacobi,0,Jacobi,1,1,residual_fraction,0.5\n"
                 "jacobi,0,Jacobi,2,2,residual_fraction,0.1\n"
                 "jacobi,1,\"Jacobi, edit 1: light, \"\"north\"\"\",1,3,residual_fraction,0.3\n"
                 "progressive,0,Progressive refinement (edited materials),1,1,unshot_power_fraction,"
                 "0.3333333333333333\n");
}

TEST_CASE("convergence: the first step below the tolerance is the one the legend quotes") {
    ConvergenceRecorder recorder(SolverMethod::GaussSeidel);
    appendSteps(recorder, 1, 6);  // 1e-1 .. 1e-6
    const SolveHistory steps = recorder.steps().snapshot();
    CHECK(firstStepBelow(steps, 1e-4 * 1.0001) == 4);  // 1e-4 is below 1.0001e-4
    CHECK(firstStepBelow(steps, 1e-4) == 5);           // strictly below, as Run stops
    CHECK_FALSE(firstStepBelow(steps, 1e-7).has_value());
}

TEST_CASE("plot axes: a log axis spans whole decades around the values, ticked at decades or every few") {
    const std::vector<double> values{3e-5, 0.8, 0.0, -1.0, 2e-3};  // zero and negatives cannot be drawn
    ui::LogAxis axis = ui::logAxisFor(values, 10);
    CHECK(axis.lowExponent == -5);
    CHECK(axis.highExponent == 0);
    CHECK(axis.tickExponents == std::vector<int>{-5, -4, -3, -2, -1, 0});

    axis = ui::logAxisFor(values, 3);  // six decades in three ticks: every second one, on 1e0
    CHECK(axis.tickExponents == std::vector<int>{-4, -2, 0});

    const std::vector<double> narrow{0.2, 0.3};
    axis = ui::logAxisFor(narrow, 10, 2);
    CHECK(axis.lowExponent == -1);
    CHECK(axis.highExponent == 1);  // at least two decades

    axis = ui::logAxisFor(std::vector<double>{}, 10);
    CHECK(axis.lowExponent == -1);
    CHECK(axis.highExponent == 0);
}

TEST_CASE("plot axes: linear ticks at 1-2-5 steps within the range") {
    CHECK(ui::linearTicks(1, 14, 8) == std::vector<double>{2, 4, 6, 8, 10, 12, 14});
    CHECK(ui::linearTicks(1, 14, 3) == std::vector<double>{5, 10});
    CHECK(ui::linearTicks(1, 3000, 4) == std::vector<double>{1000, 2000, 3000});
    CHECK(ui::linearTicks(0, 1, 5) == std::vector<double>{0, 0.5, 1});
    CHECK(ui::linearTicks(4, 4, 5) == std::vector<double>{4});
    CHECK(ui::linearTicks(1, 2, 5, 1.0) == std::vector<double>{1, 2});  // iterations: no 1.5
}

} // TEST_SUITE
