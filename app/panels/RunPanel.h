#pragma once

#include "app/workers/RunWorker.h"

#include <QElapsedTimer>
#include <QWidget>

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace prisca::app {

class EmergencyStop;
class LabSession;
class RunThread;

/// Run, pause, stop and reset a run of the session's method on the simulated plant; trials,
/// seed, perturbation and sensor levels; simulation speed (1x, 10x, as fast as possible); each
/// trial's result. Run (F5), Pause (F6), Stop (Shift+F5), Reset (Ctrl+R), E-STOP and its reset
/// are actions (runActions()) the window puts in its Run menu and always-visible toolbar, so
/// their shortcuts work whatever has the focus and whichever docks are shown.
class RunPanel : public QWidget {
    Q_OBJECT
  public:
    /// The run stops when `emergency` engages and cannot start while it is latched.
    RunPanel(LabSession& session, RunThread& run, EmergencyStop& emergency,
             QWidget* parent = nullptr);

    /// Starts a run with the session as it is now (the same as pressing Run).
    void startRun();
    /// Writes the last run's log (its finished trials, the CLI's `run --out` format). False with
    /// *error if there is none or it cannot be written.
    bool exportRunLog(const QString& path, QString* error) const;
    /// Speeds offered, simulated seconds per wall second (0 = as fast as possible).
    static QList<double> speeds() { return {1.0, 10.0, 0.0}; }

    /// Run, Pause/Resume, Stop, Reset, with their shortcuts, enabled as the run's phase allows.
    QList<QAction*> runActions() const;
    /// E-STOP (the Run menu's; the window's keys and button press the latch directly) and its
    /// reset (enabled only while latched).
    QAction* emergencyAction() const { return emergencyAction_; }
    QAction* resetEmergencyAction() const { return resetEmergencyAction_; }

  signals:
    /// A run is about to start, or Reset was pressed: views clear their trails and charts.
    void runStarting();

  protected:
    void changeEvent(QEvent* event) override;
    /// The wheel over the results scrolls the results, never the dock behind them.
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void retranslateUi();
    void retranslateRunActions();
    void updateButtons(RunPhase phase);
    void addTrialRow(int trial, const sim::TrialSummary& summary);
    void clearResultsForNewTask();
    /// A trial that ends far worse than the run's first: a learner gone unstable, most likely.
    static bool diverged(const sim::TrialSummary& summary, double firstTrialRms);

    /// The latch engaged: the run stops within one control period.
    void emergencyStop();
    void showLatch(bool latched);

    LabSession& session_;
    RunThread& run_;
    EmergencyStop& emergency_;
    RunPhase phase_ = RunPhase::Idle;
    QLabel* trialsLabel_;
    QSpinBox* trials_;
    QLabel* seedLabel_;
    QSpinBox* seed_;
    QLabel* perturbationLabel_;
    QDoubleSpinBox* perturbation_;
    QLabel* sensorLabel_;
    QDoubleSpinBox* sensor_;
    QLabel* speedLabel_;
    QComboBox* speed_;
    QAction* runAction_;
    QAction* pauseAction_;
    QAction* stopAction_;
    QAction* resetAction_;
    QAction* emergencyAction_;
    QAction* resetEmergencyAction_;
    QPushButton* exportLog_;  // the last run's log to CSV
    QLabel* status_;
    QTableWidget* results_;
    // Shown when a trial diverges: what happened, and what the operator can do about it.
    QWidget* divergence_;
    QLabel* divergenceText_;
    QPushButton* divergenceStop_;
    QPushButton* divergenceRestart_;
    double firstTrialRms_ = 0.0;
    bool finishedSeen_ = false;    ///< the run under way told it finished
    QElapsedTimer runClock_;       ///< since the run's first trial began
    bool restartPending_ = false;  ///< a new run once the stopped one is idle  ///< the run's first
                                   ///< finished trial, the yardstick
};

}  // namespace prisca::app
