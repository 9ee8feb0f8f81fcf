#include "radiometry/solver/FormFactorMatrix.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

#include "radiometry/solver/ParallelFor.h"
#include "radiometry/solver/SolverCommon.h"

namespace radiant {

namespace {

/// Every corner of `polygon` on or behind the plane of `plane`, within the pair's planarity.
bool whollyBehind(const PatchPolygon& polygon, const PatchPolygon& plane) {
    const double tolerance = planarityTolerance(polygon, plane);
    for (const glm::dvec3& corner : polygon.corners())
        if (glm::dot(plane.normal, corner - plane.centroid) > tolerance) return false;
    return true;
}

/// F_ij and F_ji of one pair above the diagonal, before thresholding.
struct PairFactors {
    std::uint32_t column = 0;
    float forward = 0;   ///< F_ij
    float backward = 0;  ///< F_ji
};

} // namespace

bool cannotSeeEachOther(const PatchPolygon& a, const PatchPolygon& b) { return whollyBehind(b, a) || whollyBehind(a, b); }

FormFactorMatrix::FormFactorMatrix(std::vector<std::vector<FormFactorEntry>> rows) {
    rowStart_.assign(rows.size() + 1, 0);
    for (std::size_t i = 0; i < rows.size(); ++i) rowStart_[i + 1] = rowStart_[i] + rows[i].size();
    entries_.reserve(rowStart_.back());
    for (auto& row : rows) {
        std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.column < b.column; });
        entries_.insert(entries_.end(), row.begin(), row.end());
    }
    stats_.entries = entries_.size();
}

double FormFactorMatrix::rowSum(std::size_t i) const {
    double sum = 0;
    for (const FormFactorEntry& e : row(i)) sum += e.value;
    return sum;
}

std::size_t FormFactorMatrix::bytes() const {
    return rowStart_.capacity() * sizeof(std::size_t) + entries_.capacity() * sizeof(FormFactorEntry);
}

FormFactorMatrix FormFactorMatrix::compute(const PatchMesh& mesh, const RayCaster* rays,
                                           const FormFactorOptions& options, double threshold, Progress* progress) {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = mesh.size();
    std::vector<PatchPolygon> polygons(n);
    for (std::size_t i = 0; i < n; ++i) polygons[i] = mesh.polygon(i);

    const std::size_t pairCount = n < 2 ? 0 : n * (n - 1) / 2;
    if (progress) {
        progress->done = 0;
        progress->total = pairCount;
    }

    // Pass 1, in parallel over rows: the pairs j > i. Quadrature is over the smaller patch of the
    // pair (its error grows with the integrated patch's size); the other direction is reciprocity.
    std::vector<std::vector<PairFactors>> upper(n);
    std::vector<std::size_t> culledPerRow(n, 0);
    parallelFor(n, 1, [&](std::size_t rowBegin, std::size_t rowEnd) {
        for (std::size_t i = rowBegin; i < rowEnd; ++i) {
            if (progress) progress->checkCancelled();
            const Patch& pi = mesh.patches[i];
            auto& out = upper[i];
            for (std::size_t j = i + 1; j < n; ++j) {
                const Patch& pj = mesh.patches[j];
                // A covered patch (Patch::covered: the floor under a block) sees only backs: its pairs
                // are all hidden, and rays grazing the footprint's line leaked light into it (1e-6 to
                // 1e-4 W/m^2 on the Cornell box, 100% in the comparison view's ratio).
                if ((pi.surface == pj.surface && pi.face == pj.face) || pi.covered || pj.covered ||
                    cannotSeeEachOther(polygons[i], polygons[j])) {
                    ++culledPerRow[i];
                    continue;
                }
                FormFactorOptions pairOptions = options;
                pairOptions.seed = pairSeed(options.seed, i, j);
                const double ai = polygons[i].area, aj = polygons[j].area;
                double fij = 0, fji = 0;
                if (ai <= aj) {
                    fij = formFactor(polygons[i], polygons[j], rays, pairOptions);
                    fji = fij * ai / aj;
                } else {
                    fji = formFactor(polygons[j], polygons[i], rays, pairOptions);
                    fij = fji * aj / ai;
                }
                if (fij > 0 || fji > 0)
                    out.push_back({static_cast<std::uint32_t>(j), static_cast<float>(fij), static_cast<float>(fji)});
            }
            if (progress) progress->done.fetch_add(n - i - 1, std::memory_order_relaxed);
        }
    });

    // Pass 2: assemble sorted CSR rows. Row i holds the backward factors of upper[k] (k < i, in
    // increasing k, so sorted) followed by its own forward factors (j > i, sorted).
    FormFactorMatrix matrix;
    std::vector<double> dropped(n, 0.0);
    std::vector<std::size_t> count(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        for (const PairFactors& p : upper[i]) {
            if (p.forward >= threshold) ++count[i]; else dropped[i] += p.forward;
            if (p.backward >= threshold) ++count[p.column]; else dropped[p.column] += p.backward;
        }
    matrix.rowStart_.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) matrix.rowStart_[i + 1] = matrix.rowStart_[i] + count[i];
    matrix.entries_.resize(matrix.rowStart_[n]);
    std::vector<std::size_t> cursor(matrix.rowStart_.begin(), matrix.rowStart_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
        for (const PairFactors& p : upper[i])
            if (p.backward >= threshold) matrix.entries_[cursor[p.column]++] = {static_cast<std::uint32_t>(i), p.backward};
        for (const PairFactors& p : upper[i])
            if (p.forward >= threshold) matrix.entries_[cursor[i]++] = {p.column, p.forward};
        upper[i] = {};  // release as we go: the peak is the matrix plus what is left of the pairs
    }

    matrix.stats_.pairs = pairCount;
    matrix.stats_.pairsCulled = std::accumulate(culledPerRow.begin(), culledPerRow.end(), std::size_t{0});
    matrix.stats_.entries = matrix.entries_.size();
    matrix.stats_.droppedMaxRow = dropped.empty() ? 0.0 : *std::max_element(dropped.begin(), dropped.end());
    matrix.stats_.droppedTotal = std::accumulate(dropped.begin(), dropped.end(), 0.0);
    matrix.stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return matrix;
}

} // namespace radiant
