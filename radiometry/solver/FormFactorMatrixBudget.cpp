#include "radiometry/solver/FormFactorMatrixBudget.h"

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "radiometry/common/Error.h"
#include "radiometry/mesh/PatchMesh.h"
#include "radiometry/solver/FormFactorMatrix.h"

namespace radiant {

namespace {

/// What FormFactorMatrix::compute keeps per unordered pair: one 12-byte pair record (column, F_ij,
/// F_ji) in pass 1, then both directions as CSR entries in pass 2, while pass 1's records are
/// released row by row (so the peak is both).
constexpr double kBytesPerPair = 4 + 2 * sizeof(float) + 2 * sizeof(FormFactorEntry);
/// Per patch: its polygon, a pair-buffer header, row start, and four counters of pass 2.
constexpr double kBytesPerPatch = sizeof(PatchPolygon) + sizeof(std::vector<int>) + 5 * sizeof(std::size_t) + sizeof(double);

std::string gigabytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, bytes >= 10e9 ? "%.0f GB" : "%.2g GB", bytes / 1e9);
    return text;
}

std::string refusal(std::size_t patches, double neededBytes, double budgetBytes, std::string_view coarserMeshing) {
    return "a form-factor matrix for " + std::to_string(patches) + " patches needs up to " + gigabytes(neededBytes) +
           "; the budget is " + gigabytes(budgetBytes) + ": use progressive or hierarchical, or " + std::string(coarserMeshing);
}

} // namespace

double formFactorMatrixPeakBytes(std::size_t patches) {
    const double n = static_cast<double>(patches);
    return kBytesPerPair * n * (n - 1) / 2 + kBytesPerPatch * n;
}

FormFactorBudgetError::FormFactorBudgetError(std::size_t patches, double neededBytes, double budgetBytes)
    : BudgetError({"", "form-factor matrix"}, refusal(patches, neededBytes, budgetBytes, kCommandLineCoarserMeshing)),
      patches_(patches), neededBytes_(neededBytes), budgetBytes_(budgetBytes) {}

std::string FormFactorBudgetError::message(std::string_view coarserMeshing) const {
    return refusal(patches_, neededBytes_, budgetBytes_, coarserMeshing);
}

void checkFormFactorMatrixBudget(std::size_t patches, double budgetBytes) {
    const double needed = formFactorMatrixPeakBytes(patches);
    if (needed <= budgetBytes) return;
    throw FormFactorBudgetError(patches, needed, budgetBytes);
}

} // namespace radiant
