#include <doctest/doctest.h>

#include <cstddef>

#include "app/solver/SolveHistory.h"

using namespace radiant;
using namespace radiant::app;

namespace {

/// Step i (from 1) with fields that tell every entry apart.
IterationStats historyStep(std::size_t i) {
    IterationStats stats;
    stats.iteration = i;
    stats.residual = 1.0 / static_cast<double>(i);
    stats.links = 2 * i;
    return stats;
}

void appendHistorySteps(SolveHistoryBuilder& builder, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i <= to; ++i) builder.append(historyStep(i));
}

/// Every entry of `history` is historyStep(index + 1).
bool holdsStepsInOrder(const SolveHistory& history) {
    for (std::size_t i = 0; i < history.size(); ++i)
        if (history[i].iteration != i + 1 || history[i].links != 2 * (i + 1) ||
            history[i].residual != 1.0 / static_cast<double>(i + 1))
            return false;
    return true;
}

} // namespace

TEST_SUITE("solve history") {

TEST_CASE("solve history: entries read back in order across chunk boundaries") {
    static_assert(SolveHistory::kChunkSize < 2500 / 2, "the test must cross at least two chunk boundaries");
    SolveHistoryBuilder builder;
    appendHistorySteps(builder, 1, 2500);
    CHECK(builder.size() == 2500);
    const SolveHistory history = builder.snapshot();
    REQUIRE(history.size() == 2500);
    CHECK_FALSE(history.empty());
    CHECK(history.frozenChunks().size() == 2500 / SolveHistory::kChunkSize);
    CHECK(holdsStepsInOrder(history));
    const std::size_t boundary = SolveHistory::kChunkSize;
    CHECK(history[boundary - 1].iteration == boundary);
    CHECK(history[boundary].iteration == boundary + 1);
    CHECK(history.back().iteration == 2500);
}

TEST_CASE("solve history: a chunk exactly full is frozen, and back() reads it") {
    SolveHistoryBuilder builder;
    appendHistorySteps(builder, 1, SolveHistory::kChunkSize);
    const SolveHistory history = builder.snapshot();
    CHECK(history.size() == SolveHistory::kChunkSize);
    CHECK(history.frozenChunks().size() == 1);
    CHECK(history.back().iteration == SolveHistory::kChunkSize);
    CHECK(holdsStepsInOrder(history));
}

TEST_CASE("solve history: a snapshot is unchanged by later appends") {
    SolveHistoryBuilder builder;
    appendHistorySteps(builder, 1, 1500);
    const SolveHistory early = builder.snapshot();
    appendHistorySteps(builder, 1501, 5000);
    CHECK(builder.size() == 5000);
    CHECK(early.size() == 1500);
    CHECK(early.frozenChunks().size() == 1);
    CHECK(early.back().iteration == 1500);
    CHECK(holdsStepsInOrder(early));
    CHECK(holdsStepsInOrder(builder.snapshot()));
}

TEST_CASE("solve history: successive snapshots share their full chunks") {
    SolveHistoryBuilder builder;
    appendHistorySteps(builder, 1, 2100);
    const SolveHistory first = builder.snapshot();
    appendHistorySteps(builder, 2101, 3500);  // freezes a third chunk in between
    const SolveHistory second = builder.snapshot();
    REQUIRE(first.frozenChunks().size() == 2);
    REQUIRE(second.frozenChunks().size() == 3);
    for (std::size_t c = 0; c < first.frozenChunks().size(); ++c)
        CHECK(first.frozenChunks()[c].get() == second.frozenChunks()[c].get());
    // Snapshots with nothing appended in between share the list itself.
    const SolveHistory again = builder.snapshot();
    CHECK(again.frozenChunks().data() == second.frozenChunks().data());
}

TEST_CASE("solve history: clear starts empty, and a default history is empty") {
    CHECK(SolveHistory().empty());
    CHECK(SolveHistory().size() == 0);
    CHECK(SolveHistory().frozenChunks().empty());
    SolveHistoryBuilder builder;
    appendHistorySteps(builder, 1, 1200);
    const SolveHistory before = builder.snapshot();
    builder.clear();
    CHECK(builder.size() == 0);
    const SolveHistory after = builder.snapshot();
    CHECK(after.empty());
    CHECK(after.frozenChunks().empty());
    CHECK(before.size() == 1200);  // what was published before the reset stays readable
    appendHistorySteps(builder, 1, 3);
    const SolveHistory restarted = builder.snapshot();
    CHECK(restarted.size() == 3);
    CHECK(holdsStepsInOrder(restarted));
}

} // TEST_SUITE
