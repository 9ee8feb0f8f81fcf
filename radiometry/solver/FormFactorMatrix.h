#pragma once
// The form-factor matrix of a patch mesh for the gathering solvers: sparse rows of F_ij (float),
// computed once. Pairs that cannot see each other are skipped before any ray, only j > i is
// computed (F_ji follows from reciprocity, A_i F_ij = A_j F_ji), and entries below a threshold are
// dropped with their mass reported, so a teacher can see what the sparsity cost.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "radiometry/common/Progress.h"
#include "radiometry/formfactor/FormFactor.h"
#include "radiometry/mesh/PatchMesh.h"

namespace radiant {

class RayCaster;

struct FormFactorEntry {
    std::uint32_t column = 0;
    float value = 0;  ///< F_ij, dimensionless
};

struct FormFactorMatrixStats {
    std::size_t pairs = 0;          ///< unordered pairs i < j considered
    std::size_t pairsCulled = 0;    ///< skipped before any ray: behind a plane or on the same face
    std::size_t entries = 0;        ///< non-zero F_ij kept
    double droppedMaxRow = 0;       ///< max over rows of the summed F_ij dropped by the threshold
    double droppedTotal = 0;        ///< sum over all rows of the F_ij dropped
    double seconds = 0;             ///< wall time of compute()
};

class FormFactorMatrix {
public:
    FormFactorMatrix() = default;
    /// From explicit rows (tests, analytic factors); each row is sorted by column here.
    explicit FormFactorMatrix(std::vector<std::vector<FormFactorEntry>> rows);

    /// Computes F_ij for every pair of patches with formFactor(polygon_i, polygon_j, rays), in
    /// parallel over rows, reporting progress in pairs and honouring cancellation (throws Cancelled).
    static FormFactorMatrix compute(const PatchMesh& mesh, const RayCaster* rays, const FormFactorOptions& options,
                                    double threshold, Progress* progress = nullptr);

    [[nodiscard]] std::size_t size() const { return rowStart_.empty() ? 0 : rowStart_.size() - 1; }
    [[nodiscard]] std::span<const FormFactorEntry> row(std::size_t i) const {
        return {entries_.data() + rowStart_[i], entries_.data() + rowStart_[i + 1]};
    }
    /// sum_j F_ij: 1 for a patch inside a closed enclosure, less where light escapes or was dropped.
    [[nodiscard]] double rowSum(std::size_t i) const;
    [[nodiscard]] std::size_t entryCount() const { return entries_.size(); }
    /// Memory held by the matrix.
    [[nodiscard]] std::size_t bytes() const;
    [[nodiscard]] const FormFactorMatrixStats& stats() const { return stats_; }

private:
    std::vector<std::size_t> rowStart_;
    std::vector<FormFactorEntry> entries_;
    FormFactorMatrixStats stats_;
};

/// True when no light can pass between the two patches: one lies wholly behind the other's plane
/// (which includes coplanar patches, a double-sided face's twins among them, to the pair's
/// planarityTolerance). Cheap, exact, and done before any ray.
bool cannotSeeEachOther(const PatchPolygon& a, const PatchPolygon& b);

} // namespace radiant
