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
        inner_->step();
        spread();
        return stats_;
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
    [[nodiscard]] const IterationStats& lastStats() const override { return stats_; }
    [[nodiscard]] std::size_t bytes() const override {
        return inner_->bytes() + perPatch_.capacity() * sizeof(Rgb) +
               (groups_->groupOf.capacity() + groups_->members.capacity()) * sizeof(std::uint32_t);
    }

private:
    void spread() {
        const std::vector<Rgb>& perGroup = inner_->solution();
        perPatch_.resize(groups_->groupOf.size());
        for (std::size_t p = 0; p < perPatch_.size(); ++p) perPatch_[p] = perGroup[groups_->groupOf[p]];
        stats_ = inner_->lastStats();
        // The inner shooter is a group; whoever shows it (the lab's last-shooter overlay) wants a patch.
        if (stats_.shooter >= 0) stats_.shooter = groups_->patchesOf(static_cast<std::size_t>(stats_.shooter))[0];
    }

    std::unique_ptr<Solver> inner_;
    std::shared_ptr<const PatchGroups> groups_;
    std::vector<Rgb> perPatch_;
    IterationStats stats_;
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

ProgressiveShooters groupShooters(const PatchMesh& mesh, const PatchGroups& groups, std::size_t block) {
    if (groups.groupOf.size() != mesh.size())
        throw RadiantError({"", "patch groups"}, "the groups do not match the mesh");
    const ProgressiveShooters blocks = blockShooters(mesh, block);
    std::vector<std::uint32_t> blockOf(mesh.size());
    for (std::size_t b = 0; b < blocks.size(); ++b)
        for (const std::uint32_t p : blocks.group(b)) blockOf[p] = static_cast<std::uint32_t>(b);
    // A block shoots as one when every patch of it is in a group lying wholly within it.
    std::vector<std::int64_t> within(groups.size(), -1);
    std::vector<std::size_t> covered(blocks.size(), 0);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const auto patches = groups.patchesOf(g);
        const std::uint32_t b = blockOf[patches[0]];
        if (std::all_of(patches.begin(), patches.end(), [&](std::uint32_t p) { return blockOf[p] == b; })) {
            within[g] = b;
            covered[b] += patches.size();
        }
    }
    std::vector<std::vector<std::uint32_t>> blockGroups(blocks.size());
    std::vector<std::uint32_t> alone;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const std::int64_t b = within[g];
        if (b >= 0 && covered[static_cast<std::size_t>(b)] == blocks.group(static_cast<std::size_t>(b)).size())
            blockGroups[static_cast<std::size_t>(b)].push_back(static_cast<std::uint32_t>(g));
        else
            alone.push_back(static_cast<std::uint32_t>(g));
    }
    ProgressiveShooters shooters;
    shooters.first.push_back(0);
    const auto close = [&](const PatchPolygon& outline, const Patch& patch) {
        shooters.first.push_back(static_cast<std::uint32_t>(shooters.members.size()));
        shooters.polygons.push_back(outline);
        shooters.surface.push_back(patch.surface);
        shooters.face.push_back(patch.face);
    };
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        if (blockGroups[b].empty()) continue;
        shooters.members.insert(shooters.members.end(), blockGroups[b].begin(), blockGroups[b].end());
        close(blocks.polygons[b], mesh.patches[blocks.group(b)[0]]);
    }
    for (const std::uint32_t g : alone) {
        shooters.members.push_back(g);
        const auto patches = groups.patchesOf(g);
        close(patches.size() == 1 ? mesh.polygon(patches[0]) : PatchPolygon{}, mesh.patches[patches[0]]);
    }
    return shooters;
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
    if (method != SolverMethod::Jacobi && method != SolverMethod::GaussSeidel && method != SolverMethod::Progressive)
        throw RadiantError({scene.name, "patch groups"},
                           "grouped patches are solved by jacobi, gauss-seidel or progressive only, not " +
                               std::string(methodName(method)));
    if (!groups || groups->groupOf.size() != mesh.size() || groups->surfaceFirstGroup.size() != scene.surfaces.size() + 1)
        throw RadiantError({scene.name, "patch groups"}, "the groups do not match the mesh");
    if (method == SolverMethod::Progressive) {
        SolverOptions shots = options;  // one ray caster for the direct light and the shots
        if (!shots.rays) shots.rays = std::make_shared<const RayCaster>(scene);
        PatchMaterials materials = groupedMaterials(scene, mesh, *groups, shots.rays.get());
        const ProgressiveOptions progressive;  // the ungrouped solver's block size
        ProgressiveShooters shooters =
            groupShooters(mesh, *groups, blockForShooterCount(mesh.size(), progressive.shooterCount));
        GroupShotFormFactors formFactors = makeRayCastPatchGroupShotFormFactors(scene, mesh, groups, shooters, shots);
        auto inner = std::make_unique<ProgressiveSolver>(std::move(materials), std::move(shooters), std::move(formFactors));
        return std::make_unique<GroupedSolver>(std::move(inner), std::move(groups));
    }
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
