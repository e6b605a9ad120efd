#pragma once

#include "core/ActionMapping.h"
#include "core/FeatureMap.h"
#include "core/IlcController.h"
#include "core/PdController.h"
#include "core/Pegasus.h"
#include "core/PgsdController.h"
#include "core/PriscaController.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/planning/MpcController.h"
#include "sim/planning/OracleController.h"
#include "sim/plants/MeasurementModel.h"
#include "sim/plants/Plant.h"

#include <Eigen/Core>

#include <memory>
#include <optional>

namespace prisca::sim {

/// How each method is set up on one plant: the intuitive mapping B~, the features, the
/// matching and cost weights, a camera-like measurement model, and every method's default
/// tuning. The app, the CLI and the experiments all start from here, so the baselines share
/// the plant, features and limits with PRISCA (docs/architecture.md "Baselines"). Plain data.
struct MethodTuning {
    PlantInfo info;                   ///< the plant
    core::IntuitiveMapping mapping;   ///< B~ (m x n signs)
    core::FeatureMap features;        ///< phi_l per channel
    Eigen::VectorXd matchingWeights;  ///< L1 weights of the least-state-deviation match (n)
    int matchingWindow = 40;          ///< forward search window [samples]
    /// The least-state-deviation reference falls at most this far behind the demonstration's
    /// clock [samples] (2 s at 40 Hz): a car standing just ahead of the start would otherwise
    /// wait for a reference that waits for it. Long enough never to touch a moving car's timing
    /// (10, 20, 40 samples cost the PD family accuracy on development cells; 80 did not).
    int matchingMaxLag = 80;
    Eigen::VectorXd costWeights;        ///< W in C = e^T W e (n)
    MeasurementParameters measurement;  ///< the sensor at "realistic" level
    double settleTime = 2.0;            ///< a trial runs this long past the demonstration [s]
    /// A vehicle still moving when its trial ends runs out in failsafe (neutral) until it rests,
    /// at most this long [s], and is scored where it rests (EpisodeSettings::runOutLimit).
    double runOutLimit = 0.0;
    /// Whether the trackers compensate the sensor's latency (EpisodeSettings): the reference is
    /// matched for the time the observation was taken. The slide-car's are (with every method
    /// re-tuned and the lost-track failsafe below); the acrobot's sensor has no latency, the
    /// aircraft's methods were tuned without.
    bool compensateLoopLatency = false;
    /// Position deviation [m] past which a trial ends in failsafe (EpisodeSettings); 0: never.
    double lostTrackDistance = 0.0;
    /// Each part of a perturbation level (initial state, parameters, actuator noise) as a share
    /// of the level: all 1 in every table; an ablation sets one part at a time.
    Perturbation perturbationShares = Perturbation::realistic();
    core::PriscaParameters prisca;  ///< PRISCA defaults
    /// PRISCA starts from the profile's PD law (pd, with priscaPriorHorizon) as its prior
    /// (PriscaParameters::prior) and learns a correction to it.
    bool priscaFromPd = false;
    /// The smoothing horizon of that law: -1 for pdHorizon (the slide-car's PD+H+LSD), 0 for
    /// the plain PD (the acrobot's and the aircraft's baseline).
    int priscaPriorHorizon = -1;
    /// PRISCA's reference: least-state-deviation where the task is a path (the car parks
    /// wherever the path ends), time-driven where it is a timed trajectory (the acrobot's
    /// "desired joint angles at each time step", paper V.A).
    core::MatchingParameters::Mode priscaMatching =
        core::MatchingParameters::Mode::LeastStateDeviation;
    /// PRISCA's own features and cost weights where its tuning chose others than the shared
    /// ones that PGSD and PEGASUS use (unset / empty: the shared ones).
    std::optional<core::FeatureMap> priscaFeatures;
    Eigen::VectorXd priscaCostWeights;
    /// PRISCA's model B (m x n): the fit B_v (.) B~, or the signs B~ alone where the fit is not
    /// to be trusted (a demonstration flown in closed loop confounds eq. 8; see docs/decisions.md).
    /// FittedWithDrift fits eq. 5 in full on the demonstration (A with B, so the closed-loop
    /// gradient propagates through the state's own drift too).
    enum class PriscaModel { Fitted, Signs, FittedWithDrift };
    PriscaModel priscaModel = PriscaModel::Fitted;
    /// PRISCA's automatic defaults, for a demonstration no one tuned on: its feature scales,
    /// alpha_0 and matching window derived from the demonstration and the fit instead of the
    /// preset numbers (automaticFeatures, automaticStep, automaticWindowSeconds). The preset's
    /// structure stays: which deviations feed which control, the model, gradient and R.
    bool priscaAutomatic = false;
    /// alpha_0 of the automatic defaults, one number for every plant: the fraction of a scalar
    /// Newton step taken per control step (StepSize::normalised), from sweeps on development
    /// cells (docs/research-log.md, "What the profiles' numbers rest on").
    static constexpr double automaticStep = 0.0003;
    double priscaAutomaticStep = automaticStep;  ///< the one in use (a method parameter)
    /// The automatic matching window: this much of the demonstration's time [s].
    static constexpr double automaticWindowSeconds = 1.0;
    /// The closed-loop gradient learns only where a robust fit explains the demonstration.
    bool priscaLearnWhereExplained = false;
    /// PRISCA's phase features [s] (0: none): on every channel, one feature per stretch of the
    /// demonstration this long, 1 while the reference is in it (core::FeatureTerm::Phase), so
    /// theta also learns a correction of u* along the manoeuvre, what a lab day's persistent
    /// mismatch (trim, throttle gain, grip) asks of it.
    double priscaPhaseSeconds = 0.0;
    /// Whether the PD family's feedback and PRISCA's prior act only while the reference is a
    /// sample the robust fit explains (not in a slide, where the linear model the gains stand
    /// on does not hold). Auto: with the demonstration start (whose gains come from that linear
    /// model), not with the tuned one (whose gains were tuned through the slides).
    enum class FeedbackGate { Auto, On, Off };
    /// For planar vehicles: the feedback's heading and yaw-rate terms change sign where the
    /// demonstration drives backwards (the steering turns the car the other way there).
    bool feedbackReverseAware = true;
    FeedbackGate feedbackGate = FeedbackGate::Auto;
    bool feedbackWhereExplained() const {
        return feedbackGate == FeedbackGate::On ||
               (feedbackGate == FeedbackGate::Auto && start == Start::Demonstration);
    }
    /// Where the feedback law PRISCA (its prior) and the PD family start from: the profile's
    /// tuned gains (pd, pdHorizon), or a law derived from the demonstration, the fit and the
    /// actuator limits alone (core::deriveStartLaw), for a robot no one tuned on. With the
    /// demonstration start PRISCA also takes its automatic defaults (priscaAutomatic).
    enum class Start { Tuned, Demonstration };
    Start start = Start::Tuned;
    /// The law PRISCA's prior and the PD family use under `start`: the profile's tuned PD with
    /// the given smoothing horizon, or the law derived from the demonstration and the fit B
    /// (m x n) with the same horizon. std::invalid_argument where the derivation cannot be made.
    core::PdParameters startLaw(const core::Demonstration& demonstration,
                                const Eigen::MatrixXd& fittedB, int horizon) const;
    /// The dead time [steps] between an action and its effect that explains the demonstration
    /// best: the fit's latency shift (ActionMappingFitOptions::latency) with the highest mean
    /// R^2 over the states it models, searched over a quarter of a second.
    int fittedDeadTime(const core::Demonstration& demonstration) const;
    core::PgsdParameters pgsd;  ///< PGSD defaults
    core::PdParameters pd;      ///< PD gains (error combination, Kp, Kd; horizon 0)
    int pdHorizon = 10;         ///< H for PD+H and PD+H+LSD [steps]
    /// ILC's learning (its error combination is the PD's, its feedback the PD's gains scaled).
    double ilcLearningScale = 0.3;  ///< learning gain Gamma = this x the PD's Kp, per control
    int ilcLead = 2;                ///< the error this many steps later corrects u_k [steps]
    double ilcCutoff = 2.0;         ///< Q filter, zero-phase low-pass cutoff [Hz]
    double ilcFeedbackScale = 1.0;  ///< the PD gains in ILC's loop, scaled by this
    /// The time-varying LQR (eq. 5), from grids on each plant's tuning cells (docs/results.md,
    /// "LQR"): R per control (empty: the plant has no LQR tuning), the terminal weight, and
    /// whether A is fitted with B.
    Eigen::VectorXd lqrEffort;
    double lqrTerminal = 100.0;
    bool lqrDrift = false;
    core::PegasusParameters pegasus;  ///< PEGASUS defaults
    /// The oracle's planner (the limit every accuracy figure is read against); its trial
    /// length is filled in from the demonstration when it is created.
    OracleParameters oracle;
    /// Whether the oracle plans through the proportional part of the PD feedback.
    bool oracleFeedback = true;
    /// Model-predictive parking (mpc): its planning, tube and refits.
    MpcParameters mpc;
    /// The model mpc plans through: an identified car (a plant file `identify` wrote); null:
    /// identified from the demonstration when the controller is made, starting from mpcPrior
    /// (the car's measured mass and geometry, the rest the catalog's; null: the catalog car).
    std::shared_ptr<const PlantParameters> mpcModel;
    std::shared_ptr<const PlantParameters> mpcPrior;
    int pegasusIterations = 10;  ///< gradient steps PEGASUS takes before it is evaluated

    /// How a trial of this plant repeating `demonstration` runs: the perturbation and the
    /// sensor scaled by their levels (0 nominal / perfect, 1 realistic; a perfect sensor also has
    /// no latency and no drops), the demonstration's length plus settleTime, and (vehicles) an
    /// early end once at rest after the demonstration's length. The seed and reset mode are the
    /// caller's.
    EpisodeSettings episode(const core::Demonstration& demonstration, double perturbation,
                            double sensor) const;
    /// ILC's parameters from the PD gains and the ILC fields above.
    core::IlcParameters ilcParameters() const;
    /// The tracking problem for a demonstration of this plant (deviation, matching, weights,
    /// limits); mode chooses least-state-deviation or time-driven matching.
    core::TrackingProblem trackingProblem(std::shared_ptr<const core::Demonstration> demonstration,
                                          core::MatchingParameters::Mode mode) const;
    /// PRISCA's tracking problem: its own reference mode and cost weights where it has them.
    core::TrackingProblem priscaProblem(
        std::shared_ptr<const core::Demonstration> demonstration) const;
    /// The features a method's theta is over: PRISCA's own where set, for a method with its own
    /// features (MethodSpec::ownFeatures: both PRISCA rows), the shared ones otherwise
    /// (MethodCatalog::featuresOf answers by the method's name).
    const core::FeatureMap& featuresFor(bool ownFeatures) const;
    /// The method's features with every deviation term's scale set to 1 / sigma_i, sigma_i the
    /// RMS of deviation i between the demonstration's states one matching window apart (how far
    /// that error component moves in a second of the manoeuvre), so that every feature is of
    /// order one whatever its unit. Other terms are kept.
    core::FeatureMap automaticFeatures(bool ownFeatures,
                                       const core::Demonstration& demonstration) const;
    /// The automatic matching window for a demonstration: automaticWindowSeconds of samples.
    static int automaticWindow(const core::Demonstration& demonstration);
};

/// The catalog plants' tunings (PlantCatalog's entries point here).
MethodTuning slideCarTuning(const PlantInfo& info);
MethodTuning acrobotTuning(const PlantInfo& info);
MethodTuning aircraftTuning(const PlantInfo& info);

}  // namespace prisca::sim
