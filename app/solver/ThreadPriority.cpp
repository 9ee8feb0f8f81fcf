#include "app/solver/ThreadPriority.h"

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdlib>

namespace radiant::app {

void yieldToTheDisplay() {
    const auto thread = static_cast<id_t>(syscall(SYS_gettid));
    if (const char* nice = std::getenv("RADIANT_SOLVER_NICE")) {
        setpriority(PRIO_PROCESS, thread, std::atoi(nice));
        return;
    }
    const sched_param idle{};  // SCHED_IDLE takes priority 0
    if (pthread_setschedparam(pthread_self(), SCHED_IDLE, &idle) != 0) setpriority(PRIO_PROCESS, thread, 19);
}

} // namespace radiant::app
