#pragma once
// The convergence plot's data as CSV, for a student's report: one row per step of every segment.
//   method,segment,label,iteration,solver_iteration,quantity,value
// `iteration` counts from 1 at the segment's start (the plot's x axis); `solver_iteration` is the
// solver's own count (it goes on across a material edit); `value` is the residual of the quantity
// named (ConvergenceQuantity.h), printed to round-trip.
#include <cstddef>
#include <optional>
#include <string>

#include "app/solver/ConvergenceRecord.h"

namespace radiant::app {

[[nodiscard]] std::string convergenceCsv(const ConvergenceRecord& record, const SolveHistory& currentSteps);

/// One CSV field (RFC 4180): a field with a comma, quote or line break is quoted, its quotes doubled.
[[nodiscard]] std::string csvField(const std::string& text);

/// The first step (from 1) of `steps` whose residual is below `tolerance`, if any.
[[nodiscard]] std::optional<std::size_t> firstStepBelow(const SolveHistory& steps, double tolerance);

/// Writes `text` to `path`; throws RadiantError naming the file when it cannot.
void writeTextFile(const std::string& path, const std::string& text);

} // namespace radiant::app
