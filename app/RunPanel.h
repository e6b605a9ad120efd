#pragma once

#include "app/RunWorker.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace prisca::app {

class LabSession;
class RunController;

/// Run, pause, stop and reset a run of the session's method on the simulated plant; trials,
/// seed, perturbation and sensor levels; simulation speed (1x, 10x, as fast as possible); the
/// big red E-STOP (Space or Esc anywhere in the window) and its reset; each trial's result.
class RunPanel : public QWidget {
    Q_OBJECT
  public:
    RunPanel(LabSession& session, RunController& run, QWidget* parent = nullptr);

    /// Starts a run with the session as it is now (the same as pressing Run).
    void startRun();
    /// Writes the last run's log (its finished trials, the CLI's `run --out` format). False with
    /// *error if there is none or it cannot be written.
    bool exportRunLog(const QString& path, QString* error) const;
    /// Speeds offered, simulated seconds per wall second (0 = as fast as possible).
    static QList<double> speeds() { return {1.0, 10.0, 0.0}; }

  signals:
    /// A run is about to start, or Reset was pressed: views clear their trails and charts.
    void runStarting();
    /// The operator pressed E-STOP (button, Space or Esc); sent at once, before the run reacts.
    void emergencyStopRequested();
    /// The operator reset E-STOP.
    void emergencyStopReset();

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslateUi();
    void updateButtons(RunPhase phase);
    void addTrialRow(int trial, const sim::TrialSummary& summary);

    LabSession& session_;
    RunController& run_;
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
    QPushButton* runButton_;
    QPushButton* pauseButton_;
    QPushButton* stopButton_;
    QPushButton* resetButton_;
    QPushButton* emergencyButton_;
    QPushButton* resetEmergencyButton_;
    QPushButton* exportLog_;  // the last run's log to CSV
    QLabel* status_;
    QTableWidget* results_;
};

}  // namespace prisca::app
