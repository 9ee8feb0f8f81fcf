// ctest-labels: threads
// The persistent worker pool under parallelFor and the hierarchical solver's parallelChunks: helpers
// wait, yielding, between back-to-back jobs and sleep after a pause, and a helper that comes late
// (after the caller ran every chunk) is neither waited for nor handed a finished job.
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <thread>

#include <doctest/doctest.h>

#include "radiometry/solver/WorkerPool.h"

using namespace radiant;

TEST_CASE("the worker pool runs every chunk of back-to-back jobs once, whether its helpers were spinning or asleep") {
    WorkerPool pool(3);
    constexpr int kChunks = 64;
    int complete = 0;
    for (int round = 0; round < 3000; ++round) {
        std::atomic<int> next{0}, done{0};
        const std::function<void()> job = [&] {
            while (next.fetch_add(1) < kChunks) done.fetch_add(1);
        };
        REQUIRE(pool.tryRunOnAll(job));
        complete += done.load() == kChunks && next.load() >= kChunks ? 1 : 0;
        // Now and then a pause longer than the helpers' spin: the next job wakes them from sleep.
        if (round % 300 == 299) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    CHECK(complete == 3000);
}

TEST_CASE("a helper that wakes after the caller finished a job alone skips the job") {
    // The caller runs the job at once; a sleeping helper may join it or wake after it returned. One
    // that wakes late must skip it rather than run a job whose state is gone.
    WorkerPool pool(1);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));  // the helper is asleep
    for (int round = 0; round < 200; ++round) {
        auto counter = std::make_unique<std::atomic<int>>(0);
        const std::function<void()> job = [&counter] { counter->fetch_add(1); };
        REQUIRE(pool.tryRunOnAll(job));
        const int ran = counter->load();
        CHECK(ran >= 1);
        CHECK(ran <= 2);
        counter.reset();  // a helper that ran this job after the return would touch freed memory (ASan)
        if (round % 20 == 19) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

TEST_CASE("a second caller or a nested call is told the pool is busy") {
    WorkerPool pool(1);
    std::atomic<int> accepted{0};
    const std::function<void()> inner = [] {};
    const std::function<void()> outer = [&] { accepted.fetch_add(pool.tryRunOnAll(inner) ? 1 : 0); };
    REQUIRE(pool.tryRunOnAll(outer));
    CHECK(accepted.load() == 0);
}
