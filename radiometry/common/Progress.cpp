#include "radiometry/common/Progress.h"

#include "radiometry/common/Error.h"

namespace radiant {

void Progress::checkCancelled() const {
    if (cancelRequested.load(std::memory_order_relaxed)) throw Cancelled();
}

} // namespace radiant
