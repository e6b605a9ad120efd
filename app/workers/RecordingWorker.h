#pragma once

#include "app/workers/RunWorker.h"
#include "core/Demonstration.h"
#include "core/DemonstrationStream.h"
#include "sim/plants/PlantParameters.h"

#include <Eigen/Core>
#include <QElapsedTimer>
#include <QFile>
#include <QObject>
#include <QVector>

#include <atomic>
#include <memory>
#include <vector>

class QTimer;

namespace prisca::sim {
class Plant;
}

namespace prisca::app {

/// Records a demonstration by driving a simulated plant in real time: at every control period
/// it applies the operator's latest input, records (state, action) and streams the row to a CSV
/// file in the demonstration format (core::DemonstrationStream: the header at once, rows flushed
/// every quarter second, so a crash loses at most that; a ".part" file renamed when it ends).
/// Lives on its own thread; slots are called queued, requestStop() from any thread.
class RecordingWorker : public QObject {
    Q_OBJECT
  public:
    explicit RecordingWorker(QObject* parent = nullptr);
    ~RecordingWorker() override;

    /// Any thread: stop at the next control period (E-STOP while recording).
    void requestStop() { stopRequested_.store(true); }

  public slots:
    /// Starts driving `plant` from its nominal start, streaming to `streamPath`.
    void start(const QString& plant, const QString& streamPath,
               std::shared_ptr<const sim::PlantParameters> parameters = nullptr);
    /// The operator's input (size m; clamped to the plant's limits).
    void setInput(const Eigen::VectorXd& input);
    /// Ends the recording: flushes and closes the stream, then emits finished().
    void stop();

  signals:
    void samplesReady(const QVector<prisca::app::LiveSample>& samples);
    /// The recording ended; the demonstration holds every recorded sample.
    void finished(const prisca::core::Demonstration& demonstration, const QString& streamPath);
    void failed(const QString& message);

  private:
    void tick();

    std::unique_ptr<sim::Plant> plant_;
    QTimer* timer_;
    QElapsedTimer clock_;
    QElapsedTimer flushClock_;  ///< paces the live samples to the GUI
    core::DemonstrationStream stream_;
    QVector<LiveSample> samples_;
    Eigen::VectorXd input_;
    Eigen::VectorXd state_;
    int steps_ = 0;  ///< control steps recorded
    std::atomic<bool> stopRequested_{false};
    bool active_ = false;
};

}  // namespace prisca::app

Q_DECLARE_METATYPE(prisca::core::Demonstration)
