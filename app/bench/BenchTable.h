#pragma once
// `radiant bench` prints tables. Each part of the system contributes its own table from its own
// file; timings are medians over repeats, printed with their units.
#include <chrono>
#include <string>
#include <vector>

namespace radiant::app {

struct BenchOptions {
    bool quick = false;  ///< fewer sizes and repeats: for CI smoke runs, not for quoting figures
};

struct BenchTable {
    std::string title;
    std::vector<std::string> columns;             ///< header cells, with units: "seconds (median)"
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> notes;               ///< lines printed under the table

    void print() const;
};

/// Median of the samples (the samples are reordered).
double median(std::vector<double> samples);
/// "12.3" with a fixed number of significant digits.
std::string formatNumber(double value, int significantDigits = 3);
/// "12.35%" for 0.12345.
std::string percent(double fraction);
/// Wall seconds from `start` to now.
double secondsSince(std::chrono::steady_clock::time_point start);
/// "met" when `seconds` is within `targetSeconds`, else by how much and how many times it is missed.
std::string timeVerdict(double seconds, double targetSeconds);

// One function per table; each lives in its own file under app/bench/.
BenchTable benchScenes(const BenchOptions& options);       ///< loading and meshing
BenchTable benchFormFactors(const BenchOptions& options);  ///< form factors and rays per second
BenchTable benchSolvers(const BenchOptions& options);      ///< each method to residual 1e-3
BenchTable benchHierarchical(const BenchOptions& options);  ///< hierarchical radiosity at 10k, 100k, 1M elements
BenchTable benchHierarchicalPeers(const BenchOptions& options);  ///< against RenderPark and SPLASH-2 at their sizes
BenchTable benchAccuracy(const BenchOptions& options);     ///< each method at its defaults against the path tracer
BenchTable benchAccuracySquareBlocks(const BenchOptions& options);  ///< the same on a box with its blocks square to the walls
BenchTable benchHierarchicalAccuracy(const BenchOptions& options);  ///< at points, by link tolerance, RenderPark at equal accuracy
BenchTable benchHemicube(const BenchOptions& options);     ///< GPU hemicubes per second (needs a display)
BenchTable benchFrames(const BenchOptions& options);       ///< frame time, solver idle and running (needs a display)

} // namespace radiant::app
