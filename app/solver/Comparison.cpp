#include "app/solver/Comparison.h"

#include <type_traits>

#include "app/solver/MethodLabel.h"

namespace radiant::app {

std::optional<SolverCommand> commandForSecond(const SolverCommand& command, const ComparisonSettings& settings,
                                              std::uint64_t secondMeshGeneration) {
    return std::visit(
        [&](const auto& c) -> std::optional<SolverCommand> {
            using C = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<C, command::SetMethod>) {
                return std::nullopt;
            } else if constexpr (std::is_same_v<C, command::Remesh> || std::is_same_v<C, command::LoadScene>) {
                C scaled = c;
                scaled.meshing.maxPatchArea *= settings.patchAreaScale;
                return scaled;
            } else if constexpr (std::is_same_v<C, command::FocusPoint>) {
                command::FocusPoint moved = c;
                if (moved.at) moved.at->meshGeneration = secondMeshGeneration;
                return moved;
            } else {
                return c;
            }
        },
        command);
}

std::string comparisonLabel(char side, SolverMethod method, double patchAreaScale) {
    std::string label = std::string(1, side) + ": " + methodLabel(method);
    if (patchAreaScale < 1) label += ", finer mesh";
    if (patchAreaScale > 1) label += ", coarser mesh";
    return label;
}

} // namespace radiant::app
