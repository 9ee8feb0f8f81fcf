#include "app/bench/BenchTable.h"

namespace radiant::app {

// PLACEHOLDER until its issue lands.
BenchTable benchScenes(const BenchOptions&) { return {"Scenes", {"status"}, {{"not measured yet"}}, {}}; }

} // namespace radiant::app
