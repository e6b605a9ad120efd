#pragma once

#include "app/workers/RunWorker.h"
#include "devices/ThreadHandOff.h"

#include <QObject>

namespace prisca::app {

/// The GUI thread's handle on a RunWorker running on its own thread. Every call returns at once;
/// the worker's signals arrive queued on the GUI thread. E-STOP is flagged directly (an atomic)
/// so it takes effect at the worker's next control step even while its event queue is busy.
class RunThread : public QObject {
    Q_OBJECT
  public:
    explicit RunThread(QObject* parent = nullptr);
    /// Stops the run, quits the thread and waits for it (bounded; never terminates it).
    ~RunThread() override;

    void start(const RunRequest& request);
    void pause();
    void resume();
    void stop();
    void emergencyStop();
    void resetEmergencyStop();
    /// Simulated seconds per wall second; 0 = as fast as possible.
    void setSpeed(double speed);

    RunPhase phase() const { return phase_; }
    /// The run log of the last run's finished trials (null before any run ended).
    std::shared_ptr<const core::RunLog> lastRunLog() const { return lastRunLog_; }
    /// The worker, for connecting to its signals (do not call its slots directly).
    const RunWorker* worker() const { return worker_; }

  signals:
    void samplesReady(const QVector<prisca::app::LiveSample>& samples);
    void phaseChanged(prisca::app::RunPhase phase);
    void progress(const QString& text);
    void trialStarted(int trial, int trials);
    void trainingProgress(int done, int total);
    void trialFinished(int trial, const prisca::sim::TrialSummary& summary);
    void runFinished();
    void runLogReady(std::shared_ptr<const prisca::core::RunLog> log);
    void failed(const QString& message);

  private:
    RunWorker* worker_;
    devices::WorkerThread host_;  ///< the worker's thread (after the worker)
    RunPhase phase_ = RunPhase::Idle;
    std::shared_ptr<const core::RunLog> lastRunLog_;
};

}  // namespace prisca::app
