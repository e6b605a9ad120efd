#pragma once

#include "core/Demonstration.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/PathDistance.h"
#include "sim/plants/Plant.h"

#include <Eigen/Core>

namespace prisca::sim {

/// How well one trial repeated the demonstration. NaN where a metric does not apply.
struct TrialSummary {
    double finalPositionError = 0.0;  ///< |p_end - p_lot| [m] (planar vehicles)
    double finalHeadingError = 0.0;   ///< |wrap(psi_end - psi_lot)| [rad] (planar vehicles)
    double trackingRms = 0.0;         ///< RMS over time of the tracked error (see trackedError)
    /// RMS over time of the distance to the nearest point of the demonstrated path [m]: how well
    /// the path is held regardless of timing (planar vehicles; NaN otherwise).
    double pathRms = 0.0;
    double meanCost = 0.0;  ///< mean C_k the controller saw
    double duration = 0.0;  ///< simulated time [s]
    /// Of it, run out in neutral after the trial's time, the vehicle still moving [s]
    /// (EpisodeResult::runOutSeconds): it was scored where it came to rest.
    double runOutSeconds = 0.0;
    /// The controller's CPU time per control step [us] (reports only).
    double controllerMicrosecondsPerStep = 0.0;
    /// False for a trial stopped before its end (its numbers cover only what was run).
    bool complete = true;
    /// The controller's word on the trial (Controller::trialNote): mpc's "planned through
    /// the model" or why a feedback law drove; empty for most controllers.
    QString controllerNote;
};

/// The error that "tracking error" means for a plant at step k, against the demonstration
/// sample of the same time (the last one past its end): the position error [m] for planar
/// vehicles, the joint-angle error norm [rad] otherwise (the paper's Fig. 3b uses its square).
double trackedError(const PlantInfo& info, const core::Demonstration& demonstration,
                    const Eigen::VectorXd& state, int step);

/// Distance [m] from (x, y) to the polyline through the demonstration's positions, by brute
/// force over every segment (PathDistance gives the same bits from an index): +infinity for an
/// empty demonstration, NaN if x or y is NaN. Requires a planar vehicle (info.pose).
double distanceToPath(const PlantInfo& info, const core::Demonstration& demonstration, double x,
                      double y);
/// How far a vehicle's final pose is from the lot (the demonstration's final pose): the
/// distance [m] and the heading difference's magnitude [rad], Table I's two errors. Wherever a
/// trial is scored (simulation, the rig, the virtual rig) it is scored by this.
struct ParkingError {
    double position = 0.0;  ///< [m]
    double heading = 0.0;   ///< [rad], in [0, pi]
};
ParkingError parkingError(const PlantInfo& info, const core::Demonstration& demonstration, double x,
                          double y, double heading);

/// Summary of a trial against the demonstration (the lot is its final pose).
/// The result must have its steps recorded for trackingRms and pathRms (else they are NaN).
/// Costs O(T log T + K log T) for T demonstration samples and K steps (PathDistance).
TrialSummary summarizeTrial(const PlantInfo& info, const core::Demonstration& demonstration,
                            const EpisodeResult& result);

/// A single number to minimise when tuning on training seeds: the final position error for
/// planar vehicles (what Table I ranks), the tracking RMS otherwise.
double tuningScore(const PlantInfo& info, const TrialSummary& summary);

}  // namespace prisca::sim
