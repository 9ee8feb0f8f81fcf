#pragma once
// Background work in the lab (the solver thread and its worker pool, the probe's measurements) runs
// only on cycles the window's threads leave. On two cores with software GL the window's main thread
// and llvmpipe's rasterisers want both cores every frame; a background thread at normal priority
// takes one from them and frames wait (bench frames, 20k patches, 1600 x 1000, solver running: p99
// 41-44 ms at nice +10, 31-35 ms at SCHED_IDLE; with a probe picked, its nice-0 measurements raised
// the p99 by another ~10 ms).
namespace radiant::app {

/// Puts the calling thread at SCHED_IDLE: a woken drawing thread preempts it at once, and with the
/// window idle (or on a GPU, waiting for the swap) it still has every core. Falls back to nice 19
/// where SCHED_IDLE is refused. RADIANT_SOLVER_NICE=n asks for nice n instead: the tests set it,
/// since under ctest -j other test processes are not idle time and would starve it. Linux's policy
/// and nice value are per thread, and threads started from this one inherit them.
void yieldToTheDisplay();

} // namespace radiant::app
