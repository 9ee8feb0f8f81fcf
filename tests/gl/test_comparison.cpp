// Comparison mode in the real lab (issue #16 item 5): two solver threads on one scene, the 3D view in
// two halves with one camera, the difference view, and the probe reading both solutions. The furnace
// has a closed form (B = E / (1 - rho) on every patch, whatever the method or mesh), so both halves,
// the difference and both probe readings are checked against it; the Cornell box shows that two
// methods converged on one mesh draw the same picture in both halves.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/Lab.h"
#include "app/ui/Theme.h"
#include "render/ColourScale.h"
#include "render/camera/Camera.h"
#include "tests/gl/FrameUntil.h"
#include "tests/gl/RequireDisplay.h"

using namespace radiant;
using radiant::app::ComparisonSettings;
using radiant::app::ComparisonView;
using radiant::app::Lab;
using radiant::app::LabOptions;
namespace command = radiant::app::command;

using radiant::test::frameUntil;
using radiant::test::requireDisplay;

namespace {

LabOptions options(const char* scene, double patchArea) {
    LabOptions o;
    o.scene = scene;
    o.width = 800;
    o.height = 500;
    o.showPanels = false;  // the 3D view fills the window
    o.vsync = false;
    o.maxPatchArea = patchArea;
    o.runOnStart = false;
    return o;
}

bool converged(const std::shared_ptr<const app::Snapshot>& s) {
    return s && s->mesh && s->solverBuilds > 0 && s->stats.iteration > 0 && !s->running && s->stats.residual < s->tolerance;
}

/// Runs both solvers to their tolerance and draws until the lab shows both.
void solveBoth(Lab& lab) {
    lab.send(command::Run{});
    frameUntil(lab, [&] { return converged(lab.snapshot()) && converged(lab.secondSnapshot()); });
    lab.frame();
}

double relativeError(double a, double b) { return std::abs(a - b) / std::abs(b); }

/// Share of the pixels of `view` (rows from `top` down) that differ from the backdrop.
double sceneShare(const render::ImageRgb8& image, const render::Viewport& view, int top) {
    const glm::dvec3 backdrop = 255.0 * glm::dvec3(app::kBackdrop.r, app::kBackdrop.g, app::kBackdrop.b);
    std::size_t scene = 0, all = 0;
    for (int y = view.y + top; y < view.y + view.height; ++y)
        for (int x = view.x; x < view.x + view.width; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 3;
            const glm::dvec3 c(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]);
            scene += glm::length(c - backdrop) > 6.0 ? 1 : 0;
            ++all;
        }
    return static_cast<double>(scene) / static_cast<double>(all);
}

/// Mean absolute difference (0..255) between the two halves, pixel by pixel, below row `top`.
double halvesDiffer(const render::ImageRgb8& image, const render::Viewport& left, const render::Viewport& right, int top) {
    double sum = 0;
    std::size_t count = 0;
    const int width = std::min(left.width, right.width);
    for (int y = left.y + top; y < left.y + left.height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto at = [&](int column) {
                return (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(column)) * 3;
            };
            const std::size_t a = at(left.x + x), b = at(right.x + x);
            for (int band = 0; band < 3; ++band) sum += std::abs(int(image.pixels[a + band]) - int(image.pixels[b + band]));
            count += 3;
        }
    return sum / static_cast<double>(count);
}

} // namespace

TEST_SUITE("gl lab") {

TEST_CASE("comparison mode: Jacobi and Gauss-Seidel on two meshes of the furnace both give E / (1 - rho), in both halves, "
          "in the difference view and at the probe") {
    requireDisplay();
    Lab lab(options("furnace", 0.1));
    lab.send(command::SetMethod{SolverMethod::Jacobi});
    lab.send(command::SetTolerance{1e-7});
    ComparisonSettings settings;
    settings.method = SolverMethod::GaussSeidel;
    settings.patchAreaScale = 0.25;  // B twice as fine: the difference view maps B's patches onto A's
    lab.setComparison(settings);
    lab.pressKey(GLFW_KEY_V);  // the lecturer's key: side by side
    REQUIRE(lab.secondSnapshot());
    solveBoth(lab);
    const std::shared_ptr<const app::Snapshot> solvedA = lab.snapshot(), solvedB = lab.secondSnapshot();
    const app::Snapshot& a = *solvedA;
    const app::Snapshot& b = *solvedB;
    CHECK(a.method == SolverMethod::Jacobi);
    CHECK(b.method == SolverMethod::GaussSeidel);
    CHECK(b.mesh->size() >= 3 * a.mesh->size());
    CHECK(b.stats.iteration < a.stats.iteration);  // Gauss-Seidel needs fewer sweeps
    const Material& wall = a.scene->materials.at(0);
    const double exact = wall.exitance.value().x / (1 - wall.reflectance.x);  // 2 W/m^2 per band
    // Meshed form factors close each row only to quadrature accuracy (measured: within 1e-5 here).
    for (const app::Snapshot* s : {&a, &b})
        for (const Rgb& radiosity : s->radiosity) CHECK(relativeError(radiosity.x, exact) < 1e-3);

    // Both halves show the scene, with one camera: a uniform furnace looks the same in each.
    const render::ImageRgb8 image = lab.frameAndCapture();
    const std::vector<render::Viewport> halves = lab.sceneViews();
    REQUIRE(halves.size() == 2);
    CHECK(halves[0].x + halves[0].width == halves[1].x);
    const int belowLabels = halves[0].height / 4;
    CHECK(sceneShare(image, halves[0], belowLabels) > 0.5);
    CHECK(sceneShare(image, halves[1], belowLabels) > 0.5);
    CHECK(halvesDiffer(image, halves[0], halves[1], belowLabels) < 6.0);

    // A click in B's half probes the same scene; the probe reads both solutions there.
    const glm::dvec2 click{halves[1].x + halves[1].width / 2.0, halves[1].y + halves[1].height / 2.0};
    REQUIRE(lab.clickAt(click));
    frameUntil(lab, [&] { return lab.probeGeneration() == lab.snapshot()->generation && lab.probeReading() && lab.secondProbeReading(); });
    const ProbeReading readingA = *lab.probeReading();
    const ProbeReading readingB = *lab.secondProbeReading();
    CHECK(glm::length(readingA.at.point - readingB.at.point) < 1e-9);
    for (const ProbeReading* r : {&readingA, &readingB}) {
        CHECK(relativeError(r->patchRadiosity.value().x, exact) < 1e-3);
        CHECK(relativeError(r->radiosity.value().x, exact) < 1e-3);  // M + rho E gathered at the point
    }
    CHECK(app::relativeDifference(readingA.patchRadiosity.value(), readingB.patchRadiosity.value()) < 1e-3);

    // V again: the difference, on B's finer mesh, everywhere near 0 (the bottom of the colour map).
    lab.pressKey(GLFW_KEY_V);
    lab.pressKey(GLFW_KEY_S);  // the dome over the probe point off: the view alone
    lab.frame();
    const render::ImageRgb8 difference = lab.frameAndCapture();
    REQUIRE(lab.sceneViews().size() == 1);
    const app::SolutionDifference& d = lab.comparisonDifference();
    REQUIRE(d.mesh);
    CHECK(d.mesh == lab.secondSnapshot()->mesh);
    CHECK_FALSE(d.onFirst);
    CHECK(d.maxRelative < 1e-3);  // measured 2.2e-5
    const render::Viewport view = lab.sceneViews().front();
    // Every patch under 0.1% apart: the colour map's bottom, viridis(0), all over the view, or on a
    // patch edge a mix of it with the wireframe's dark grey (shaders/patch.frag.glsl).
    const glm::dvec3 bottom = 255.0 * render::viridis(0.0);
    const glm::dvec3 edge = 255.0 * glm::dvec3(0.06, 0.07, 0.09);
    const auto offBottom = [&](const glm::dvec3& c) {
        const double t = std::clamp(glm::dot(c - bottom, edge - bottom) / glm::dot(edge - bottom, edge - bottom), 0.0, 1.0);
        return glm::length(c - (bottom + t * (edge - bottom)));
    };
    std::size_t near = 0, all = 0;
    for (int y = view.y + view.height / 4; y < view.y + view.height; y += 4)
        for (int x = view.x + view.width / 8; x < view.x + 5 * view.width / 8; x += 4) {  // left of the legend
            const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(difference.width) + static_cast<std::size_t>(x)) * 3;
            const glm::dvec3 c(difference.pixels[i], difference.pixels[i + 1], difference.pixels[i + 2]);
            ++all;
            near += offBottom(c) < 12.0 ? 1 : 0;  // the probe's marker aside
        }
    CHECK(static_cast<double>(near) / static_cast<double>(all) > 0.98);

    lab.pressKey(GLFW_KEY_V);  // off
    lab.frame();
    CHECK_FALSE(lab.secondSnapshot());
    CHECK(lab.sceneViews().size() == 1);
}

TEST_CASE("comparison mode: the probe reads B only once B has stepped, not its initial guess while it is ready or "
          "computing form factors") {
    requireDisplay();
    Lab lab(options("furnace", 0.1));
    lab.send(command::SetMethod{SolverMethod::Jacobi});
    ComparisonSettings settings;
    settings.method = SolverMethod::GaussSeidel;
    lab.setComparison(settings);
    lab.compare(true);
    REQUIRE(lab.secondSnapshot());
    const auto ready = [](const std::shared_ptr<const app::Snapshot>& s) { return s && s->mesh && s->solverBuilds > 0; };
    frameUntil(lab, [&] { return ready(lab.snapshot()) && ready(lab.secondSnapshot()); }, "both solvers built");
    REQUIRE(lab.secondSnapshot()->history.empty());  // not run: B holds its initial guess only
    REQUIRE(lab.clickAt({400.0, 250.0}));
    frameUntil(lab, [&] { return lab.probeReading() && lab.probeGeneration() == lab.snapshot()->generation; }, "A's reading");
    for (int frame = 0; frame < 5; ++frame) lab.frame();
    CHECK_FALSE(lab.secondProbeReading());  // the Probe panel says "waiting for both to step" instead

    lab.send(command::Step{});
    frameUntil(lab, [&] { return lab.secondProbeReading().has_value(); }, "B's reading after its first step");
    const std::shared_ptr<const app::Snapshot> b = lab.secondSnapshot();
    REQUIRE(!b->history.empty());
    // One Gauss-Seidel sweep in the furnace already adds reflected light to the emission.
    const Material& wall = b->scene->materials.at(0);
    CHECK(lab.secondProbeReading()->patchRadiosity.value().x > 1.2 * wall.exitance.value().x);
}

TEST_CASE("comparison mode: Jacobi and Gauss-Seidel converged on one mesh of the Cornell box draw the same picture in both halves") {
    requireDisplay();
    LabOptions o = options("cornell-box", 0.05);
    Lab lab(o);
    lab.send(command::SetMethod{SolverMethod::Jacobi});
    // The residual is a fraction of the emitted power: a dim patch's own relative error exceeds it
    // (at 1e-6 the two solutions' largest relative difference was 3.9e-4; at 1e-8, 2.5e-8).
    lab.send(command::SetTolerance{1e-8});
    ComparisonSettings settings;
    settings.method = SolverMethod::GaussSeidel;
    lab.setComparison(settings);
    lab.compare(true);
    solveBoth(lab);
    const render::ImageRgb8 image = lab.frameAndCapture();
    const std::vector<render::Viewport> halves = lab.sceneViews();
    REQUIRE(halves.size() == 2);
    const int belowLabels = halves[0].height / 4;
    CHECK(sceneShare(image, halves[0], belowLabels) > 0.3);
    CHECK(sceneShare(image, halves[1], belowLabels) > 0.3);
    CHECK(halvesDiffer(image, halves[0], halves[1], belowLabels) < 2.0);

    settings.view = ComparisonView::Difference;
    lab.setComparison(settings);
    lab.frame();
    lab.frame();
    const app::SolutionDifference& d = lab.comparisonDifference();
    REQUIRE(d.mesh);
    CHECK(d.relative.size() == lab.snapshot()->mesh->size());
    CHECK(d.maxRelative < 1e-6);
}

} // TEST_SUITE
