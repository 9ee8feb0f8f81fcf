#pragma once
// Draws the lab's frames until a state is reached. The watchdog measures progress, not wall time
// (docs/RELIABILITY.md): the solver threads and the probe run at nice 10, and on a loaded machine
// they crawl without being stuck. The wait fails only after kStallSeconds in which the lab published
// nothing new: no snapshot of either solver, no probe reading. ctest's --timeout stays the backstop for
// a lab that keeps publishing and never arrives.
#include <doctest/doctest.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <tuple>

#include "app/Lab.h"

namespace radiant::test {

inline constexpr double kStallSeconds = 120;

/// What the lab has published so far: any change is progress.
inline auto labProgress(const app::Lab& lab) {
    const auto a = lab.snapshot(), b = lab.secondSnapshot();
    return std::make_tuple(a ? a->generation : std::uint64_t{0}, b ? b->generation : std::uint64_t{0}, lab.probeGeneration(),
                           lab.probeReading().has_value(), lab.secondProbeReading().has_value());
}

inline void frameUntil(app::Lab& lab, const std::function<bool()>& done, const std::string& what = "the expected state") {
    auto progress = labProgress(lab);
    auto lastProgress = std::chrono::steady_clock::now();
    for (;;) {
        lab.frame();
        if (done()) return;
        const auto now = std::chrono::steady_clock::now();
        if (const auto current = labProgress(lab); current != progress) {
            progress = current;
            lastProgress = now;
        } else if (std::chrono::duration<double>(now - lastProgress).count() > kStallSeconds) {
            const auto s = lab.snapshot();
            FAIL("the lab did not reach " << what << ": nothing new published for " << kStallSeconds << " s (generation "
                                          << (s ? s->generation : 0) << ", patches " << (s && s->mesh ? s->mesh->size() : 0)
                                          << ", solver builds " << (s ? s->solverBuilds : 0) << ", iteration "
                                          << (s ? s->stats.iteration : 0) << ", running " << (s && s->running)
                                          << ", error '" << (s ? s->error : std::string()) << "')");
        }
    }
}

/// The same, with the condition on the lab's newest snapshot.
inline void frameUntil(app::Lab& lab, const std::function<bool(const app::Snapshot&)>& done,
                       const std::string& what = "the expected state") {
    frameUntil(lab, [&] { return lab.snapshot() && done(*lab.snapshot()); }, what);
}

} // namespace radiant::test
