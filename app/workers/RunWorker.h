#pragma once

#include "core/Demonstration.h"
#include "core/RunLogCsv.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/run/RunSetup.h"
#include "sim/tuning/MethodTuning.h"

#include <Eigen/Core>
#include <QElapsedTimer>
#include <QJsonObject>
#include <QMetaType>
#include <QObject>
#include <QVector>

#include <atomic>
#include <memory>
#include <optional>

class QTimer;

namespace prisca::core {
class Controller;
}
namespace prisca::sim {
class Plant;
}

namespace prisca::app {

/// Everything a run needs, copied by value into the worker thread (plain data; the
/// demonstration is shared read-only).
struct RunRequest {
    sim::Task task;               ///< the demonstration, its plant, profile and fit
    QString method;               ///< sim::MethodCatalog id
    int trials = 5;               ///< trials in a row; learners keep learning (warm start)
    sim::RunSettings settings;    ///< seed, levels, training trials (sim::RunSetup's defaults)
    QString demonstrationSource;  ///< for the run log: the file, or the scripted style and seed
    /// Save each trial as a bundle (rig::writeSimulationBundle) in a new folder under this one;
    /// empty: none. `session` goes into each bundle's header.
    QString bundleParent;
    QJsonObject session;
};

/// One control step as the live views show it.
struct LiveSample {
    int trial = 0;                    ///< 0-based trial of the run
    int step = 0;                     ///< control step k within the trial
    double time = 0.0;                ///< t_k [s] within the trial
    double runTime = 0.0;             ///< simulated time since the run started [s]
    Eigen::VectorXd state;            ///< true state s_k
    Eigen::VectorXd action;           ///< u_k
    Eigen::VectorXd referenceAction;  ///< u*_{j_k}
    Eigen::VectorXd theta;      ///< theta flattened column by column (empty for fixed policies)
    int referenceIndex = 0;     ///< j_k
    double cost = 0.0;          ///< C_k
    double trackedError = 0.0;  ///< sim::trackedError: position [m] or joint angles [rad]
    std::optional<Eigen::Vector2d> wind;  ///< wind over the ground [m/s] (flying plants)
};

/// What the worker is doing.
enum class RunPhase {
    Idle,  ///< nothing to run (finished, stopped or never started)
    /// Preparing before the first step: training an offline method (PD (selected), PEGASUS), or
    /// identifying the model a method plans through (mpc). Work under way: E-STOP wins over
    /// every menu and dialog, as while running.
    Training,
    Running,           ///< stepping the plant
    Paused,            ///< stepping suspended; resume() continues the same trial
    EmergencyStopped,  ///< E-STOP: stepping stopped, latched until resetEmergencyStop()
};

/// Runs a method on a simulated plant, trial after trial, paced to real time, a multiple of it,
/// or as fast as possible. Lives on its own thread (RunThread moves it there); its slots are
/// called through queued connections, and requestEmergencyStop() from any thread. Samples are
/// emitted in batches (every ~40 ms of wall time and at the end of each trial) so a fast run
/// never floods the GUI thread.
class RunWorker : public QObject {
    Q_OBJECT
  public:
    explicit RunWorker(QObject* parent = nullptr);
    ~RunWorker() override;

    /// Any thread: no further control step is taken after this returns (the check is made
    /// before every step), so a run stops within one control period. Latched.
    void requestEmergencyStop() { emergency_.store(true); }
    /// Any thread: abandons training in progress (stop() cannot run until training returns).
    void requestCancel() { cancelTraining_.store(true); }

    /// Control steps taken in the current run (any thread; for tests and the status line).
    int stepsTaken() const { return stepsTaken_.load(); }

  public slots:
    /// Starts a run (stopping any run in progress). Errors (bad shapes, unknown names) are
    /// reported by failed(), never thrown.
    void start(const prisca::app::RunRequest& request);
    void pause();
    void resume();
    /// Stops the run; the trial in progress is reported as far as it went.
    void stop();
    /// Engages E-STOP now, whatever the phase (requestEmergencyStop() plus the phase change).
    void engageEmergencyStop();
    /// Clears a latched E-STOP (back to Idle; a new run must be started).
    void resetEmergencyStop();
    /// Simulated seconds per wall-clock second; 0 means as fast as possible.
    void setSpeed(double speed);

  signals:
    /// A trial's bundle is on disk (RunRequest::bundleParent).
    void bundleSaved(const QString& folder);
    void samplesReady(const QVector<prisca::app::LiveSample>& samples);
    void phaseChanged(prisca::app::RunPhase phase);
    /// One line for the status bar ("trial 2 of 5", "training PD (selected): ...").
    void progress(const QString& text);
    /// Trial `trial` (0-based) of `trials` has begun.
    void trialStarted(int trial, int trials);
    /// Training before the run: `done` of `total` steps (total 0: not known).
    void trainingProgress(int done, int total);
    void trialFinished(int trial, const prisca::sim::TrialSummary& summary);
    /// All trials done (not sent after stop() or E-STOP).
    void runFinished();
    /// The run log of the trials that finished (the CLI's `run --out` format), when the run
    /// ends (before phaseChanged(Idle)), is stopped or meets E-STOP; a trial cut short is not
    /// in it.
    void runLogReady(std::shared_ptr<const prisca::core::RunLog> log);
    void failed(const QString& message);

  private:
    void tick();
    void beginTrial();
    void endTrial();
    void saveBundle(const sim::EpisodeResult& result, const sim::TrialSummary& summary);
    void flushSamples();
    void setPhase(RunPhase phase);
    void enterEmergencyStop();
    /// The trial under way, cut short by Stop or E-STOP: reported as far as it went.
    void reportCutTrial();
    void repace();

    RunRequest request_;
    std::optional<sim::RunSetup> setup_;
    std::unique_ptr<sim::Plant> plant_;
    std::unique_ptr<core::Controller> controller_;
    core::RunLog runLog_;  // the finished trials of this run
    void emitRunLog();
    std::unique_ptr<sim::EpisodeStepper> stepper_;
    QTimer* timer_;
    QElapsedTimer paceClock_;   ///< wall time since the pace was last anchored
    QElapsedTimer flushClock_;  ///< wall time since samples were last sent
    int paceOriginStep_ = 0;    ///< step count at the pace anchor
    double speed_ = 1.0;
    int trial_ = 0;
    double runTimeOffset_ = 0.0;
    RunPhase phase_ = RunPhase::Idle;
    QVector<LiveSample> pending_;
    std::atomic<bool> emergency_{false};
    std::atomic<bool> cancelTraining_{false};
    std::atomic<int> stepsTaken_{0};
};

}  // namespace prisca::app

Q_DECLARE_METATYPE(prisca::app::RunRequest)
Q_DECLARE_METATYPE(prisca::app::LiveSample)
Q_DECLARE_METATYPE(prisca::app::RunPhase)
Q_DECLARE_METATYPE(prisca::sim::TrialSummary)
Q_DECLARE_METATYPE(std::shared_ptr<const prisca::core::RunLog>)
