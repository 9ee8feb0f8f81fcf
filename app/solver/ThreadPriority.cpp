#include "app/solver/ThreadPriority.h"

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdlib>
#include <string_view>

namespace radiant::app {
namespace {

/// RADIANT_SOLVER_NICE asks for SCHED_IDLE.
bool idleAsked() {
    const char* asked = std::getenv("RADIANT_SOLVER_NICE");
    return asked != nullptr && std::string_view(asked) == "idle";
}

int niceAsked() {
    const char* asked = std::getenv("RADIANT_SOLVER_NICE");
    return asked != nullptr ? std::atoi(asked) : kBackgroundNice;
}

} // namespace

void yieldToTheDisplay() {
    const auto thread = static_cast<id_t>(syscall(SYS_gettid));
    if (idleAsked()) {
        const sched_param idle{};  // SCHED_IDLE takes priority 0
        if (pthread_setschedparam(pthread_self(), SCHED_IDLE, &idle) != 0) setpriority(PRIO_PROCESS, thread, 19);
        return;
    }
    setpriority(PRIO_PROCESS, thread, niceAsked());
}

std::string backgroundPolicyName() {
    return idleAsked() ? "SCHED_IDLE" : "nice " + std::to_string(niceAsked());
}

} // namespace radiant::app
