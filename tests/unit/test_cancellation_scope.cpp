// ctest-labels: threads
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <set>
#include <thread>

#include "radiometry/common/CancellationScope.h"
#include "radiometry/common/Error.h"
#include "radiometry/solver/HierarchicalParallel.h"
#include "radiometry/solver/ParallelFor.h"

using namespace radiant;

TEST_SUITE("cancellation scope") {

TEST_CASE("a parallel loop inside a scope stops between chunks once cancellation is asked, and throws Cancelled") {
    constexpr std::size_t kChunks = 10000;
    Progress progress;
    std::atomic<std::size_t> chunksRun{0};
    const auto cancelAtFirstChunk = [&] {
        chunksRun.fetch_add(1);
        progress.cancelRequested.store(true);
    };
    {
        const CancellationScope scope(progress);
        CHECK_THROWS_AS(parallelFor(kChunks, 1, [&](std::size_t, std::size_t) { cancelAtFirstChunk(); }), Cancelled);
    }
    // Each worker finishes at most the chunk it had begun.
    CHECK(chunksRun.load() >= 1);
    CHECK(chunksRun.load() <= workerCount());

    progress.cancelRequested.store(false);
    chunksRun.store(0);
    {
        const CancellationScope scope(progress);
        CHECK_THROWS_AS(parallelChunks(kChunks, 2, 1, [&](std::size_t, std::size_t, unsigned) { cancelAtFirstChunk(); }),
                        Cancelled);
    }
    CHECK(chunksRun.load() >= 1);
    CHECK(chunksRun.load() <= 2);

    progress.cancelRequested.store(false);
    chunksRun.store(0);
    {
        const CancellationScope scope(progress);
        CHECK_THROWS_AS(parallelChunks(kChunks, 1, 1, [&](std::size_t, std::size_t, unsigned) { cancelAtFirstChunk(); }),
                        Cancelled);
    }
    CHECK(chunksRun.load() == 1);
}

TEST_CASE("outside every scope (the command line, the tests) a loop runs to the end whatever the flag says") {
    Progress progress;
    progress.cancelRequested.store(true);
    CHECK(CancellationScope::current() == nullptr);
    std::atomic<std::size_t> indices{0};
    parallelFor(1000, 7, [&](std::size_t begin, std::size_t end) { indices.fetch_add(end - begin); });
    CHECK(indices.load() == 1000);
    {
        const CancellationScope outer(progress);
        CHECK(CancellationScope::current() == &progress);
        {
            Progress inner;
            const CancellationScope scope(inner);
            CHECK(CancellationScope::current() == &inner);
            indices.store(0);
            parallelChunks(1000, 2, 7, [&](std::size_t begin, std::size_t end, unsigned) { indices.fetch_add(end - begin); });
            CHECK(indices.load() == 1000);  // the innermost scope decides: not cancelled
        }
        CHECK(CancellationScope::current() == &progress);
    }
    CHECK(CancellationScope::current() == nullptr);
}

TEST_CASE("a second caller of a held pool runs its loop on its own thread, not on threads of its own") {
    if (workerCount() < 2) {
        MESSAGE("one hardware thread: loops run serially and no pool is shared");
        return;
    }
    // The first caller holds the pool until released (chunk 0 waits; chunk 1 runs on the other thread).
    std::atomic<bool> firstRunning{false}, releaseFirst{false};
    std::jthread first([&] {
        parallelFor(2, 1, [&](std::size_t begin, std::size_t) {
            if (begin != 0) return;
            firstRunning.store(true);
            while (!releaseFirst.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        });
    });
    while (!firstRunning.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));

    std::mutex mutex;
    std::set<std::thread::id> ran;
    std::size_t indices = 0;
    const auto note = [&](std::size_t begin, std::size_t end) {
        const std::lock_guard lock(mutex);
        ran.insert(std::this_thread::get_id());
        indices += end - begin;
    };
    parallelFor(100, 1, note);
    parallelChunks(100, 2, 1, [&](std::size_t begin, std::size_t end, unsigned thread) {
        CHECK(thread == 0);
        note(begin, end);
    });
    CHECK(indices == 200);
    CHECK(ran == std::set<std::thread::id>{std::this_thread::get_id()});
    releaseFirst.store(true);
}

} // TEST_SUITE
