#pragma once

namespace prisca::devices {

/// Raises the calling thread's scheduling priority, so a frame that arrives while other programs
/// keep every core busy is tracked, controlled and sent at once instead of waiting for their
/// time slices: SCHED_FIFO at priority 10 where allowed (root, CAP_SYS_NICE, or an rtprio limit
/// such as "@lab - rtprio 10" in /etc/security/limits.conf), else a nice value of -10 for this
/// thread alone (an "@lab - nice -10" limit), else nothing changes and false is returned. The
/// camera's and the link's threads call it when they start; both sleep between frames. Threads
/// they start (OpenCV's or a video decoder's pool) get the normal policy (SCHED_RESET_ON_FORK).
bool raiseCurrentThreadPriority();

}  // namespace prisca::devices
