#include "devices/ProcessFailsafe.h"

#include <errno.h>
#include <signal.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

namespace prisca::devices::processfailsafe {

namespace {

// One open port. fd: -1 free, -2 being filled in, >= 0 registered. The handler reads fd, then
// the frame; registerPort() fills the frame before it publishes fd.
struct PortSlot {
    std::atomic<int> fd{-1};
    std::atomic<int> length{0};
    char frame[kMaxFrameBytes] = {};
};
PortSlot ports[kMaxPorts];

std::atomic<bool> endingFlag{false};
std::atomic<bool> heldFlag{false};  // stopped and continued: failsafe until someone takes over
std::atomic<bool> graceful{false};
std::atomic<int> firstStop{0};
std::atomic<int> endings{0};
std::atomic<bool> reported{false};  // the terminate handler said it already
char programName[64] = "prisca";

static_assert(std::atomic<int>::is_always_lock_free && std::atomic<bool>::is_always_lock_free);

// Every signal whose default action ends or stops the process, by what it means:
// a crash; a request to end (every other terminating signal, a timer's or a limit's included:
// none of them is ours, so each ends the process); job control, which stops it.
constexpr int kFatalSignals[] = {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGSYS, SIGTRAP};
// (prisca-cli ignores SIGXFSZ once these are installed, so that a write past a file-size limit
// fails with an error naming the file.)
constexpr int kStopSignals[] = {SIGINT,    SIGTERM, SIGHUP,    SIGQUIT, SIGPIPE, SIGUSR1,
                                SIGUSR2,   SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU, SIGXFSZ,
#ifdef SIGPWR
                                SIGPWR,
#endif
#ifdef SIGSTKFLT
                                SIGSTKFLT,
#endif
                                SIGIO};
constexpr int kPauseSignals[] = {SIGTSTP, SIGTTIN, SIGTTOU};

bool isStopSignal(int signal) {
    return std::find(std::begin(kStopSignals), std::end(kStopSignals), signal) !=
           std::end(kStopSignals);
}

// Async-signal-safe text: a fixed buffer appended to with plain copies.
struct Line {
    char text[256];
    size_t used = 0;
    Line& add(const char* s) {
        while (*s != '\0' && used + 1 < sizeof text) {
            text[used++] = *s++;
        }
        return *this;
    }
    Line& add(int n) {
        char digits[16];
        int count = 0;
        unsigned v = n < 0 ? 0u : static_cast<unsigned>(n);
        do {
            digits[count++] = static_cast<char>('0' + v % 10);
            v /= 10;
        } while (v != 0 && count < 15);
        while (count > 0 && used + 1 < sizeof text) {
            text[used++] = digits[--count];
        }
        return *this;
    }
    void writeToStderr() {
        add("\n");
        size_t done = 0;
        while (done < used) {
            const ssize_t n = ::write(STDERR_FILENO, text + done, used - done);
            if (n <= 0) {
                break;
            }
            done += static_cast<size_t>(n);
        }
    }
};

void writeAll(int fd, const char* data, int length) {
    int done = 0;
    int attempts = 0;
    while (done < length && attempts++ < 100) {
        const ssize_t n = ::write(fd, data + done, static_cast<size_t>(length - done));
        if (n > 0) {
            done += static_cast<int>(n);
        } else if (n < 0 && errno != EINTR && errno != EAGAIN) {
            return;  // the port is gone: its receiver's own failsafe takes over
        }
    }
}

bool portsRegistered() {
    for (const PortSlot& slot : ports) {
        if (slot.fd.load() >= 0) {
            return true;
        }
    }
    return false;
}

int writeFrames() {
    int written = 0;
    for (PortSlot& slot : ports) {
        const int fd = slot.fd.load();
        if (fd >= 0) {
            // Failsafe replaces what is still queued for the line: driving frames waiting in
            // the kernel's buffer would reach the receiver first (tcflush is async-signal safe).
            tcflush(fd, TCOFLUSH);
            writeAll(fd, slot.frame, slot.length.load());
            ++written;
        }
    }
    return written;
}

// The end of the process: failsafe, one line, the signal's default action.
void endNow(int signal) {
    endingFlag.store(true);
    const int written = sendNow();
    if (!reported.load() && !(signal == SIGPIPE && written == 0)) {
        Line line;
        line.add(programName).add(isStopSignal(signal) ? ": stopped by " : ": crashed (");
        line.add(signalName(signal)).add(isStopSignal(signal) ? "" : ")");
        if (written > 0) {
            line.add("; failsafe sent on ").add(written).add(written == 1 ? " link" : " links");
        }
        line.writeToStderr();
    }
    // The default action (end, or end with a core dump) once this handler returns.
    struct sigaction action {};
    action.sa_handler = SIG_DFL;
    sigemptyset(&action.sa_mask);
    sigaction(signal, &action, nullptr);
    raise(signal);
}

// Job control (Ctrl-Z, a background read or write): failsafe, then the stop the signal asks for;
// once continued, failsafe is held until the operator or the next trial takes over (held()).
void pauseNow(int signal) {
    heldFlag.store(true);
    const int written = sendNow();
    Line line;
    line.add(programName).add(": stopped by ").add(signalName(signal));
    if (written > 0) {
        line.add("; failsafe sent on ").add(written).add(written == 1 ? " link" : " links");
    }
    line.writeToStderr();
    // The stop the signal asks for, now, inside this handler; raise() returns once continued.
    // SIGSTOP, not the signal's own default action: that one the kernel discards in a process
    // group without a controlling shell (a service, a test runner's child), and the process
    // would say "stopped" and go on.
    raise(SIGSTOP);
}

extern "C" void onSignal(int signal) {
    const int savedErrno = errno;
    if (signal == SIGCONT) {
        // Continued after any stop, SIGSTOP's too (which no handler sees): the car was left
        // without frames, and the command it last had is out of date. Failsafe until taken over.
        if (portsRegistered()) {
            heldFlag.store(true);
            Line line;
            line.add(programName).add(": continued; the link holds failsafe");
            line.writeToStderr();
        }
        errno = savedErrno;
        return;
    }
    if (std::find(std::begin(kPauseSignals), std::end(kPauseSignals), signal) !=
        std::end(kPauseSignals)) {
        pauseNow(signal);
        errno = savedErrno;
        return;
    }
    if (isStopSignal(signal) && graceful.load()) {
        int none = 0;
        if (firstStop.compare_exchange_strong(none, signal)) {
            // Failsafe on the wire now, not once the command has noticed: the links send only
            // failsafe from here, and what they had queued is flushed.
            endingFlag.store(true);
            sendNow();
            errno = savedErrno;
            return;  // the command polls stopSignal() and ends its links in failsafe itself
        }
        if (signal == SIGPIPE) {
            errno = savedErrno;
            return;
        }
    }
    endNow(signal);
    errno = savedErrno;
}

[[noreturn]] void onTerminate() {
    endingFlag.store(true);
    const int written = sendNow();
    std::string what = "an unknown exception";
    if (const std::exception_ptr current = std::current_exception()) {
        try {
            std::rethrow_exception(current);
        } catch (const std::exception& error) {
            what = error.what();
        } catch (...) {
        }
    } else {
        what = "std::terminate";
    }
    std::fprintf(stderr, "%s: uncaught exception: %s%s\n", programName, what.c_str(),
                 written > 0 ? "; failsafe sent on the link" : "");
    std::fflush(stderr);
    reported.store(true);
    std::abort();
}

}  // namespace

int registerPort(int fd, const QByteArray& failsafeFrame) {
    if (fd < 0 || failsafeFrame.isEmpty() || failsafeFrame.size() > kMaxFrameBytes) {
        return -1;
    }
    for (int i = 0; i < kMaxPorts; ++i) {
        int expected = -1;
        if (ports[i].fd.compare_exchange_strong(expected, -2)) {
            std::memcpy(ports[i].frame, failsafeFrame.constData(),
                        static_cast<size_t>(failsafeFrame.size()));
            ports[i].length.store(static_cast<int>(failsafeFrame.size()));
            ports[i].fd.store(fd);
            return i;
        }
    }
    return -1;
}

void unregisterPort(int slot) {
    if (slot >= 0 && slot < kMaxPorts) {
        ports[slot].fd.store(-1);
    }
}

int sendNow() noexcept {
    const int written = writeFrames();
    if (written > 0) {
        // Again one frame period later: a frame another thread was writing at this moment (the
        // link's own) is followed by failsafe, whatever order the bytes took.
        timespec period{0, 20'000'000};
        while (nanosleep(&period, &period) != 0 && errno == EINTR) {
        }
        writeFrames();
    }
    return written;
}

bool ending() noexcept {
    return endingFlag.load();
}

bool held() noexcept {
    return heldFlag.load();
}

void releaseHold() noexcept {
    heldFlag.store(false);
}

void noteFailsafeEnding() noexcept {
    endings.fetch_add(1);
}

int failsafeEndings() noexcept {
    return endings.load();
}

void install(const char* program) {
    std::snprintf(programName, sizeof programName, "%s", program);
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    for (int signal : kFatalSignals) {
        sigaction(signal, &action, nullptr);
    }
    for (int signal : kStopSignals) {
        sigaction(signal, &action, nullptr);
    }
    for (int signal : kPauseSignals) {
        sigaction(signal, &action, nullptr);
    }
    action.sa_flags = SA_RESTART;  // a continue interrupts no system call
    sigaction(SIGCONT, &action, nullptr);
    std::set_terminate(onTerminate);
}

void acceptGracefulStop() {
    graceful.store(true);
}

int stopSignal() noexcept {
    return firstStop.load();
}

const char* signalName(int signal) noexcept {
    switch (signal) {
        case SIGINT:
            return "SIGINT";
        case SIGTERM:
            return "SIGTERM";
        case SIGHUP:
            return "SIGHUP";
        case SIGQUIT:
            return "SIGQUIT";
        case SIGPIPE:
            return "SIGPIPE";
        case SIGABRT:
            return "SIGABRT";
        case SIGSEGV:
            return "SIGSEGV";
        case SIGBUS:
            return "SIGBUS";
        case SIGFPE:
            return "SIGFPE";
        case SIGILL:
            return "SIGILL";
        case SIGSYS:
            return "SIGSYS";
        case SIGTRAP:
            return "SIGTRAP";
        case SIGUSR1:
            return "SIGUSR1";
        case SIGUSR2:
            return "SIGUSR2";
        case SIGALRM:
            return "SIGALRM";
        case SIGVTALRM:
            return "SIGVTALRM";
        case SIGPROF:
            return "SIGPROF";
        case SIGXCPU:
            return "SIGXCPU (the CPU-time limit)";
#ifdef SIGPWR
        case SIGPWR:
            return "SIGPWR";
#endif
#ifdef SIGSTKFLT
        case SIGSTKFLT:
            return "SIGSTKFLT";
#endif
        case SIGXFSZ:
            return "SIGXFSZ";
        case SIGIO:
            return "SIGIO";
        case SIGTSTP:
            return "SIGTSTP";
        case SIGTTIN:
            return "SIGTTIN";
        case SIGTTOU:
            return "SIGTTOU";
        case SIGCONT:
            return "SIGCONT";
        default:
            return "a signal";
    }
}

void injectFaultForTesting() {
    const char* fault = std::getenv("PRISCA_INJECT_FAULT");
    if (fault == nullptr || *fault == '\0') {
        return;
    }
#ifndef PRISCA_FAULT_INJECTION
    std::fprintf(stderr, "PRISCA_INJECT_FAULT is ignored: this build has no fault injection\n");
#else
    const std::string kind = fault;
    if (kind == "exception") {
        throw std::runtime_error("injected fault (PRISCA_INJECT_FAULT=exception)");
    }
    if (kind == "assertion") {
        // What a failed assertion does: a line, then abort().
        std::fprintf(stderr, "assertion failed: injected fault (PRISCA_INJECT_FAULT=assertion)\n");
        std::abort();
    }
    if (kind == "terminate") {
        // An exception escaping a thread's function: std::terminate.
        std::thread([] { throw std::runtime_error("injected fault on a worker thread"); }).join();
    }
    if (kind == "segfault") {
        raise(SIGSEGV);
    }
#endif
}

}  // namespace prisca::devices::processfailsafe
