#pragma once

#include "app/workers/IdentificationWorker.h"
#include "devices/ThreadHandOff.h"

#include <QObject>

#include <memory>

namespace prisca::app {

/// The GUI thread's handle on an IdentificationWorker running on its own thread, as RunThread is
/// the run's. Every call returns at once; the worker's signals arrive queued on the GUI thread.
/// cancel() stops the search within a few model runs, whatever the worker's queue holds.
class IdentificationThread : public QObject {
    Q_OBJECT
  public:
    explicit IdentificationThread(QObject* parent = nullptr);
    /// Cancels the search, quits the thread and waits for it (bounded; never terminates it).
    ~IdentificationThread() override;

    /// Identifies; a cancel() from now on stops it, even before it has begun.
    void start(const IdentificationRequest& request);
    void cancel();
    /// cancel() was called since the last start().
    bool isCancelled() const;

  signals:
    void progress(int id, long long done, long long total);
    void finished(int id, std::shared_ptr<const prisca::sim::IdentificationResult> result);
    void failed(int id, const QString& message);

  private:
    IdentificationWorker* worker_;
    devices::WorkerThread host_;  ///< the worker's thread (after the worker)
};

}  // namespace prisca::app
