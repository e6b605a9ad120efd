#pragma once

#include "core/Demonstration.h"
#include "sim/plants/Plant.h"
#include "sim/plants/PlantParameters.h"

#include <Eigen/Core>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <functional>
#include <vector>

namespace prisca::sim {

/// How a plant's parameters are fitted to recorded runs (docs/architecture.md
/// "Identification"). Plain data.
struct IdentificationSettings {
    /// Multiple shooting: each run is cut into segments this long; each segment restarts the
    /// model at the recorded state, with the commands of the steps before it still in flight,
    /// and replays the recorded commands [s]. Half a second: over a whole second the moment
    /// the tyres break away shifts with every parameter, and the cost is too rugged for the
    /// search to find its floor (docs/research-log.md, issue 33's eighth step).
    double segmentSeconds = 0.5;
    int evaluationsPerStart = 1500;   ///< model evaluations per local search
    int restarts = 2;                 ///< further local searches from perturbed starts
    double positionScale = 0.01;      ///< this much position error [m] ...
    double headingScale = 0.0174533;  ///< ... weighs as much as this heading error [rad]
    /// The residual's standard deviation is taken as at least this pose noise [m] (a camera's),
    /// so that noise-free data do not claim parameters they barely determine.
    double poseNoise = 0.003;
    /// A parameter counts as identified when its standard deviation is below this share of
    /// its value; the others are held at their prior.
    double identifiedBelow = 0.10;
    std::uint64_t seed = 1;  ///< the restarts' draws
    /// Physics steps per control step of the model fitted (SimulationTiming): the dead times
    /// are searched on this grid. A planner that simulates with fewer steps for speed fits its
    /// model with the same.
    int physicsSubsteps = SimulationTiming{}.physicsSubsteps;
    /// A search over the whole box first (a controlled random search). Off for a refit from a
    /// model already identified, which searches near it only.
    bool global = true;
    /// Passes of "the undetermined back at their prior, the rest fitted again" (at least 1).
    int passes = 3;
};

/// One parameter of an identified model. Plain data.
struct IdentifiedParameter {
    QString key;
    QString unit;
    double prior = 0.0;  ///< the value it started from (the prior plant file's)
    /// The identified value. Where not identified, the prior; but where the data reject the
    /// prior (the parameter is determined only together with others, as the two static grips
    /// on some cars), the value fitted with the rest, so that the rest stay right.
    double value = 0.0;
    double std = 0.0;         ///< its standard deviation (fitted ones; 0 for the held)
    bool fitted = false;      ///< the identification varied it
    bool identified = false;  ///< the data determined it (std below the threshold)
    /// Not identified and at its prior; not identified and elsewhere is undetermined (the data
    /// rejected the prior: the value fitted with the rest). One rule for every front end.
    bool heldAtPrior() const { return !identified && value == prior; }
};

/// The fit over one segment. Plain data.
struct SegmentFit {
    int run = 0;               ///< index of the run (0: the first given)
    double start = 0.0;        ///< [s] from the run's start
    double duration = 0.0;     ///< [s]
    double positionRms = 0.0;  ///< [m]
    double headingRms = 0.0;   ///< [rad]
};

/// The outcome of identifyPlant. Plain data.
struct IdentificationResult {
    QString refusal;  ///< non-empty: the data could not identify the plant, and why
    bool cancelled = false;
    PlantParameters parameters;  ///< the identified plant (the prior's for what was not fitted)
    std::vector<IdentifiedParameter> table;  ///< every parameter of the plant, in spec order
    std::vector<SegmentFit> segments;
    double positionRms = 0.0;       ///< over all segments [m]
    double headingRms = 0.0;        ///< [rad]
    double priorPositionRms = 0.0;  ///< the prior model's, for comparison [m]
    long long evaluations = 0;      ///< model evaluations used
    bool ok() const { return refusal.isEmpty() && !cancelled; }
};

/// Called now and then with the model runs done so far (over every pass) and about how many the
/// whole identification takes (an estimate, never below `done`; it may grow when a further pass
/// is needed); return false to cancel.
using IdentificationProgress = std::function<bool(long long done, long long total)>;

/// The plants identification knows, and which keys it fits for each (the others are held).
bool identificationAvailable(const QString& plant);
QStringList identifiedKeys(const QString& plant);

/// What a lab measures rather than identifies (the mass, the geometry: a scale and a ruler),
/// taken from `car`; every other parameter the catalog plant's. The prior an identification
/// starts from when it is to know nothing else of the car.
PlantParameters measuredPrior(const PlantParameters& car);

/// Empty when these runs can identify the plant; else why not, naming the run and where: a run
/// of another plant or shape, a gap in the poses, too short, constant actions, no slide (the
/// slide-car's grips need one).
QString identificationDataProblem(const QString& plant,
                                  const std::vector<core::Demonstration>& runs,
                                  const IdentificationSettings& settings = {});

/// Fits the plant's parameters to the runs by multiple shooting, starting from `prior`, with a
/// derivative-free local search (NLopt's subplex) over log-factors of the fitted parameters,
/// a search over each dead time on the physics step's grid, and restarts. Refuses (refusal set)
/// what identificationDataProblem refuses.
IdentificationResult identifyPlant(const std::vector<core::Demonstration>& runs,
                                   const PlantParameters& prior,
                                   const IdentificationSettings& settings = {},
                                   const IdentificationProgress& progress = {});

/// The position RMS [m] of a model over the runs' multiple-shooting segments (what
/// IdentificationResult::positionRms says of an identified one); -1 when the runs have fewer
/// than two segments with motion.
double modelPositionRms(const std::vector<core::Demonstration>& runs,
                        const PlantParameters& parameters,
                        const IdentificationSettings& settings = {});

/// The model's replay of the run's recorded actions from its first state, open loop over the
/// whole run (the window draws it next to the recorded path): T x n states.
Eigen::MatrixXd replayRun(const core::Demonstration& run, const PlantParameters& parameters,
                          int physicsSubsteps = SimulationTiming{}.physicsSubsteps);

}  // namespace prisca::sim
