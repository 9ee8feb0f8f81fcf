#pragma once
// A path-traced estimate at one point, refined batch by batch on several threads. Batch k always
// draws from random stream (seed, k) and batches are merged in their order, so the estimate after
// the same calls is the same for a seed whatever the thread count. The standard error per band is
// the sample standard deviation over sqrt(N) (Welford's running moments, merged by Chan, Golub &
// LeVeque's pairwise formula so that large batches do not cancel catastrophically).
#include <chrono>
#include <cstdint>
#include <optional>

#include "radiometry/reference/PathTracer.h"
#include "radiometry/reference/ReferencePoint.h"
#include "radiometry/units/Quantity.h"

namespace radiant {

struct ReferenceEstimate {
    ReferencePoint at;
    Rgb reflectance{0.0};                   ///< rho at the point
    ExitanceRgb exitance{};                 ///< M at the point, W/m^2
    IrradianceRgb irradiance{};             ///< E, W/m^2
    RadiosityRgb radiosity{};               ///< B = M + rho E, W/m^2
    Rgb irradianceStandardError{0.0};       ///< W/m^2
    Rgb radiosityStandardError{0.0};        ///< rho x the irradiance's, W/m^2 (M is exact)
    std::uint64_t samples = 0;              ///< paths traced

    /// The largest standard error relative to its value over the bands, of E (which bounds B's,
    /// since B >= rho E). 0 where a band's value and error are both zero; infinite before any sample.
    [[nodiscard]] double relativeStandardError() const;
};

struct ReferenceRunOptions {
    std::uint64_t seed = 1;
    unsigned threads = 0;                 ///< 0: one per hardware thread
    std::uint64_t samplesPerBatch = 4096; ///< the unit of determinism and of work handed to a thread
};

/// When a run may stop: the first of these to hold (at least one must be set).
struct ReferenceStop {
    std::optional<std::uint64_t> samples;           ///< exactly this many paths in all
    std::optional<std::chrono::duration<double>> time;
    std::optional<double> relativeStandardError;    ///< ReferenceEstimate::relativeStandardError at most this
    std::uint64_t minimumSamples = 16384;           ///< before a standard-error test is trusted
};

class ReferenceRun {
public:
    /// Keeps a reference to the tracer, which must outlive the run.
    ReferenceRun(const PathTracer& tracer, const ReferencePoint& at, const ReferenceRunOptions& options = {});

    /// Traces `batches` more batches of options.samplesPerBatch paths (the last one `lastBatchSamples`
    /// when given) and merges them. Blocks; runs on options.threads threads started from the caller
    /// (they inherit its scheduling priority).
    void addBatches(std::uint64_t batches, std::optional<std::uint64_t> lastBatchSamples = std::nullopt);
    /// Adds batches until `stop` holds; returns the estimate.
    ReferenceEstimate runUntil(const ReferenceStop& stop);

    [[nodiscard]] ReferenceEstimate estimate() const;
    [[nodiscard]] std::uint64_t samples() const { return moments_.count; }

    /// Running moments of one estimator per band.
    struct Moments {
        std::uint64_t count = 0;
        Rgb mean{0.0};
        Rgb squaredDeviations{0.0};  ///< sum of (x - mean)^2
        void add(const Rgb& x);
        void merge(const Moments& other);
    };

private:
    const PathTracer& tracer_;
    ReferencePoint at_;
    ReferenceRunOptions options_;
    std::uint64_t nextBatch_ = 0;
    Moments moments_;
};

} // namespace radiant
