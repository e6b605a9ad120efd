#pragma once

#include "core/Controller.h"
#include "sim/plants/Plant.h"

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <vector>

namespace prisca::sim {

/// Tuning of the oracle's planner. Plain data.
struct OracleParameters {
    /// What the plan minimises: the pose at the trial's end (slide parking, where Table I
    /// measures), or the time-aligned tracking error over a receding horizon (trajectories).
    enum class Objective { FinalPose, Tracking };
    Objective objective = Objective::Tracking;
    int replanEvery = 4;   ///< control steps between two plans (>= 1)
    int samples = 24;      ///< candidate plans tried at each planning (>= 1; the current one too)
    int knotSpacing = 10;  ///< control steps between knots of the correction (at least)
    int maxKnots = 8;      ///< knots per channel (>= 2); they spread out over a long remainder
    int horizon = 40;      ///< Tracking: control steps simulated ahead
    /// FinalPose: the final pose is planned for once the trial's end is at most this many
    /// control steps ahead; before that the plan tracks (the Tracking objective over `horizon`),
    /// so a long demonstration costs linear, not quadratic, time. Longer than any parking
    /// manoeuvre (20 s at 40 Hz), so the Table I trials plan for the final pose throughout.
    int finalPoseWindow = 800;
    /// FinalPose: the trial's longest length [control steps] and the step from which it ends
    /// once the plant is at rest (EpisodeSettings::duration and stopAtRestAfter).
    int trialSteps = 0;
    int restAfterStep = -1;
    /// FinalPose: a plant still moving at the trial's end runs on with the zero action for at
    /// most this many control steps, or until it rests, and the final pose is where it then is
    /// (EpisodeSettings::runOutLimit): a plan that drives through the lot at the last step is
    /// scored where the car coasts to, as the trial is. `mpc` plans so (its plans had learnt to
    /// creep through the lot at the last step); the oracle does not (0): planning for the coast
    /// it found, on one evaluation trial, a plan that ended 2.9 m away (docs/research-log.md,
    /// issue 33's tenth step).
    int runOutSteps = 0;
    /// Feedback u += K e around the time-aligned demonstration (m x n on the deviation e;
    /// empty: none). Planned through, so corrections are found for the closed loop, which
    /// keeps the plant on its plan between two plannings despite the actuator noise.
    Eigen::MatrixXd feedback;
    /// Each planning also takes Gauss-Newton steps from finite differences of the residuals
    /// (one rollout per knot and channel), which find smooth optima fast; the random samples
    /// keep the search going where the plant is not smooth (stick-slip). false: samples only.
    bool gaussNewton = true;
    double spread = 0.15;             ///< first search spread per knot, share of the half range [1]
    double minimumSpread = 0.003;     ///< the spread never shrinks below this share [1]
    double positionScale = 0.01;      ///< FinalPose: this much position error [m] ...
    double headingScale = 0.0174533;  ///< ... costs as much as this heading error [rad]
    std::uint64_t seed = 1;           ///< the planner's sampling (the same every trial)
    /// FinalPose: a correction of this share of the half range [1] costs as much as the
    /// position scale's error (a plan stays near the demonstration's actions unless moving
    /// pays); 0: corrections are free (the oracle, which plans on the plant itself).
    double correctionScale = 0.0;
    /// FinalPose: a root-mean-square distance [m] from the demonstration's path (time-aligned)
    /// over the rest of the trial costs as much as the position scale's error at the lot, so
    /// a plan keeps to where the demonstration drove (where a model was identified); 0: free.
    double trackingScale = 0.0;
    /// The largest correction, as a share of the half range [1] (1: the whole range).
    double maxCorrection = 2.0;
    /// Before the demonstration's step `calmUntil` the correction is at most `calmCorrection`
    /// of the half range [1], whatever the knots say: the plan keeps to the demonstration's
    /// actions on the way into a slide (-1: no such stretch).
    int calmUntil = -1;
    double calmCorrection = 2.0;
};

/// The limit of what a controller could do on this simulation: it is given the trial's own
/// perturbed plant (a copy it simulates ahead, without the actuator noise still to come) and the
/// true state, and plans corrections to the demonstration's actions on plant copies at the
/// control rate: Gauss-Newton steps from finite differences and random shooting around the
/// current plan (warm started, with an adaptive spread), keeping the best plan found. It is a
/// ruler, not a competitor: its error is what the perturbations and the actuator noise leave over
/// when the plant is known. The correction is piecewise linear in time between knots; the plan is
/// replayed open loop between two plannings. Single-threaded; one per trial (clone() for parallel
/// trials).
class OracleController : public core::Controller, public PlantAware {
  public:
    /// @param problem  the demonstration (its actions are the plan's starting point), the
    ///                 deviation model and the limits
    OracleController(core::TrackingProblem problem, OracleParameters parameters);

    QString name() const override { return QStringLiteral("oracle"); }
    void reset(core::ResetMode mode = core::ResetMode::Cold) override;
    const core::ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) override;
    std::unique_ptr<core::Controller> clone() const override;
    void attachPlant(const Plant* plant) override { plant_ = plant; }
    /// FinalPose: further plants a plan must hold on as well (robust planning through models
    /// that differ where the first is least sure): each one's final pose and path residuals
    /// join the first's, all weighted alike; the corrections' cost counts once. They are
    /// simulated from their own states. Not owned; empty: the attached plant only.
    void attachEnsemble(std::vector<const Plant*> plants) { ensemble_ = std::move(plants); }

    const OracleParameters& parameters() const { return parameters_; }
    /// Plant steps simulated ahead since the last reset (the planner's work).
    long long simulatedSteps() const { return simulatedSteps_; }

  private:
    void plan(int k);
    /// The residuals r of a plan (cost = |r|^2): the scaled final pose error, or the tracked
    /// errors over the horizon.
    Eigen::VectorXd rollout(const Eigen::MatrixXd& knots, const std::vector<int>& times, int k);
    /// FinalPose: runs `copy` under the plan from step k to the trial's end (or rest); the
    /// scaled final pose error, and the path's distance from the demonstration per step in
    /// `away` (x, y) if given.
    Eigen::Vector3d finalPoseOf(Plant& copy, const Eigen::MatrixXd& knots,
                                const std::vector<int>& times, int k, std::vector<double>* away);
    Eigen::MatrixXd clampedToLimits(Eigen::MatrixXd knots, const std::vector<int>& times) const;
    Eigen::VectorXd correctionAt(int t) const;
    Eigen::VectorXd actionAt(int t, const Eigen::VectorXd& correction,
                             const Eigen::VectorXd& state);

    core::TrackingProblem problem_;
    OracleParameters parameters_;
    const Plant* plant_ = nullptr;
    std::vector<const Plant*> ensemble_;
    std::mt19937_64 random_;
    Eigen::MatrixXd planKnots_;  // m x J corrections at planTimes_
    std::vector<int> planTimes_;
    Eigen::VectorXd spread_;  // m, current search spread [action units]
    Eigen::VectorXd halfRange_;
    Eigen::VectorXd deviation_;  // scratch for the feedback
    core::ControlStep record_;
    int step_ = 0;
    long long simulatedSteps_ = 0;
    bool finalPoseNow_ = false;  ///< this plan aims at the final pose (else it tracks)
};

}  // namespace prisca::sim
