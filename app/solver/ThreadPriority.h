#pragma once
// Background work in the lab (the solver thread and its worker pool, the probe's measurements) yields
// to the window's threads without letting other programs starve it. On two cores with software GL the
// window's main thread and llvmpipe's rasterisers want both cores every frame; a background thread at
// normal priority takes one from them and frames wait. SCHED_IDLE, the earlier policy, kept frames
// best (bench frames, 20k patches, 1600 x 1000, back to back, solver running: p99 31-35 ms, 41-44 ms at
// nice +10) but let a busy program stop the solve: with two nice-0 processes in the lab's session, the
// lab's Cornell box at 1487 patches had not finished its form factors after 120 s at SCHED_IDLE,
// converged in 57-93 s at nice 10 and in 30 and 42 s at nice 5 (22-32 s at nice 10 without them;
// bench frames, issue #17). Nice 10 is the compromise: a nice-0 drawing thread outweighs it about
// ten to one when both want a core, and it still gets about a tenth of a core from any nice-0 program.
#include <string>

namespace radiant::app {

/// The nice value of background threads, unless RADIANT_SOLVER_NICE says otherwise.
inline constexpr int kBackgroundNice = 10;

/// Puts the calling thread at nice kBackgroundNice. RADIANT_SOLVER_NICE=n asks for nice n instead,
/// and RADIANT_SOLVER_NICE=idle for SCHED_IDLE (the earlier policy, for comparison: it runs only on
/// cycles nothing else wants, and falls back to nice 19 where refused). Linux's policy and nice value
/// are per thread, and threads started from this one inherit them.
void yieldToTheDisplay();

/// What yieldToTheDisplay() asks for in this process, for bench tables: "nice n" or "SCHED_IDLE".
std::string backgroundPolicyName();

} // namespace radiant::app
