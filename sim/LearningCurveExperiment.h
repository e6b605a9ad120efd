#pragma once

#include "core/Statistics.h"

#include "EpisodeRunner.h"
#include "PlantProfile.h"
#include "core/Demonstration.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

namespace prisca::sim {

/// Learning curves at an equal budget of simulated experience (paper Fig. 3b). Plain data.
struct LearningCurveSettings {
    QString plant = QStringLiteral("acrobot");
    QStringList methods = {"prisca", "pgsd", "pegasus"};  ///< curveMethods()
    int runs = 20;  ///< independent runs per method (run r: seeds from mixSeed(seed, r))
    std::uint64_t seed = 1;
    long long budgetSteps = 64000;  ///< simulated control steps each run may consume
    double perturbation = 1.0;      ///< plant perturbation level
    double sensor = 1.0;            ///< sensor noise level
    int threads = 2;
    std::function<bool()> cancelled;
    std::function<void(const QString&)> progress;
};

/// The methods a learning curve can show: the learners (PRISCA, PGSD, ILC online, PEGASUS
/// offline) and, as flat lines to read them against, the fixed controllers and the oracle.
QStringList curveMethods();
bool isCurveMethod(const QString& method);

/// One run's curve: tracking error after each unit of experience.
struct CurvePoint {
    long long steps = 0;  ///< cumulative simulated steps consumed so far
    double trackingError =
        0.0;  ///< mean over a trial of the squared tracked error (rad^2 for the acrobot)
};

/// All curves of one method.
struct MethodCurves {
    QString method;
    std::vector<std::vector<CurvePoint>> runs;
};

/// Runs the experiment: PRISCA and PGSD learn online over consecutive trials (warm start), and
/// each trial's own tracking error is a point; PEGASUS iterates on fixed scenarios (mixSeed of the
/// run seed), and after each iteration its policy is scored on a fresh trial it never trained on,
/// as the online learners are (that evaluation is not charged to its budget). Independent of the
/// thread count.
std::vector<MethodCurves> runLearningCurves(
    const LearningCurveSettings& settings, std::shared_ptr<const core::Demonstration> demonstration,
    const PlantProfile& profile, const Eigen::MatrixXd& fittedB);

/// Resamples a run onto a common grid of step counts: at each grid point, the error of the most
/// recent point at or before it (NaN before the first).
std::vector<double> resampleCurve(const std::vector<CurvePoint>& run,
                                  const std::vector<long long>& grid);

/// One method's curve on a common grid: mean and 95% band over its runs (Fig. 3b).
struct CurveSummary {
    QString method;
    std::vector<long long> steps;  ///< grid of simulated steps
    std::vector<double> seconds;   ///< the same in simulated seconds
    core::ConfidenceBand band;     ///< mean, lower, upper and count per grid point
};

/// Resamples every run on a grid of one point per `unit` steps up to `budgetSteps` and
/// summarises each method over its runs.
std::vector<CurveSummary> summarizeCurves(const std::vector<MethodCurves>& curves, long long unit,
                                          long long budgetSteps, double dt);

}  // namespace prisca::sim
