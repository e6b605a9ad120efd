#pragma once

#include <QByteArray>

namespace prisca::devices::processfailsafe {

// The last resort for a car on the link (docs/architecture.md "Reliability"): every open
// transmitter link registers its port's file descriptor and its encoded failsafe frame here, so
// that however the process ends short of SIGKILL (a signal, an uncaught exception, a failed
// assertion, a crash) the last frames on the wire are failsafe: throttle neutral, steering
// centred. Everything a signal handler touches is lock-free and fixed in size.

/// How many links may be open at once (each a serial port).
constexpr int kMaxPorts = 8;
/// The largest failsafe frame (CRSF 26 bytes, SBUS 25, Multiprotocol 26).
constexpr int kMaxFrameBytes = 64;

/// Registers an open port. @return its slot, or -1 when there is none free (the link still
/// ends in failsafe on every orderly path; only the last-resort write is missing).
int registerPort(int fd, const QByteArray& failsafeFrame);
/// Before the port closes (its descriptor must never be written once closed).
void unregisterPort(int slot);

/// Writes every registered port's failsafe frame, twice, one frame period apart. Async-signal
/// safe. @return the number of ports written to.
int sendNow() noexcept;
/// True once the process is ending: links send failsafe only from then on.
bool ending() noexcept;
/// True once the process was stopped (SIGTSTP, SIGTTIN, SIGTTOU, or SIGSTOP, seen by its
/// SIGCONT) and continued with a link open: links send failsafe, latched like E-STOP, until
/// releaseHold() (the operator's E-STOP reset). Any thread.
bool held() noexcept;
void releaseHold() noexcept;
/// Links that closed with a failsafe frame as their last (for the message on exit).
void noteFailsafeEnding() noexcept;
int failsafeEndings() noexcept;

/// Installs the handlers for the whole process (call first thing in main), for every signal
/// whose default action ends or stops it:
///  - SIGABRT (a failed assertion, std::terminate), SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGSYS,
///    SIGTRAP: failsafe on every registered port, one line on stderr, then the default action.
///  - SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE and every other terminating signal (SIGUSR1,
///    SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU, SIGXFSZ, SIGPWR, SIGSTKFLT, SIGIO): the
///    same, until acceptGracefulStop(). (prisca-cli then ignores SIGXFSZ: a write past a
///    file-size limit fails with an error naming the file.)
///  - SIGTSTP, SIGTTIN, SIGTTOU: failsafe, one line, then the stop; once continued, held().
///  - SIGCONT with a link open: held() (a SIGSTOP left the car without frames).
///  - std::terminate (an uncaught exception): failsafe, the exception's message, abort.
/// Failsafe replaces what is still queued for a port: its output queue is flushed first.
/// @param program the name stderr lines start with (copied)
void install(const char* program);
/// From now on the terminating signals only ask the caller to stop (it polls stopSignal() and
/// ends its links in failsafe itself); a second one after the first ends the process at once,
/// in failsafe. Repeated SIGPIPEs (every write to a closed pipe) only keep the request.
void acceptGracefulStop();
/// The first stopping signal received since acceptGracefulStop(), 0 for none. Any thread.
int stopSignal() noexcept;
/// "SIGTERM", "SIGHUP", ... for a message.
const char* signalName(int signal) noexcept;

/// For the tests of the above on a real process (docs/testing.md): reads PRISCA_INJECT_FAULT
/// (exception, assertion, terminate, segfault) and raises that fault; does nothing when unset.
/// Only the link command calls it, once its first frames are out. Built in only with the tests
/// (CMake's PRISCA_FAULT_INJECTION, on with PRISCA_BUILD_TESTS); elsewhere it says on stderr
/// that the variable is ignored and raises nothing.
void injectFaultForTesting();

}  // namespace prisca::devices::processfailsafe
