#include "app/bench/BenchTable.h"

namespace radiant::app {

// PLACEHOLDER until its issue lands.
BenchTable benchFormFactors(const BenchOptions&) { return {"FormFactors", {"status"}, {{"not measured yet"}}, {}}; }

} // namespace radiant::app
