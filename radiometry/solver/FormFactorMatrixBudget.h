#pragma once
// The gathering solvers store F_ij for every pair of patches that see each other: memory grows as
// n^2, and a student who meshes a scene finely can ask for more than the machine has. The request is
// refused before anything is allocated, with the numbers and what to do instead.
#include <cstddef>

namespace radiant {

/// Peak bytes FormFactorMatrix::compute may hold for `patches` patches: the pair buffer of pass 1
/// and the assembled rows of pass 2 together, with every pair visible (an upper bound; culling
/// only lowers it), plus the per-patch arrays.
[[nodiscard]] double formFactorMatrixPeakBytes(std::size_t patches);

/// Throws BudgetError ("a form-factor matrix for 40000 patches needs up to 22 GB; the budget is
/// 4 GB: ...") when formFactorMatrixPeakBytes(patches) exceeds `budgetBytes`.
void checkFormFactorMatrixBudget(std::size_t patches, double budgetBytes);

} // namespace radiant
