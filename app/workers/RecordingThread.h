#pragma once

#include "app/workers/RecordingWorker.h"
#include "devices/ThreadHandOff.h"

#include <QObject>

#include <memory>

namespace prisca::app {

/// The GUI thread's handle on a RecordingWorker running on its own thread, as RunThread is the
/// run's. Every call returns at once; the worker's signals arrive queued on the GUI thread.
/// requestStop() takes effect at the next control period, whatever the worker's queue holds.
class RecordingThread : public QObject {
    Q_OBJECT
  public:
    explicit RecordingThread(QObject* parent = nullptr);
    /// Stops the recording, quits the thread and waits for it (bounded; never terminates it).
    /// A recording under way keeps its stream file.
    ~RecordingThread() override;

    /// Records `plant` (with these physical parameters; null: the catalog's), streaming to
    /// `streamPath`.
    void start(const QString& plant, const QString& streamPath,
               std::shared_ptr<const sim::PlantParameters> parameters);
    /// The operator's input, held until the next one.
    void setInput(const Eigen::VectorXd& input);
    /// Ends the take: finished() follows with the demonstration.
    void stop();
    /// Any thread: the recording stops at its next control period (E-STOP while recording).
    void requestStop();

  signals:
    void samplesReady(const QVector<prisca::app::LiveSample>& samples);
    void finished(const prisca::core::Demonstration& demonstration, const QString& streamPath);
    void failed(const QString& message);

  private:
    RecordingWorker* worker_;
    devices::WorkerThread host_;  ///< the worker's thread (after the worker)
};

}  // namespace prisca::app
