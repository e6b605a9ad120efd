#include "devices/ThreadPriority.h"

#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace prisca::devices {

bool raiseCurrentThreadPriority() {
    // Real-time first: a frame's work (a millisecond) then never waits behind other programs'
    // time slices. The thread sleeps between frames, so it cannot starve the machine.
    sched_param realtime{};
    realtime.sched_priority = 10;  // low among real-time priorities; the kernel's own run higher
    if (::pthread_setschedparam(::pthread_self(), SCHED_FIFO, &realtime) == 0) {
        return true;
    }
    // Else a nice value for this thread alone (on Linux it belongs to the thread's task id).
    const auto thread = static_cast<id_t>(::syscall(SYS_gettid));
    return ::setpriority(PRIO_PROCESS, thread, -10) == 0;
}

}  // namespace prisca::devices
