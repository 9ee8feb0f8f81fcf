// Form-factor throughput on the Cornell box at several meshing densities: the kernel every
// gathering solver runs ~N^2 times. Rows of the matrix are computed in a scrambled order (so the
// sample spans near and far pairs of the whole box) on both cores until a time budget runs out;
// rates are medians over repeats.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <numeric>
#include <thread>
#include <vector>

#include "app/bench/BenchTable.h"
#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/scene/BuiltinScenes.h"

namespace radiant::app {
namespace {

using Clock = std::chrono::steady_clock;

/// Runs work(index) for indices 0, 1, 2, ... on `threads` threads until `budget` has passed; each
/// call returns how many items it did. Returns items per second of wall-clock time.
double measureThroughput(int threads, std::chrono::duration<double> budget,
                         const std::function<std::uint64_t(std::uint64_t)>& work) {
    std::atomic<std::uint64_t> nextIndex{0};
    std::atomic<std::uint64_t> items{0};
    const Clock::time_point start = Clock::now();
    const Clock::time_point deadline = start + std::chrono::duration_cast<Clock::duration>(budget);
    {
        std::vector<std::jthread> workers;
        for (int t = 0; t < threads; ++t)
            workers.emplace_back([&] {
                std::uint64_t done = 0;
                while (Clock::now() < deadline) done += work(nextIndex++);
                items += done;
            });
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return static_cast<double>(items.load()) / seconds;
}

double medianRate(int repeats, const std::function<double()>& measure) {
    std::vector<double> rates;
    for (int r = 0; r < repeats; ++r) rates.push_back(measure());
    return median(rates);
}

} // namespace

BenchTable benchFormFactors(const BenchOptions& options) {
    BenchTable table{"Form factors (Cornell box, both cores)",
                     {"max patch area (m^2)", "patches", "form factors/s, 1 thread", "form factors/s",
                      "form factors/s, 16-ray visibility", "rays/s", "full matrix (s, est.)"},
                     {},
                     {}};
    const Scene box = makeCornellBox();
    const Clock::time_point buildStart = Clock::now();
    const RayCaster rays(box);
    const double buildSeconds = std::chrono::duration<double>(Clock::now() - buildStart).count();

    const std::vector<double> densities = options.quick ? std::vector<double>{0.01} : std::vector<double>{0.01, 0.0025, 0.0006};
    const int repeats = options.quick ? 1 : 3;
    const std::chrono::duration<double> budget(options.quick ? 0.2 : 1.0);
    const int threads = 2;

    for (const double maxArea : densities) {
        MeshingOptions meshing;
        meshing.maxPatchArea = maxArea;
        const PatchMesh mesh = meshScene(box, meshing);
        const std::uint64_t n = mesh.size();
        std::vector<PatchPolygon> polygons;
        polygons.reserve(n);
        for (std::size_t i = 0; i < n; ++i) polygons.push_back(mesh.polygon(i));
        // Rows in a scrambled order: an odd multiplier coprime with n walks all of them.
        std::uint64_t stride = 2654435761u % n;
        while (stride == 0 || std::gcd(stride, n) != 1) ++stride;
        const auto rowOf = [&](std::uint64_t k) { return (k * stride) % n; };

        FormFactorOptions unoccludedOptions;
        unoccludedOptions.visibilityRays = 0;
        const auto unoccludedRow = [&](std::uint64_t k) -> std::uint64_t {
            const PatchPolygon& from = polygons[rowOf(k)];
            double sink = 0;
            for (const PatchPolygon& to : polygons) sink += formFactor(from, to, nullptr, unoccludedOptions);
            return sink >= 0 ? n : 0;  // keeps the work observable
        };
        FormFactorOptions visibleOptions;
        visibleOptions.visibilityRays = 16;
        const auto visibleRow = [&](std::uint64_t k) -> std::uint64_t {
            const PatchPolygon& from = polygons[rowOf(k)];
            double sink = 0;
            for (const PatchPolygon& to : polygons) sink += formFactor(from, to, &rays, visibleOptions);
            return sink >= 0 ? n : 0;
        };
        // Rays between patch centroids of scrambled pairs: the cost of one occlusion query.
        const auto rayBatch = [&](std::uint64_t k) -> std::uint64_t {
            constexpr std::uint64_t batch = 1024;
            std::uint64_t blocked = 0;
            for (std::uint64_t r = 0; r < batch; ++r) {
                const std::uint64_t pair = k * batch + r;
                const glm::dvec3& a = polygons[rowOf(pair) % n].centroid;
                const glm::dvec3& b = polygons[(pair * 40503u + 7) % n].centroid;
                blocked += rays.occluded(a, b) ? 1 : 0;
            }
            return blocked <= batch ? batch : 0;
        };

        const double single = medianRate(repeats, [&] { return measureThroughput(1, budget, unoccludedRow); });
        const double both = medianRate(repeats, [&] { return measureThroughput(threads, budget, unoccludedRow); });
        const double visible = medianRate(repeats, [&] { return measureThroughput(threads, budget, visibleRow); });
        const double raysPerSecond = medianRate(repeats, [&] { return measureThroughput(threads, budget, rayBatch); });
        table.rows.push_back({formatNumber(maxArea), std::to_string(n), formatNumber(single), formatNumber(both),
                              formatNumber(visible), formatNumber(raysPerSecond),
                              formatNumber(static_cast<double>(n) * static_cast<double>(n) / visible)});
    }
    table.notes.push_back("Embree BVH build for the box: " + formatNumber(buildSeconds * 1e3) + " ms. Accuracy target 1e-3; "
                          "rows of the matrix in scrambled order for " + formatNumber(budget.count()) +
                          " s per measurement, median of " + std::to_string(repeats) + ".");
    table.notes.push_back("full matrix: N^2 pairs at the visibility rate, without the solvers' reciprocity halving.");
    return table;
}

} // namespace radiant::app
