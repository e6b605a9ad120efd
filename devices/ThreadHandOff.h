#pragma once
// Hand-offs between this project's threads made visible to ThreadSanitizer.
//
// Debian's Qt is not built with ThreadSanitizer: its event queue and QThread::wait() synchronise
// through futexes and detached threads TSan cannot see. So a value a thread writes and then hands
// to a worker through Qt's queue, or a worker object deleted after QThread::wait(), looks to TSan
// like a race although Qt orders it. These helpers tell TSan what Qt guarantees (release before
// the hand-off, acquire where it arrives), on the same object Qt synchronises on; in builds
// without TSan they are plain QMetaObject::invokeMethod and QThread::wait().
#include <QMetaObject>
#include <QObject>
#include <QThread>

#include <memory>
#include <type_traits>
#include <utility>

#if defined(__SANITIZE_THREAD__)
#define PRISCA_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define PRISCA_TSAN 1
#endif
#endif

#ifdef PRISCA_TSAN
#include <sanitizer/tsan_interface.h>
#endif

namespace prisca::devices {

#ifdef PRISCA_TSAN
/// Everything this thread did so far happens before a later happensAfter(token) on any thread.
inline void happensBefore(const void* token) {
    __tsan_release(const_cast<void*>(token));
}
/// Everything done before a happensBefore(token) happens before what this thread does next.
inline void happensAfter(const void* token) {
    __tsan_acquire(const_cast<void*>(token));
}
#else
inline void happensBefore(const void*) {}
inline void happensAfter(const void*) {}
#endif

/// Runs f on receiver's thread, queued (Qt::QueuedConnection): f and what the caller wrote before
/// posting happen before f runs, as Qt's posted-event queue (a mutex per receiving thread)
/// orders them. Under TSan f is moved to the heap first, so everything it carries is written
/// before the release; Qt's own slot object around it is Qt's business (tsan.supp).
template <class F>
void postTo(QObject* receiver, F&& f) {
#ifdef PRISCA_TSAN
    auto task = std::make_shared<std::decay_t<F>>(std::forward<F>(f));
    happensBefore(task.get());
    QMetaObject::invokeMethod(
        receiver,
        [task = std::move(task)] {
            happensAfter(task.get());
            (*task)();
        },
        Qt::QueuedConnection);
#else
    QMetaObject::invokeMethod(receiver, std::forward<F>(f), Qt::QueuedConnection);
#endif
}

/// Call once on a worker thread before starting it: the end of its run is marked, so that
/// endWorkerThread() can order everything the thread did before the worker is deleted.
inline void markThreadEnd(QThread& thread) {
    QObject::connect(&thread, &QThread::finished, [t = &thread] { happensBefore(t); });
}

/// Ends a worker's thread: quits its event loop, waits up to waitMs for it to end, then deletes
/// worker, after everything the thread did (TSan is told). A thread still running after waitMs
/// keeps its worker: left alone rather than deleted under it.
inline void endWorkerThread(QThread& thread, QObject* worker, unsigned long waitMs) {
    thread.quit();
    thread.wait(waitMs);
    if (!thread.isFinished()) {
        return;
    }
    happensAfter(&thread);
    delete worker;
}

/// A worker object on a thread of its own, hosted the one way the window hosts its workers: the
/// worker moved onto a named thread when this is made, the thread started by start() (after the
/// owner has connected to the worker), and ended when this goes (endWorkerThread: bounded, never
/// terminated; the worker deleted after everything its thread did). Declare it after the worker
/// it hosts; stop the worker's work (the flag it polls) before it goes.
class WorkerThread {
  public:
    WorkerThread(QObject* worker, const QString& name, unsigned long waitMs)
        : worker_(worker), waitMs_(waitMs) {
        thread_.setObjectName(name);
        worker_->moveToThread(&thread_);
    }
    ~WorkerThread() { endWorkerThread(thread_, worker_, waitMs_); }
    WorkerThread(const WorkerThread&) = delete;
    WorkerThread& operator=(const WorkerThread&) = delete;

    void start() {
        markThreadEnd(thread_);
        thread_.start();
    }
    /// Runs f on the worker's thread, queued (postTo).
    template <class F>
    void post(F&& f) {
        postTo(worker_, std::forward<F>(f));
    }

  private:
    QThread thread_;
    QObject* worker_;
    unsigned long waitMs_;
};

}  // namespace prisca::devices
