#include "devices/ThreadPriority.h"

#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace prisca::devices {

bool raiseCurrentThreadPriority() {
    // This thread alone (on Linux a thread is a task with its own id), and never the threads it
    // starts: SCHED_RESET_ON_FORK gives every task created from it (OpenCV's or a video
    // decoder's worker pool, whose workers spin while they wait for work) the normal policy and
    // nice value, so no busy-waiting thread runs ahead of everything else.
    const auto thread = static_cast<pid_t>(::syscall(SYS_gettid));
    sched_param realtime{};
    realtime.sched_priority = 10;  // low among real-time priorities; the kernel's own run higher
    if (::sched_setscheduler(thread, SCHED_FIFO | SCHED_RESET_ON_FORK, &realtime) == 0) {
        return true;
    }
    sched_param normal{};
    ::sched_setscheduler(thread, SCHED_OTHER | SCHED_RESET_ON_FORK, &normal);
    return ::setpriority(PRIO_PROCESS, static_cast<id_t>(thread), -10) == 0;
}

}  // namespace prisca::devices
