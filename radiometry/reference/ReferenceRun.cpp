#include "radiometry/reference/ReferenceRun.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

#include <glm/exponential.hpp>

#include "radiometry/common/Error.h"

namespace radiant {

double ReferenceEstimate::relativeStandardError() const {
    if (samples == 0) return std::numeric_limits<double>::infinity();
    double worst = 0;
    for (int band = 0; band < 3; ++band) {
        const double value = irradiance.value()[band], error = irradianceStandardError[band];
        if (error == 0) continue;
        worst = std::max(worst, value > 0 ? error / value : std::numeric_limits<double>::infinity());
    }
    return worst;
}

void ReferenceRun::Moments::add(const Rgb& x) {
    ++count;
    const Rgb delta = x - mean;
    mean += delta / static_cast<double>(count);
    squaredDeviations += delta * (x - mean);
}

void ReferenceRun::Moments::merge(const Moments& other) {
    if (other.count == 0) return;
    if (count == 0) {
        *this = other;
        return;
    }
    const double n = static_cast<double>(count), m = static_cast<double>(other.count);
    const Rgb delta = other.mean - mean;
    mean += delta * (m / (n + m));
    squaredDeviations += other.squaredDeviations + delta * delta * (n * m / (n + m));
    count += other.count;
}

ReferenceRun::ReferenceRun(const PathTracer& tracer, const ReferencePoint& at, const ReferenceRunOptions& options)
    : tracer_(tracer), at_(at), options_(options) {
    if (options_.samplesPerBatch == 0)
        throw RadiantError({"", "reference"}, "samplesPerBatch must be at least 1");
    if (options_.threads == 0) options_.threads = std::max(1u, std::thread::hardware_concurrency());
}

void ReferenceRun::addBatches(std::uint64_t batches, std::optional<std::uint64_t> lastBatchSamples) {
    if (batches == 0) return;
    std::vector<Moments> results(batches);
    std::atomic<std::uint64_t> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    const auto work = [&] {
        try {
            for (std::uint64_t k = next.fetch_add(1); k < batches; k = next.fetch_add(1)) {
                reference::RandomStream random(options_.seed, nextBatch_ + k);
                const std::uint64_t count =
                    k + 1 == batches && lastBatchSamples ? *lastBatchSamples : options_.samplesPerBatch;
                for (std::uint64_t s = 0; s < count; ++s)
                    results[k].add(tracer_.sampleIrradiance(at_.point, at_.normal, random));
            }
        } catch (...) {
            const std::lock_guard lock(failureMutex);
            if (!failure) failure = std::current_exception();
            next = batches;
        }
    };
    {
        const auto helpers = static_cast<unsigned>(std::min<std::uint64_t>(options_.threads, batches)) - 1;
        std::vector<std::jthread> threads;
        threads.reserve(helpers);
        for (unsigned t = 0; t < helpers; ++t) threads.emplace_back(work);
        work();
    }  // joined here
    if (failure) std::rethrow_exception(failure);
    for (const Moments& batch : results) moments_.merge(batch);
    nextBatch_ += batches;
}

ReferenceEstimate ReferenceRun::runUntil(const ReferenceStop& stop) {
    if (!stop.samples && !stop.time && !stop.relativeStandardError)
        throw RadiantError({"", "reference"}, "a run needs a sample count, a time or a standard error to stop at");
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t round = 2ull * options_.threads;  // batches per round: keeps every thread busy
    for (;;) {
        if (stop.samples && samples() >= *stop.samples) break;
        if (stop.time && std::chrono::steady_clock::now() - start >= *stop.time) break;
        if (stop.relativeStandardError && samples() >= stop.minimumSamples &&
            estimate().relativeStandardError() <= *stop.relativeStandardError)
            break;
        if (stop.samples) {
            const std::uint64_t missing = *stop.samples - samples();
            const std::uint64_t batches = std::min(round, (missing + options_.samplesPerBatch - 1) / options_.samplesPerBatch);
            const std::uint64_t inLast = missing - (batches - 1) * options_.samplesPerBatch;
            addBatches(batches, std::min(inLast, options_.samplesPerBatch));
        } else {
            addBatches(round);
        }
    }
    return estimate();
}

ReferenceEstimate ReferenceRun::estimate() const {
    ReferenceEstimate e;
    e.at = at_;
    e.reflectance = tracer_.reflectance(at_.surface);
    e.exitance = ExitanceRgb(tracer_.exitance(at_.surface));
    e.samples = moments_.count;
    e.irradiance = IrradianceRgb(moments_.mean);
    e.radiosity = RadiosityRgb(e.exitance.value() + e.reflectance * moments_.mean);
    if (moments_.count > 1) {
        const double n = static_cast<double>(moments_.count);
        const Rgb variance = moments_.squaredDeviations / (n - 1);
        e.irradianceStandardError = glm::sqrt(variance / n);
        e.radiosityStandardError = e.reflectance * e.irradianceStandardError;
    }
    return e;
}

} // namespace radiant
