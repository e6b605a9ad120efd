#pragma once

#include "core/Controller.h"
#include "sim/planning/Identification.h"
#include "sim/planning/OracleController.h"
#include "sim/plants/PlantParameters.h"

#include <Eigen/Core>
#include <QString>

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace prisca::sim {

/// Tuning of model-predictive parking (docs/architecture.md "Planning through the slide").
/// Plain data.
struct MpcParameters {
    int replanEvery = 2;  ///< control steps between two plans (2 at 25 Hz: every 0.08 s)
    int rollouts = 12;    ///< model runs per plan: the planning's budget (>= 2 m knots + 2)
    int maxKnots = 4;     ///< knots per channel of the plan's correction (>= 2)
    /// A correction of this share of the half range costs as much as 1 cm at the lot: the plan
    /// stays near the demonstration's actions unless moving away pays (OracleParameters).
    double correctionScale = 0.2;
    double maxCorrection = 0.6;  ///< the largest correction, share of the half range
    /// A root-mean-square distance from the demonstration's path this large [m] costs as much
    /// as 1 cm at the lot: the plan keeps to where the car was identified.
    double trackingScale = 0.3;
    /// Whether the plan's actions carry the PD's time-aligned feedback between plannings (as the
    /// oracle's do). Off: the plan is replayed as planned and the replanning is the feedback;
    /// with it, a car that lags its demonstration on the straight (another day's grip, a
    /// weaker battery) is pushed into the slide with throttle on, and spins.
    bool feedback = false;
    /// Robust planning: the plan must also park the model with its tyres' grips this share
    /// lower (a floor of uneven grip, tyres the model's friction law only approximates: the
    /// side a plan spins out on); 0: the model alone. (A third model with more grip as well
    /// cost half again the planning time, over the real-time budget, for no dependable gain on
    /// the development cells: docs/research-log.md.)
    double gripSpread = 0.15;
    /// Physics steps per control step of the model (it is identified with the same), fewer
    /// than the simulator's for speed.
    int substeps = 4;
    /// The predicted tube: every control step, the model replays the commands sent over the
    /// last `tubeSeconds` from the state measured then; a measured position this far [m] or a
    /// heading this far [rad] from that prediction on `tubeStrikes` steps in a row, and the
    /// trial is finished by the fallback law.
    double tubePosition = 0.15;
    double tubeHeading = 0.6;
    double tubeSeconds = 0.4;
    int tubeStrikes = 3;
    /// The spin guard: up to the demonstration's fastest turn, a measured yaw rate this far
    /// [rad/s] or a side-slip angle this far [rad] from every one the demonstration had within
    /// `spinWindow` [s] of the same time, on `tubeStrikes` steps in a row while the car moves
    /// faster than `spinSpeed` [m/s], and the trial is finished by the fallback law. A car
    /// that enters the slide already sliding the wrong way (the model's Coulomb tyres held on
    /// the straight where the car's did not) spins 2.5-3.6 m away under the plan; the tube cannot
    /// see it, as the model predicts a spin once it has begun. 0 switches a check off.
    double spinYawRate = 1.5;
    double spinSideSlip = 0.17453292519943295;  // 10 deg
    double spinWindow = 0.3;
    double spinSpeed = 1.0;
    /// On the way into the slide (before the demonstration's yaw rate first reaches
    /// `turnShare` of its largest) the plan corrects the demonstration's actions by at most this
    /// share of the half range. There the model's Coulomb tyres hold where the car's, sharing
    /// their grip with the drive, may not, and the motor is known only near the demonstration's
    /// throttle: a plan that steered or eased off on the straight to save the slide later spun
    /// the car or left it metres short (docs/research-log.md, issue 33's sixth step). At 0.2
    /// a planned car still left the straight 36-39 deg off its predicted heading on one
    /// development cell in three trials of eight (1.5-2.6 m); 0.05 parked that cell at 5.9 cm
    /// and halved the mean over eleven planned cells (thirteenth step).
    double straightCorrection = 0.05;
    double turnShare = 0.3;
    /// The model's position RMS over its data's segments [m] above which identification
    /// searches again (`retryEvaluations`).
    double poorFit = 0.10;
    /// The model's position RMS over its data's segments [m] above which it is not planned
    /// through at all: the start law drives the whole trial. On the development cells with the
    /// reality gap the models that fitted worse than about 3.5 cm planned the car into spins
    /// 1.7-5.4 m from the lot, where a feedback law from the start parked within 20 cm
    /// (docs/research-log.md, issue 33's twelfth step); 3 cm until the day's trials could take a
    /// plan that parks badly off the car (`planTrust`): with it, 4.5 cm took 136 seen cells
    /// from 10.04 cm to 8.42, where 7 cm let single trials spin metres away (twentieth step).
    double planFit = 0.045;
    /// A demonstration whose largest sideways speed [m/s] is under this is not planned
    /// through: the start law drives every trial. The plan is for the slide a feedback law
    /// cannot hold. On the third and fourth held-out rounds' cars (then seen; 4 trials a cell)
    /// the 31 planned demonstrations sliding less than 1.2 m/s parked at 12.7 cm where ILC's
    /// loop from the start parked 8.4, the 12 sliding more at 4.3 against 12.4; on the catalog
    /// car (no reality gap) planned slides of 0.98-1.05 m/s parked at 3.8-6.4 cm against the
    /// loop's 6.6-7.4 (docs/research-log.md, issue 33's fifteenth step). That was 1.0 m/s, from
    /// before the day's trials chose who drives (`planTrust`) and the law parked the car
    /// (`parkingSpeed`); with them, the 28 seen cells of the fifteenth and sixteenth held-out
    /// rounds sliding 0.3-1.0 m/s parked at 6.57 cm planned against 8.35 for the loop (trials
    /// 5-8 of 8), and held out (gap-eval17) 4.86 cm against 4.88, no day worse by more than
    /// 0.32 cm (issue 33's twenty-third step): 0.3 m/s, where identification's own refusal
    /// ("no slide") begins. 0: every demonstration identification accepts is planned through.
    double planSlide = 0.3;
    /// The model is fitted over stretches of its data this long [s] (identification's
    /// segmentSeconds).
    double modelSegment = 1.0;
    /// After each trial the model is refit on the demonstration and the day's trials before
    /// it, and kept only when it predicts that trial better. Off: on two development days the
    /// refits cost about 4 cm a trial (docs/research-log.md, issue 33's seventeenth step).
    bool refit = false;
    int refitTrials = 4;            ///< at most this many of the newest trials, with the demo
    int identifyEvaluations = 400;  ///< identification's budget from the demonstration
    /// A fit from that budget worse than `poorFit` is searched again with this budget per
    /// start and two restarts, and the better kept: a poor fit from the quick search was a
    /// local minimum on a development car (16 cm; 2.6 cm with 1,000 evaluations); 0: never.
    int retryEvaluations = 1200;
    int refitEvaluations = 120;  ///< a refit's (a local search from the model)
    /// Inside a trial, once the car is parking (past the demonstration's fastest turn) and
    /// rolls straight, the model's rolling resistance is corrected from its own prediction
    /// errors, as offset-free model-predictive control corrects a model by an estimated
    /// disturbance: each step it moves by this share of the deceleration [m/s^2] (over g) the
    /// model missed over the tube's window. 0: off. The development run went from 14.2 to
    /// 9.2 cm at 0.05 and at 0.2 alike (docs/research-log.md, issue 33's tenth step).
    double rollingBiasGain = 0.05;
    /// On the way into the slide, while the car rolls faster than 1 m/s, the model's steering
    /// offset (a trim the car has and the model has not) follows the heading the model missed
    /// over the tube's window: each step it moves by this share of the offset that would have
    /// explained it (kinematic steering). 0: off.
    double steeringBiasGain = 0.1;
    /// Past the demonstration's fastest turn, once the measured speed falls below this [m/s],
    /// the feedback law (the fallback's, PD+LSD) parks the car; 0: the plan drives to the end.
    /// The plan creeps to the lot with throttles of a few hundredths the model believes and a
    /// car it does not match (tyres, motor, floor, the ESC's neutral band) may not follow. At
    /// 0.5 eleven planned development cells with the reality gap went from 7.55 cm to 3.35; held
    /// out (the fourth round's cars) 10.55 cm to 10.93, the loss on 90-degree turns that
    /// `planSlide` at 1.0 m/s then left to the start law; on those cars' 13 planned
    /// demonstrations over that bound 5.64 to 3.00
    /// (docs/research-log.md, issue 33's fourteenth and fifteenth steps).
    double parkingSpeed = 0.5;
    /// The hand-over waits, too, until the measured position is within this distance [m] of
    /// the lot (the demonstration's last pose); farther away the plan drives on. The law's
    /// least-state-deviation reference follows the car along the path, so a car that slowed
    /// on its path short of the lot gets no throttle from it and coasts to rest there. At 0.2
    /// the 67 planned development cells went from 7.33 cm to 6.31, but held out on new cars
    /// (the tenth round) from 8.54 to 9.54: off (research-log.md, issue 33's eighteenth
    /// step). 0: at any distance.
    double parkingDistance = 0.0;
    /// Once the feedback law parks the car, a car whose coast would end more than this [m]
    /// short of the lot (along the lot's heading, the way the demonstration arrived) is pushed
    /// on until its coast ends 2 cm short: the throttle follows the speed from which the car,
    /// coasting as the demonstration coasted into the lot, would come to rest there. The law's
    /// reference follows the car along the path, so it gives a car that slowed short no
    /// throttle. At 0.1 the 67 planned development cells went from 7.33 cm to 4.58 (worse on
    /// 2), and held out (the eleventh round) from 18.95 to 18.28, no day worse; pushing at 3 cm
    /// short instead was worse on 37 of the 67 (research-log.md, issue 33's nineteenth step).
    /// 0: off.
    double parkingApproach = 0.1;
    /// The day's trials choose who drives: once a planned trial has parked farther than this
    /// [m] from the lot (measured, as the camera sees the car at the trial's end), the next
    /// trial is the start law's, and from then on each trial goes to whichever of the two has
    /// parked the day's trials closer on average (the plan on a tie). A model that fits its
    /// data well can still plan one car's slide wrongly every trial (the tube left at the same
    /// moment each time) where the start law parks it; the fit alone does not tell the two
    /// apart (docs/research-log.md, issue 33's twentieth step). 0: the plan drives every trial
    /// it may.
    double planTrust = 0.1;
    /// A trial not planned through is the start law's until the day's trials it drove park on
    /// average farther than `planTrust`; then the next is the fallback law's (PD+LSD) from its
    /// start, and from then on the one of the two with the lower mean of the day drives such
    /// trials. The plan is weighed against the better of the two. Off (or `planTrust` 0): the
    /// start law drives every trial not planned through. On the fifteenth held-out round's 25
    /// stick-90-left cells (then seen; never planned: the demonstrations slide under `planSlide`),
    /// replayed from each law's 8 trials, ILC's loop alone 9.56 cm, PD+LSD alone 8.00, the
    /// choice 7.51 (docs/research-log.md, issue 33's twenty-second step). Held out on the
    /// sixteenth round (the day's trials in a row) it parked at 9.51 cm against 9.21 without
    /// it, better on four days of five, but one cell at 138 cm where PD+LSD ran the car away:
    /// off (docs/results.md).
    bool lawChoice = false;
    /// The start law (ILC's loop) keeps ILC's learning across the day's trials it drives from
    /// their start, learning from those trials only. On the thirteenth held-out round's two hard
    /// days (then seen) the models of 13 of the 20 demonstrations fitted worse than `planFit`
    /// and the loop without learning drove every trial, 1-2 cm a cell behind ILC's own row on
    /// every one of them (docs/research-log.md, issue 33's twenty-first step). Off: every trial
    /// the start law drives is as the day's first.
    bool startLearning = true;
};

/// What the day's trials gave each driver: the measured distance [m] from the lot at each
/// trial's end, the planned trials' and the start law's. Plain data.
struct MpcDayRecord {
    std::vector<double> planned;
    std::vector<double> startLaw;
    /// Trials the fallback law (PD+LSD) drove from their start (lawChoice).
    std::vector<double> fallbackLaw;
};

/// Who drives a trial now: the plan through the model; the feedback law because the model could
/// not be planned through or stopped holding (a fallback); or the feedback law parking the car
/// the plan brought out of its slide (a hand-over, no fault of the model's).
enum class MpcMode { Planning, Fallback, Parking };

/// Model-predictive parking: each control step the model (an identified car, a plant file)
/// is set to the measured state, predicted through the sensor's latency with the commands
/// sent since, and every `replanEvery` steps the oracle's planner (OracleController) searches
/// corrections to the demonstration's actions that bring the model's final pose onto the
/// demonstration's, within a budget of model runs. It knows only what the rig knows: the
/// measured (filtered) state and its own commands; nothing of the trial's draws.
/// A trial the model is not planned through (it fits its data worse than `planFit`, there is
/// none, or the demonstration slides less than `planSlide`) is driven by a start law from its
/// start; a planned trial is handed to a fallback law (the PD family's) for its rest once the
/// measured state leaves the model's predicted tube or spins, and (`parkingSpeed`) to the same law
/// to park once past the slide and slow. Learns across trials by refitting the model on the
/// demonstration and the day's trials the plan drove (reset(WarmStart)), keeping a refit only when
/// it predicts the newest trial, which it was not fitted on, better; a cold reset goes back to the
/// first model.
class MpcController : public core::Controller {
  public:
    /// @param problem   the demonstration and limits (time-driven)
    /// @param planner   the oracle's planner settings (final-pose objective, trial length)
    /// @param fallback  the feedback law that takes over a planned trial
    /// @param model     the model planned through (its plant's parameters)
    /// @param modelFit  the model's position RMS over its data [m] (negative: unknown)
    /// @param data      what the model was identified from (the refits add trials to it;
    ///                  empty: never refit)
    /// @param startLaw  the feedback law that drives a trial not planned through from its start
    /// @param noModel   why there is no model, when there is none (identification's refusal;
    ///                  modelFit is then NaN): the trial note says it
    MpcController(core::TrackingProblem problem, MpcParameters parameters, OracleParameters planner,
                  std::unique_ptr<core::Controller> fallback, PlantParameters model,
                  double modelFit, std::vector<core::Demonstration> data,
                  std::unique_ptr<core::Controller> startLaw, QString noModel = {});
    MpcController(const MpcController& other);
    MpcController& operator=(const MpcController&) = delete;

    QString name() const override { return QStringLiteral("mpc"); }
    void reset(core::ResetMode mode = core::ResetMode::Cold) override;
    const core::ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) override;
    /// "planned through the model" (with when the law parked it and the approach pushed it on)
    /// or "fell back to the feedback law ...: why" (with when).
    QString trialNote() const override;
    std::unique_ptr<core::Controller> clone() const override;
    void setLoopLatencySteps(int steps) override;

    MpcMode mode() const { return mode_; }
    /// Why the fallback took over (empty while planning).
    const QString& fallbackReason() const { return fallbackReason_; }
    /// The step of this trial the feedback law took over at, as a fallback or to park (-1: it
    /// did not).
    int fallbackStep() const { return fallbackStep_; }
    const PlantParameters& model() const { return model_; }
    double modelFit() const { return modelFit_; }
    int refits() const { return refits_; }
    /// This trial's correction of the model's rolling resistance so far (rollingBiasGain).
    double rollingCorrection() const { return rollingBias_; }
    const MpcParameters& parameters() const { return parameters_; }
    /// The demonstration's largest sideways speed [m/s] (planSlide's measure).
    double demonstrationSlide() const { return demonstrationSlide_; }
    /// The demonstration's step its turn begins at: the plan's corrections are bounded by
    /// straightCorrection before it.
    int turnStart() const { return turnStart_; }
    /// The model's steering offset this trial (steeringBiasGain), share of full lock.
    double steeringBias() const { return steeringBias_; }
    /// What this day's finished trials gave the plan and the start law (planTrust's choice).
    const MpcDayRecord& dayRecord() const { return day_; }

  private:
    void buildModel();
    /// Hands the planner its models: the model plant and the other grips.
    void attachModels();
    /// The model's plants (the model, the tube's scratch, the other grips) for `parameters`.
    void makeModels(const PlantParameters& parameters);
    /// The model's plants with `bias` added to its rolling resistance.
    void applyRollingBias(double bias);
    /// The steering offset (steeringBiasGain) from the tube's prediction.
    void correctSteering(const Eigen::VectorXd& predicted, const Eigen::VectorXd& observation);
    void applySteeringBias();
    /// The rolling-resistance correction (rollingBiasGain) from the tube's prediction.
    void correctRolling(const Eigen::VectorXd& predicted, const Eigen::VectorXd& observation);
    void fallBack(const QString& reason);
    /// The model at recorded step `from`'s observation with the commands before it in flight,
    /// stepped through `count` commands sent from step `from - latency` on.
    void predictInto(Plant& model, int from, int count) const;
    void refitOnLastTrial();
    /// Adds the trial just finished to the day's record (planTrust).
    void recordLastTrial();
    /// Why the day's record sends this trial to the start law (planTrust), or empty.
    QString dayPrefersStartLaw() const;
    /// Why the day's record sends a trial not planned through to the fallback law instead of
    /// the start law (lawChoice), or empty.
    QString dayPrefersFallbackLaw() const;
    int tubeSteps() const;
    /// The throttle that carries the parking car on to the lot (parkingApproach), or NaN where
    /// the feedback law's is kept: the car's coast already ends there, or it is past the lot.
    /// `law`: the feedback law's throttle this step. Only with a throttle (`throttle_` >= 0).
    double approachThrottle(double law);
    /// The spin guard's verdict on a measured state: empty, or why it is a spin.
    QString spinOf(const Eigen::VectorXd& observation) const;

    core::TrackingProblem problem_;
    MpcParameters parameters_;
    OracleParameters plannerParameters_;
    std::unique_ptr<core::Controller> fallback_;
    std::unique_ptr<core::Controller> startLaw_;
    PlantParameters firstModel_;
    double firstFit_;
    PlantParameters model_;
    double modelFit_;
    std::vector<core::Demonstration> data_;  // the demonstration first, then the day's trials
    std::vector<core::Demonstration> firstData_;
    QString noModel_;                               // why there is no model (empty: there is one)
    std::unique_ptr<Plant> modelPlant_;             // the model at the current (predicted) state
    std::unique_ptr<Plant> scratch_;                // the tube's prediction
    std::vector<std::unique_ptr<Plant>> ensemble_;  // the model with other grips
    std::unique_ptr<OracleController> planner_;
    int latency_ = 0;
    int pendingLatency_ = 0;
    std::vector<Eigen::VectorXd> observations_;  // this trial's, one per step
    std::vector<Eigen::VectorXd> actions_;       // this trial's commands, one per step
    MpcMode mode_ = MpcMode::Planning;
    QString fallbackReason_;
    int fallbackStep_ = -1;
    int strikes_ = 0;
    int spinStrikes_ = 0;
    double steeringBias_ = 0.0;  // the model's steering offset (steeringBiasGain)
    double wheelbase_ = 0.0;     // the model's, for the steering correction
    double steeringLock_ = 0.0;  // the model's full-lock wheel angle [rad]
    int spinUntil_ = 0;          // the demonstration's step of fastest turn: the guard's last
    int turnStart_ = 0;          // the demonstration's first step of that turn: the straight's end
    double demonstrationSlide_ = std::numeric_limits<double>::infinity();  // see planSlide
    int refits_ = 0;
    int step_ = 0;
    double rollingBias_ = 0.0;       // the estimated extra rolling resistance [1] (this trial's)
    double appliedBias_ = 0.0;       // ... as the model's plants have it
    int throttle_ = -1;              // the throttle's action index (-1: none; no approach)
    double arrival_ = 0.0;           // the demonstration's direction of travel into the lot: +1, -1
    double approachIntegral_ = 0.0;  // the approach's integral term (this trial's)
    bool approaching_ = false;       // the approach pushes the car on (this trial's)
    int approachStep_ = -1;          // the step it first did (-1: it did not)
    double demonstrationCoast_ = 0.0;       // the demonstration's coast into the lot [m/s^2]
    double demonstrationCoastSpeed_ = 0.0;  // ... at this mean speed [m/s]
    MpcDayRecord day_;                      // the day's finished trials (planTrust)
    bool fallbackLawDrives_ = false;        // this trial not planned through is PD+LSD's
    core::ControlStep record_;
};

/// The largest sideways speed [m/s] of a demonstration (`planSlide`'s measure); infinity for a
/// plant without body velocities (no gate).
double largestSidewaysSpeed(const core::Demonstration& demonstration,
                            const std::optional<core::BodyVelocityIndices>& velocity);

/// Whether `mpc` plans through a model for this demonstration: it slides at least `planSlide`
/// (the controller, its factory and the rig's pre-trial check ask this one question).
bool slideWorthPlanning(const core::Demonstration& demonstration,
                        const std::optional<core::BodyVelocityIndices>& velocity,
                        const MpcParameters& parameters);

/// The settings identification runs with for `mpc` (its model's substeps, its budget).
IdentificationSettings mpcIdentificationSettings(const MpcParameters& parameters, bool refit);

/// `mpc`'s model from its data (the demonstration): the quick search, and when that fits worse
/// than `poorFit` a thorough one from the same prior (retryEvaluations), the better kept.
/// `cancelled` (optional), asked now and then, stops it: the result says it was cancelled.
IdentificationResult identifyForMpc(const std::vector<core::Demonstration>& data,
                                    const PlantParameters& prior, const MpcParameters& parameters,
                                    const std::function<bool()>& cancelled = {});

}  // namespace prisca::sim
