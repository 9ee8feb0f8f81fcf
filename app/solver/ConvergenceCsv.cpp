#include "app/solver/ConvergenceCsv.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>

#include "app/solver/ConvergenceQuantity.h"
#include "radiometry/common/Error.h"

namespace radiant::app {
namespace {

/// The shortest text that reads back as the same double.
std::string exact(double value) {
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return {buffer.data(), result.ptr};
}

} // namespace

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + "\"";
}

std::string convergenceCsv(const ConvergenceRecord& record, const SolveHistory& currentSteps) {
    std::string csv = "method,segment,label,iteration,solver_iteration,quantity,value\n";
    for (const SegmentView& segment : record.segments(currentSteps)) {
        const std::string prefix = std::string(methodName(segment.info->method)) + "," +
                                   std::to_string(segment.info->index) + "," + csvField(segment.info->label) + ",";
        const std::string quantity(convergenceQuantity(segment.info->method).csvName);
        for (std::size_t i = 0; i < segment.steps->size(); ++i) {
            const IterationStats& step = (*segment.steps)[i];
            csv += prefix + std::to_string(i + 1) + "," + std::to_string(step.iteration) + "," + quantity + "," +
                   exact(step.residual) + "\n";
        }
    }
    return csv;
}

std::optional<std::size_t> firstStepBelow(const SolveHistory& steps, double tolerance) {
    for (std::size_t i = 0; i < steps.size(); ++i)
        if (steps[i].residual < tolerance) return i + 1;
    return std::nullopt;
}

void writeTextFile(const std::string& path, const std::string& text) {
    if (path.empty()) throw RadiantError({"", "export CSV"}, "no file name given");
    std::ofstream out(path, std::ios::binary);
    if (out) out << text;
    if (!out) throw RadiantError({path, ""}, std::string("cannot write: ") + std::strerror(errno));
}

} // namespace radiant::app
