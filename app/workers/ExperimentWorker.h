#pragma once

#include "core/Demonstration.h"
#include "sim/experiments/LearningCurveExperiment.h"
#include "sim/experiments/Table1Experiment.h"
#include "sim/run/RunSetup.h"
#include "sim/run/Task.h"
#include "sim/tuning/MethodTuning.h"

#include <Eigen/Core>
#include <QMetaType>
#include <QObject>

#include <atomic>
#include <memory>

namespace prisca::app {

/// What an experiment runs on, copied into the worker thread.
struct ExperimentRequest {
    enum class Kind { Table1, LearningCurves };
    Kind kind = Kind::Table1;
    sim::Task task;                 ///< the demonstration, its plant, profile and fit
    int trials = 20;                ///< Table I: evaluation trials per method
    int runs = 20;                  ///< learning curves: independent runs per method
    long long budgetSteps = 64000;  ///< learning curves: simulated steps per run
    sim::RunSettings settings;      ///< seed, levels, training trials, threads
};

/// Table I or the learning curves in the background (the same experiments as prisca-cli
/// table1 and curve). Lives on its own thread; cancel() may be called from any thread and stops
/// within a trial, keeping what finished.
class ExperimentWorker : public QObject {
    Q_OBJECT
  public:
    explicit ExperimentWorker(QObject* parent = nullptr) : QObject(parent) {}
    /// Any thread, before run() is posted: a cancel() from then on stops that run, even one
    /// that comes before the run has begun on the worker's thread.
    void prepare() { cancelled_.store(false); }
    /// Any thread.
    void cancel() { cancelled_.store(true); }
    /// Any thread: cancel() was called since prepare().
    bool isCancelled() const { return cancelled_.load(); }

  public slots:
    void run(const prisca::app::ExperimentRequest& request);

  signals:
    /// done of total units (trials or runs) so far, and a line for the status.
    void progress(int done, int total, const QString& text);
    void table1Finished(std::shared_ptr<const prisca::sim::Table1Result> result);
    void curvesFinished(std::shared_ptr<const std::vector<prisca::sim::CurveSummary>> curves,
                        bool cancelled);
    void failed(const QString& message);

  private:
    std::atomic<bool> cancelled_{false};
};

}  // namespace prisca::app

Q_DECLARE_METATYPE(prisca::app::ExperimentRequest)
Q_DECLARE_METATYPE(std::shared_ptr<const prisca::sim::Table1Result>)
Q_DECLARE_METATYPE(std::shared_ptr<const std::vector<prisca::sim::CurveSummary>>)
