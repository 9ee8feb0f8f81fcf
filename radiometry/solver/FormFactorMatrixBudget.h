#pragma once
// The gathering solvers store F_ij for every pair of patches that see each other: memory grows as
// n^2, and a student who meshes a scene finely can ask for more than the machine has. The request is
// refused before anything is allocated, with the numbers and what to do instead.
#include <cstddef>
#include <string>
#include <string_view>

#include "radiometry/common/Error.h"

namespace radiant {

/// The refusal, carrying its numbers so that each front end names its own way to coarser meshing:
/// what() says the command line's ("a larger --max-patch-area"), the lab says its meshing slider.
class FormFactorBudgetError : public BudgetError {
public:
    FormFactorBudgetError(std::size_t patches, double neededBytes, double budgetBytes);
    /// "a form-factor matrix for 40000 patches needs up to 22 GB; the budget is 4 GB: use
    /// progressive or hierarchical, or " + coarserMeshing.
    [[nodiscard]] std::string message(std::string_view coarserMeshing) const;
    [[nodiscard]] std::size_t patches() const { return patches_; }

private:
    std::size_t patches_;
    double neededBytes_;
    double budgetBytes_;
};

/// The command line's words for coarser meshing, as in FormFactorBudgetError::what().
inline constexpr std::string_view kCommandLineCoarserMeshing = "a larger --max-patch-area";

/// Peak bytes FormFactorMatrix::compute may hold for `patches` patches: the pair buffer of pass 1
/// and the assembled rows of pass 2 together, with every pair visible (an upper bound; culling
/// only lowers it), plus the per-patch arrays.
[[nodiscard]] double formFactorMatrixPeakBytes(std::size_t patches);

/// Throws FormFactorBudgetError ("a form-factor matrix for 40000 patches needs up to 22 GB; the budget is
/// 4 GB: ...") when formFactorMatrixPeakBytes(patches) exceeds `budgetBytes`.
void checkFormFactorMatrixBudget(std::size_t patches, double budgetBytes);

} // namespace radiant
