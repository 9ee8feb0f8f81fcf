#pragma once
// The cancellation a thread's parallel loops poll. The lab's solver thread opens a scope around each
// solver step, so a command that discards the solver (a new mesh, method, grouping or link
// tolerance) stops a long step between chunks of work instead of waiting behind it: a hierarchical
// sweep over 60k patches took over 35 s. Loops read it ambiently (parallelFor, parallelChunks) so
// that no solver threads a flag through its phases; the command line and the tests open no scope,
// and their loops never stop early.
#include "radiometry/common/Progress.h"

namespace radiant {

class CancellationScope {
public:
    /// From here to the end of the scope, parallel loops started on this thread throw Cancelled
    /// (between chunks, on the calling thread) once `progress` asks for cancellation.
    explicit CancellationScope(const Progress& progress);
    ~CancellationScope();
    CancellationScope(const CancellationScope&) = delete;
    CancellationScope& operator=(const CancellationScope&) = delete;

    /// The innermost scope's progress on the calling thread; null outside every scope.
    [[nodiscard]] static const Progress* current();

private:
    const Progress* previous_;
};

} // namespace radiant
