// GPU hemicubes (Cohen & Greenberg 1985) per second on the Cornell box at 64 to 512 pixels per side:
// rendering the five faces of the item buffer, reading it back, and gathering it into per-surface
// form factors and irradiance. Needs a display (a hidden window's GL context); without one the
// table says "skipped: no display".
#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/bench/BenchTable.h"
#include "app/window/OffscreenContext.h"
#include "radiometry/common/Error.h"
#include "radiometry/hemicube/HemicubeGather.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/BuiltinScenes.h"
#include "render/GlContext.h"
#include "render/hemicube/HemicubeRenderer.h"

namespace radiant::app {
namespace {

using Clock = std::chrono::steady_clock;

/// Median seconds per call of `work`, over repeats of at least `budget` seconds each.
template <class Work>
double secondsPerCall(Work&& work, int repeats, double budget) {
    std::vector<double> samples;
    for (int r = 0; r < repeats; ++r) {
        int calls = 0;
        const Clock::time_point start = Clock::now();
        double elapsed = 0;
        do {
            work();
            ++calls;
            elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        } while (elapsed < budget);
        samples.push_back(elapsed / calls);
    }
    return median(samples);
}

} // namespace

BenchTable benchHemicube(const BenchOptions& options) {
    BenchTable table{"Hemicube on the GPU (Cornell box, point on the floor)",
                     {"pixels per side", "item pixels", "render only (hemicubes/s)",
                      "+ readback (hemicubes/s)", "+ gather (hemicubes/s)", "ms each (all)"},
                     {},
                     {}};
    try {
        const OffscreenContext context("radiant bench");
        const render::GlInfo gl = render::queryGlInfo();
        const Scene box = makeCornellBox();
        MeshingOptions meshing;
        meshing.maxPatchArea = 0.01;
        const PatchMesh mesh = meshScene(box, meshing);
        std::vector<Rgb> radiosity(mesh.size(), Rgb(1.0));
        render::HemicubeRenderer renderer(mesh);
        const glm::dvec3 x{0.278, 0.0, 0.28}, n{0, 1, 0};
        const int repeats = options.quick ? 1 : 5;
        const double budget = options.quick ? 0.1 : 0.5;
        for (const int resolution : {64, 128, 256, 512}) {
            const double render = secondsPerCall([&] { renderer.renderOnly(x, n, resolution); }, repeats, budget);
            const double readback = secondsPerCall([&] { (void)renderer.capture(x, n, resolution); }, repeats, budget);
            const double all = secondsPerCall(
                [&] {
                    const render::HemicubeCapture c = renderer.capture(x, n, resolution);
                    (void)gatherHemicube(c.layout, c.items, mesh, box.surfaces.size(), radiosity);
                },
                repeats, budget);
            table.rows.push_back({std::to_string(resolution), std::to_string(3 * resolution * resolution),
                                  formatNumber(1.0 / render), formatNumber(1.0 / readback), formatNumber(1.0 / all),
                                  formatNumber(all * 1e3)});
        }
        table.notes.push_back(std::to_string(mesh.size()) + " patches; GL: " + gl.renderer + ", " + gl.version + " through " + context.kind());
    } catch (const RadiantError& error) {
        table.notes.push_back(std::string("skipped: ") + error.what());
    }
    return table;
}

} // namespace radiant::app
