#pragma once

#include "app/workers/ExperimentWorker.h"
#include "devices/ThreadHandOff.h"

#include <QObject>

#include <memory>
#include <vector>

namespace prisca::app {

/// The GUI thread's handle on an ExperimentWorker running on its own thread, as RunThread is
/// the run's. Every call returns at once; the worker's signals arrive queued on the GUI thread.
/// cancel() takes effect within the trials under way, whatever the worker's queue holds.
class ExperimentThread : public QObject {
    Q_OBJECT
  public:
    explicit ExperimentThread(QObject* parent = nullptr);
    /// Cancels the experiment, quits the thread and waits for it (bounded; never terminates it).
    ~ExperimentThread() override;

    /// Runs the experiment; a cancel() from now on stops it, even before it has begun.
    void start(const ExperimentRequest& request);
    void cancel();
    /// cancel() was called since the last start().
    bool isCancelled() const;

  signals:
    /// done of total units (trials or runs) so far, and a line for the status.
    void progress(int done, int total, const QString& text);
    void table1Finished(std::shared_ptr<const prisca::sim::Table1Result> result);
    void curvesFinished(std::shared_ptr<const std::vector<prisca::sim::CurveSummary>> curves,
                        bool cancelled);
    void failed(const QString& message);

  private:
    ExperimentWorker* worker_;
    devices::WorkerThread host_;  ///< the worker's thread (after the worker)
};

}  // namespace prisca::app
