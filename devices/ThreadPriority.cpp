#include "devices/ThreadPriority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace prisca::devices {

bool raiseCurrentThreadPriority() {
    // On Linux a nice value belongs to a thread (its task id), not to the whole process.
    const auto thread = static_cast<id_t>(::syscall(SYS_gettid));
    return ::setpriority(PRIO_PROCESS, thread, -10) == 0;
}

}  // namespace prisca::devices
