#include "radiometry/solver/GroupedSolver.h"

#include <algorithm>
#include <array>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "radiometry/common/Error.h"
#include "radiometry/geometry/RayCaster.h"
#include "radiometry/solver/FormFactorMatrixBudget.h"
#include "radiometry/solver/GatheringSolver.h"
#include "radiometry/solver/ParallelFor.h"

namespace radiant {

namespace {

/// Presents the grouped system's solution per patch: every patch holds its group's radiosity.
class GroupedSolver final : public Solver {
public:
    GroupedSolver(std::unique_ptr<Solver> groupSolver, std::shared_ptr<const PatchGroups> groups)
        : inner_(std::move(groupSolver)), groups_(std::move(groups)) {
        spread();
    }

    [[nodiscard]] SolverMethod method() const override { return inner_->method(); }
    IterationStats step() override {
        const IterationStats stats = inner_->step();
        spread();
        return stats;
    }
    [[nodiscard]] const std::vector<Rgb>& solution() const override { return perPatch_; }
    void setMaterial(std::size_t surface, const Rgb& reflectance, const ExitanceRgb& exitance) override {
        inner_->setMaterial(surface, reflectance, exitance);
        spread();
    }
    void reset() override {
        inner_->reset();
        spread();
    }
    [[nodiscard]] const IterationStats& lastStats() const override { return inner_->lastStats(); }
    [[nodiscard]] std::size_t bytes() const override {
        return inner_->bytes() + perPatch_.capacity() * sizeof(Rgb) +
               (groups_->groupOf.capacity() + groups_->members.capacity()) * sizeof(std::uint32_t);
    }

private:
    void spread() {
        const std::vector<Rgb>& perGroup = inner_->solution();
        perPatch_.resize(groups_->groupOf.size());
        for (std::size_t p = 0; p < perPatch_.size(); ++p) perPatch_[p] = perGroup[groups_->groupOf[p]];
    }

    std::unique_ptr<Solver> inner_;
    std::shared_ptr<const PatchGroups> groups_;
    std::vector<Rgb> perPatch_;
};

} // namespace

FormFactorMatrix computeGroupedFormFactors(const PatchMesh& mesh, const PatchGroups& groups, const RayCaster* rays,
                                           const FormFactorOptions& options, double threshold, Progress* progress) {
    const std::size_t n = mesh.size(), groupCount = groups.size();
    if (groups.groupOf.size() != n)
        throw RadiantError({"", "patch groups"}, "group " + std::to_string(groups.groupOf.size()) + " patches of a mesh of " +
                                                     std::to_string(n));
    std::vector<PatchPolygon> polygons(n);
    for (std::size_t i = 0; i < n; ++i) polygons[i] = mesh.polygon(i);
    if (progress) {
        progress->done = 0;
        progress->total = n < 2 ? 0 : n * (n - 1) / 2;
    }

    // sum_{p in C, q in D} A_p F_pq for D >= C, a dense upper row per group. Patches are visited in
    // member order (k), each against the later ones (l > k), so a pair is computed once and the
    // groups of the later ones never decrease: each k's sums are runs, added under its row's lock.
    std::vector<std::vector<double>> exchanged(groupCount);
    std::array<std::mutex, 64> locks;
    parallelFor(n, 1, [&](std::size_t begin, std::size_t end) {
        std::vector<std::pair<std::uint32_t, double>> runs;
        for (std::size_t k = begin; k < end; ++k) {
            if (progress) progress->checkCancelled();
            const std::uint32_t p = groups.members[k], from = groups.groupOf[p];
            const Patch& patchP = mesh.patches[p];
            runs.clear();
            for (std::size_t l = k + 1; l < n; ++l) {
                const std::uint32_t q = groups.members[l];
                const Patch& patchQ = mesh.patches[q];
                if ((patchP.surface == patchQ.surface && patchP.face == patchQ.face) ||
                    cannotSeeEachOther(polygons[p], polygons[q]))
                    continue;
                FormFactorOptions pairOptions = options;
                pairOptions.seed = pairSeed(options.seed, std::min(p, q), std::max(p, q));
                // Quadrature over the smaller of the pair, as FormFactorMatrix::compute does.
                const double exchange = polygons[p].area <= polygons[q].area
                                            ? polygons[p].area * formFactor(polygons[p], polygons[q], rays, pairOptions)
                                            : polygons[q].area * formFactor(polygons[q], polygons[p], rays, pairOptions);
                if (!(exchange > 0)) continue;
                const std::uint32_t to = groups.groupOf[q];
                if (runs.empty() || runs.back().first != to) runs.emplace_back(to, 0.0);
                runs.back().second += exchange;
            }
            if (!runs.empty()) {
                const std::lock_guard lock(locks[from % locks.size()]);
                std::vector<double>& row = exchanged[from];
                if (row.empty()) row.assign(groupCount - from, 0.0);
                for (const auto& [to, sum] : runs) row[to - from] += sum;
            }
            if (progress) progress->done.fetch_add(n - k - 1, std::memory_order_relaxed);
        }
    });

    std::vector<std::vector<FormFactorEntry>> rows(groupCount);
    for (std::size_t c = 0; c < groupCount; ++c) {
        const std::vector<double>& row = exchanged[c];
        for (std::size_t offset = 0; offset < row.size(); ++offset) {
            if (!(row[offset] > 0)) continue;
            const std::size_t d = c + offset;
            if (d == c) {
                // Pairs within C were met once (k < l): A_C F_CC counts both directions.
                const double fcc = 2 * row[offset] / groups.area[c];
                if (fcc >= threshold) rows[c].push_back({static_cast<std::uint32_t>(c), static_cast<float>(fcc)});
                continue;
            }
            const double fcd = row[offset] / groups.area[c], fdc = row[offset] / groups.area[d];
            if (fcd >= threshold) rows[c].push_back({static_cast<std::uint32_t>(d), static_cast<float>(fcd)});
            if (fdc >= threshold) rows[d].push_back({static_cast<std::uint32_t>(c), static_cast<float>(fdc)});
        }
        exchanged[c] = {};
    }
    return FormFactorMatrix(std::move(rows));
}

PatchMaterials groupedMaterials(const Scene& scene, const PatchMesh& mesh, const PatchGroups& groups,
                                const RayCaster* rays) {
    const PatchMaterials perPatch = PatchMaterials::from(scene, mesh, rays);
    PatchMaterials materials;
    const std::size_t groupCount = groups.size();
    materials.area = groups.area;
    materials.reflectance.resize(groupCount);
    materials.exitance.resize(groupCount);
    materials.source.resize(groupCount);
    materials.directIrradiance.assign(groupCount, Rgb(0.0));
    for (std::size_t g = 0; g < groupCount; ++g) {
        for (const std::uint32_t p : groups.patchesOf(g))
            materials.directIrradiance[g] += perPatch.area[p] * perPatch.directIrradiance[p];
        if (groups.area[g] > 0) materials.directIrradiance[g] /= groups.area[g];
    }
    materials.surfaceFirstPatch = groups.surfaceFirstGroup;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const Material& material = scene.materials[scene.surfaces[s].material];  // checked by from()
        materials.setSurface(s, material.reflectance, material.exitance);
    }
    return materials;
}

std::unique_ptr<Solver> makeGroupedSolver(SolverMethod method, const Scene& scene, const PatchMesh& mesh,
                                          std::shared_ptr<const PatchGroups> groups, const SolverOptions& options,
                                          Progress* progress) {
    if (method != SolverMethod::Jacobi && method != SolverMethod::GaussSeidel)
        throw RadiantError({scene.name, "patch groups"}, "grouped patches are solved by jacobi or gauss-seidel only, not " +
                                                             std::string(methodName(method)));
    if (!groups || groups->groupOf.size() != mesh.size() || groups->surfaceFirstGroup.size() != scene.surfaces.size() + 1)
        throw RadiantError({scene.name, "patch groups"}, "the groups do not match the mesh");
    checkFormFactorMatrixBudget(groups->size(), options.matrixBudgetBytes);
    std::optional<RayCaster> own;
    const RayCaster* rays = options.rays ? options.rays.get() : &own.emplace(scene);
    FormFactorOptions formFactors = options.formFactors;
    formFactors.seed = pairSeed(options.seed, options.formFactors.seed, 0);
    auto matrix = std::make_shared<const FormFactorMatrix>(
        computeGroupedFormFactors(mesh, *groups, rays, formFactors, options.matrixThreshold, progress));
    PatchMaterials materials = groupedMaterials(scene, mesh, *groups, rays);
    std::unique_ptr<Solver> inner = method == SolverMethod::Jacobi ? makeJacobiSolver(std::move(materials), std::move(matrix))
                                                                   : makeGaussSeidelSolver(std::move(materials), std::move(matrix));
    return std::make_unique<GroupedSolver>(std::move(inner), std::move(groups));
}

} // namespace radiant
