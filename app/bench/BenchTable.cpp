#include "app/bench/BenchTable.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace radiant::app {

void BenchTable::print() const {
    std::vector<std::size_t> widths(columns.size(), 0);
    for (std::size_t c = 0; c < columns.size(); ++c) widths[c] = columns[c].size();
    for (const auto& row : rows)
        for (std::size_t c = 0; c < row.size() && c < widths.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
    const auto printRow = [&](const std::vector<std::string>& cells) {
        std::string line = "|";
        for (std::size_t c = 0; c < widths.size(); ++c) {
            const std::string cell = c < cells.size() ? cells[c] : "";
            line += " " + cell + std::string(widths[c] - cell.size(), ' ') + " |";
        }
        std::printf("%s\n", line.c_str());
    };
    std::printf("\n## %s\n\n", title.c_str());
    printRow(columns);
    std::string rule = "|";
    for (std::size_t w : widths) rule += std::string(w + 2, '-') + "|";
    std::printf("%s\n", rule.c_str());
    for (const auto& row : rows) printRow(row);
    for (const auto& note : notes) std::printf("\n%s", note.c_str());
    if (!notes.empty()) std::printf("\n");
    std::fflush(stdout);
}

double median(std::vector<double> samples) {
    if (samples.empty()) return 0;
    const auto mid = samples.begin() + static_cast<std::ptrdiff_t>(samples.size() / 2);
    std::nth_element(samples.begin(), mid, samples.end());
    if (samples.size() % 2 == 1) return *mid;
    const double upper = *mid;
    const double lower = *std::max_element(samples.begin(), mid);
    return 0.5 * (lower + upper);
}

std::string formatNumber(double value, int significantDigits) {
    if (!std::isfinite(value)) return "n/a";
    std::ostringstream out;
    out.precision(significantDigits);
    out << value;
    return out.str();
}

std::string percent(double fraction) { return formatNumber(100 * fraction, 2) + "%"; }

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string timeVerdict(double seconds, double targetSeconds) {
    if (seconds <= targetSeconds) return "met";
    return "missed by " + formatNumber(seconds - targetSeconds) + " s (" + formatNumber(seconds / targetSeconds) + "x)";
}

} // namespace radiant::app
