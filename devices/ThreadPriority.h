#pragma once

namespace prisca::devices {

/// Raises the calling thread's scheduling priority (a nice value of -10 for this thread alone,
/// SCHED_OTHER as before), so a frame that arrives while other programs keep every core busy is
/// tracked, controlled and sent at once instead of waiting for their time slices. The camera's
/// and the link's threads call it when they start. Needs CAP_SYS_NICE (root, or an rlimit
/// allowing it, e.g. "@lab - nice -10" in /etc/security/limits.conf); without it nothing
/// changes and false is returned.
bool raiseCurrentThreadPriority();

}  // namespace prisca::devices
