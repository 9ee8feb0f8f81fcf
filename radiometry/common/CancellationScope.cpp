#include "radiometry/common/CancellationScope.h"

namespace radiant {
namespace {
thread_local const Progress* innermost = nullptr;
}

CancellationScope::CancellationScope(const Progress& progress) : previous_(innermost) {
    innermost = &progress;
}

CancellationScope::~CancellationScope() {
    innermost = previous_;
}

const Progress* CancellationScope::current() {
    return innermost;
}

} // namespace radiant
