#pragma once

#include "DeviationModel.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <array>
#include <vector>

namespace prisca::core {

/// The standard normal distribution's quantile: z with P(Z <= z) = p, for p in (0, 1). A
/// rational approximation (relative error about 1e-9) refined by one Newton step on erfc, so
/// accurate to about 1e-12. Throws std::invalid_argument outside (0, 1).
double normalQuantile(double p);

/// The chi-square distribution's quantile for `dof` >= 1 degrees of freedom at probability p in
/// (0, 1), by the Wilson-Hilferty cube-root normal approximation
///     q = k (1 - 2/(9k) + z_p sqrt(2/(9k)))^3,  z_p = normalQuantile(p),  k = dof,
/// (relative error under 1e-4 at the 2.5% and 97.5% points for k >= 100, where the consistency
/// checks use it; in the far upper tail at few degrees of freedom it is a little high, 1.7% at
/// k = 3 and 1% at k = 6 for p = 0.999, so a gate built on it sets aside slightly fewer samples
/// than its nominal share). Throws std::invalid_argument for dof < 1 or p outside (0, 1).
double chiSquareQuantile(double p, int dof);

/// How a PoseFilter sees one planar body. Units are SI: m, rad, s.
///
/// The filter's six components are, in this order, the world pose and the body-frame velocities:
/// x [m], y [m], psi [rad], vx [m/s] (forward), vy [m/s] (left), r [rad/s]; they sit in the
/// plant's state vector at `pose` and `velocity`. Any other state component passes through from
/// the newest measurement unchanged.
struct PoseFilterParameters {
    int stateDimension = 6;        ///< n of the plant's state vector (>= 6)
    PlanarPoseIndices pose;        ///< where x, y, psi sit in the state vector
    BodyVelocityIndices velocity;  ///< where vx, vy, r sit in the state vector
    /// The state components a measurement carries (plant-state indices, each one of the six
    /// above, no repeats, at least one). Full state (the simulation): all six. Pose only (the
    /// ceiling camera): pose.x, pose.y, pose.heading.
    std::vector<int> measured = {0, 1, 2, 3, 4, 5};
    /// Standard deviation of each state component's measurement noise (size stateDimension, in
    /// the component's unit; only the measured ones are read, each must be > 0). Default: a
    /// ceiling camera at 40 Hz (5 mm, 5 mm, 0.01 rad; 0.03 m/s, 0.03 m/s, 0.05 rad/s).
    Eigen::VectorXd measurementStd =
        (Eigen::VectorXd(6) << 0.005, 0.005, 0.01, 0.03, 0.03, 0.05).finished();
    /// Spectral densities of the white accelerations that drive the body velocities as random
    /// walks: forward and lateral [m^2/s^3], yaw [rad^2/s^3]. A velocity's change over dt then
    /// has variance density * dt. Default: a 1:10 car whose largest acceleration over one 25 ms
    /// step (4 m/s^2 forward, 6 m/s^2 sideways in a slide, 25 rad/s^2 of yaw) is one standard
    /// deviation: density = a^2 dt.
    Eigen::Vector3d accelerationDensity{0.4, 0.9, 15.6};
    /// The control period dt of step() [s] (> 0). The time-stamped calls ignore it.
    double controlPeriod = 0.025;
    /// How many control steps old a measurement is when step() receives it (>= 0): step()
    /// returns the estimate predicted that many steps ahead, to now, through the actions
    /// commanded since.
    int loopLatencySteps = 0;
    /// Spectral densities of white jerks that drive body accelerations (ax, ay, ar) as random
    /// walks: forward and lateral [m^2/s^5], yaw [rad^2/s^5]. Zero (the default): no
    /// acceleration states, the velocities are pure random walks. Positive: the filter also
    /// estimates each velocity's trend (a constant-acceleration model per body axis: v' = v + a
    /// tau, the pose along the arc at the span's mid velocity) and so predicts the velocities, not
    /// only the pose, across the latency. A manoeuvre whose body velocities keep changing over
    /// the latency (a car yawing into a slide: its body-frame velocity turns with the frame)
    /// needs it; without it the estimate of now pairs the pose of now with the velocity of then.
    Eigen::Vector3d jerkDensity = Eigen::Vector3d::Zero();
    /// Standard deviation of the accelerations at (re-)initialisation (with jerkDensity only):
    /// forward, lateral [m/s^2], yaw [rad/s^2]. Default 5, 5, 20.
    Eigen::Vector3d initialAccelerationStd{5.0, 5.0, 20.0};
    /// Optional input term G (3 x m; empty: none): the body accelerations [vx, vy, r] per unit of
    /// action. The velocity random walk is taken as balanced (zero mean acceleration) under the
    /// action in force when the estimate being propagated was last measured, u_ref; an action
    /// u that differs from it adds dv = dt G (u - u_ref) over each step it is in force. Since a
    /// measurement already carries the acceleration of the action in force when it was taken,
    /// only the action changes since matter, and they are what the demonstration's fit
    /// (fitActionMapping, RateChange target) identifies: its B (m x n) maps an action change to
    /// the change of the state's rate, so G = the transposed velocity columns of B
    /// (inputGainFromFit). No plant knowledge; zero leaves the velocities a pure random walk.
    Eigen::MatrixXd inputGain;
    /// Chi-square gate on the innovation's squared Mahalanobis distance: a measurement beyond the
    /// gateProbability quantile for its dimension is set aside (predict only) and counted. 1 or
    /// more: no gate. Default 0.999 (a consistent filter sets aside one sample in a thousand).
    double gateProbability = 0.999;
    /// After this many consecutive set-aside measurements the filter re-initialises from the
    /// newest one (>= 1): a genuine jump (the car was carried, the tracker locked anew) is
    /// believed after this long. Default 5 (125 ms at 40 Hz).
    int reinitialiseAfter = 5;
    /// Standard deviation of each of the six components (x, y, psi, vx, vy, r order) at
    /// (re-)initialisation where the measurement does not carry it; the unmeasured estimate
    /// starts at 0. Default 1 m, 1 m, pi rad, 2 m/s, 2 m/s, 5 rad/s.
    Eigen::Matrix<double, 6, 1> initialStd =
        (Eigen::Matrix<double, 6, 1>() << 1.0, 1.0, kPi, 2.0, 2.0, 5.0).finished();
    /// Largest span [s] the filter predicts across (a longer silence restarts it from the next
    /// measurement; predictTo() clamps to it). Default 1 s.
    double maxPredictionSpan = 1.0;

    /// The six plant-state indices in the filter's order (x, y, psi, vx, vy, r).
    std::array<int, 6> componentIndices() const;
    /// Throws std::invalid_argument naming the first bad field (dimension, index, std, density,
    /// period, latency, gain shape, gate, count).
    void validate() const;

    /// Only the pose (x, y, heading) measured, as from a ceiling camera.
    void measurePoseOnly() { measured = {pose.x, pose.y, pose.heading}; }
    /// The whole pose and velocity measured.
    void measureFullState() {
        measured = {pose.x,           pose.y,           pose.heading,
                    velocity.forward, velocity.lateral, velocity.yawRate};
    }
};

/// G (3 x m) of PoseFilterParameters::inputGain from the fit's B (m x n): the velocity columns
/// of B, transposed. Throws std::invalid_argument when an index is beyond B's columns.
Eigen::MatrixXd inputGainFromFit(const Eigen::MatrixXd& b, const BodyVelocityIndices& velocity);

/// The acceleration densities of PoseFilterParameters from a demonstration's states (T x n)
/// sampled every dt: the 99th percentile of each body velocity's per-step change |dv| is taken
/// as one standard deviation of the random walk, density = dv^2 / dt, never below `floor`. The
/// filter is then as ready for the demonstration's sharpest manoeuvres (a slide's onset) as for
/// its calm parts. Throws std::invalid_argument for fewer than 3 samples, a bad index or dt <= 0.
Eigen::Vector3d accelerationDensityFromStates(const Eigen::MatrixXd& states,
                                              const BodyVelocityIndices& velocity, double dt,
                                              double floor = 1e-4);

/// The jerk densities of PoseFilterParameters from a demonstration's states (T x n) sampled
/// every dt, by the same rule one derivative up: the 99th percentile of each body velocity's
/// per-step change of its per-step change, |dv_{k+1} - dv_k| / dt, is one standard deviation of
/// the acceleration's change per step, density = (that / dt)^2 dt, never below `floor`.
/// Throws std::invalid_argument for fewer than 4 samples, a bad index or dt <= 0.
Eigen::Vector3d jerkDensityFromStates(const Eigen::MatrixXd& states,
                                      const BodyVelocityIndices& velocity, double dt,
                                      double floor = 1e-4);

/// What the last measurement did.
struct PoseFilterStatus {
    bool initialised = false;     ///< the filter holds an estimate
    bool predictedOnly = false;   ///< the last step had no measurement (dropped): predict only
    bool gated = false;           ///< the last measurement was set aside by the gate
    bool reinitialised = false;   ///< the last measurement re-initialised the filter
    double nis = 0.0;             ///< its normalised innovation squared (0 if none)
    int innovationDimension = 0;  ///< the number of measured components
};

/// An extended Kalman filter over a planar body's pose and body-frame velocities
/// (docs/architecture.md "Pose filter").
///
/// Process: over a span tau with body velocities v = (vx, vy) and yaw rate r held, the pose moves
/// exactly along the arc, psi' = psi + r tau, p' = p + R(psi) [S -C; C S] v with
/// S = sin(r tau) / r, C = (1 - cos(r tau)) / r (their limits as r tau -> 0), heading wrapped to
/// (-pi, pi]; velocities are random walks driven by white accelerations (densities
/// accelerationDensity; the discrete noise is the exact constant-velocity one per body axis,
/// rotated into the world) plus the optional input term. With jerkDensity the state also holds
/// the body accelerations (random walks driven by white jerk; nine components inside, the six
/// above handed out): the velocities integrate them and the pose follows the arc at the span's
/// mid velocities. Measurement: the measured components with their noise, heading innovation
/// wrapped, Joseph-form update; gated by chi-square.
///
/// Latency: the filter keeps the estimate at the time of the newest measurement (the lagged
/// estimate) and the actions commanded since, and hands out that estimate predicted to now.
/// Two ways to drive it, not to be mixed in one trial:
/// - by control steps (simulation): step(observation, dropped) then commanded(action), once per
///   control step; the observation is loopLatencySteps steps old;
/// - by time stamps (the rig): update(observation, takenAt) per received measurement (none for a
///   dropped frame), commandedAt(action, from) per command, predictTo(now) for the estimate.
/// Every call after construction is allocation-free (fixed-size matrices, a preallocated action
/// ring of kActionCapacity entries). Single-threaded; one instance per trial.
class PoseFilter {
  public:
    using Vector6 = Eigen::Matrix<double, 6, 1>;
    using Matrix6 = Eigen::Matrix<double, 6, 6>;
    /// Actions remembered (the newest ones); a prediction spanning more reuses the oldest known.
    static constexpr int kActionCapacity = 256;

    /// Throws std::invalid_argument (PoseFilterParameters::validate, and an action dimension
    /// m = inputGain.cols() if set, else `actionDimension`).
    explicit PoseFilter(PoseFilterParameters parameters, int actionDimension = 2);

    /// Forgets the estimate, the actions and the counters.
    void reset();

    /// One control step: the observation (size n) of loopLatencySteps steps ago, or a repeat of an
    /// old one if `dropped` (then predict only). Returns the estimate predicted to now (size n; the
    /// reference stays valid until the next call). The first call initialises from the
    /// observation even if flagged dropped. Throws std::invalid_argument for a wrong size or a
    /// non-finite measured component (the filter is left as it was).
    const Eigen::VectorXd& step(const Eigen::Ref<const Eigen::VectorXd>& observation,
                                bool dropped = false);
    /// The action (size m) applied from now over the next control period; once after each step().
    void commanded(const Eigen::Ref<const Eigen::VectorXd>& action);

    /// A measurement (size n) taken at `takenAt` [s, any steady clock]. Not earlier than the
    /// previous one (std::invalid_argument otherwise, and for a wrong size or a non-finite
    /// measured component).
    void update(const Eigen::Ref<const Eigen::VectorXd>& observation, double takenAt);
    /// The action (size m) in force from time `from` [s] on (non-decreasing times).
    void commandedAt(const Eigen::Ref<const Eigen::VectorXd>& action, double from);
    /// The estimate (size n) at time `now` [s], predicted from the newest measurement through
    /// the actions since (a span over maxPredictionSpan is clamped to it). Before any
    /// measurement: std::logic_error. Also fills nowCovariance().
    const Eigen::VectorXd& predictTo(double now);

    /// The estimate at the newest measurement's time (six components, filter order), its
    /// covariance and that time [s].
    const Vector6& laggedEstimate() const { return lagged6_; }
    const Matrix6& laggedCovariance() const { return laggedP6_; }
    double laggedTime() const { return time_; }
    /// The six components of the latest estimate handed out, and their covariance.
    const Vector6& nowEstimate() const { return now6_; }
    const Matrix6& nowCovariance() const { return nowP6_; }
    /// The body accelerations (ax, ay, ar) of the latest estimate handed out (zero without
    /// jerkDensity).
    Eigen::Vector3d nowAcceleration() const { return xNow_.tail<3>(); }

    const PoseFilterStatus& status() const { return status_; }
    int gatedCount() const { return gatedCount_; }  ///< measurements set aside so far
    int reinitialisations() const { return reinitialisations_; }
    int predictOnlyCount() const { return predictOnlyCount_; }  ///< steps with no measurement
    const PoseFilterParameters& parameters() const { return parameters_; }
    int actionDimension() const { return actionDimension_; }  ///< m
    /// The gate's squared-distance threshold for this filter's measurement.
    double gateThreshold() const { return gate_; }

    /// The process model over `tau` [s] with no input: the propagated six components, and if `f`
    /// is given its Jacobian. Heading wrapped.
    static Vector6 propagate(const Vector6& x, double tau, Matrix6* f = nullptr);
    /// The discrete process noise over `tau` at state x for the given densities.
    static Matrix6 processNoise(const Vector6& x, double tau, const Eigen::Vector3d& density);

  private:
    using Vector9 = Eigen::Matrix<double, 9, 1>;
    using Matrix9 = Eigen::Matrix<double, 9, 9>;
    /// The model with the acceleration states (x, y, psi, vx, vy, r, ax, ay, ar).
    static Vector9 propagateFull(const Vector9& x, double tau, Matrix9* f);
    static Matrix9 processNoiseFull(const Vector9& x, double tau, const Eigen::Vector3d& density,
                                    const Eigen::Vector3d& jerk);
    using MeasurementVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
    using MeasurementMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
    using GainMatrix = Eigen::Matrix<double, 9, Eigen::Dynamic, 0, 9, 6>;

    void checkObservation(const Eigen::Ref<const Eigen::VectorXd>& observation) const;
    void initialise(const Eigen::Ref<const Eigen::VectorXd>& observation, double takenAt);
    void measure(const Eigen::Ref<const Eigen::VectorXd>& observation);
    /// Propagates (x, p) from t0 to t1 through the actions in force, relative to `reference`.
    void predictSpan(Vector9& x, Matrix9& p, double t0, double t1) const;
    /// The newest action starting no later than t (+ a tolerance); -1 if none.
    int actionInForce(double t) const;
    int slot(int age) const;  ///< ring slot of the action `age` places back from the newest
    void writeOutput(const Vector9& x);
    void refreshViews();  ///< the six-component views of the lagged and now estimates

    PoseFilterParameters parameters_;
    std::array<int, 6> index_{};
    std::array<int, 6> measuredComponent_{};  ///< filter component of measurement row i
    int measuredCount_ = 0;
    bool headingMeasured_ = false;
    double gate_ = 0.0;
    int actionDimension_ = 0;

    Vector9 x_ = Vector9::Zero();
    Matrix9 p_ = Matrix9::Identity();
    double time_ = 0.0;
    Vector9 xNow_ = Vector9::Zero();
    Matrix9 pNow_ = Matrix9::Identity();
    Vector6 lagged6_ = Vector6::Zero();
    Matrix6 laggedP6_ = Matrix6::Identity();
    Vector6 now6_ = Vector6::Zero();
    Matrix6 nowP6_ = Matrix6::Identity();
    Eigen::VectorXd output_;      ///< n, pass-through components from the newest measurement
    double headingBranch_ = 0.0;  ///< the newest measured heading, unwrapped as the plant has it
    Eigen::VectorXd reference_;   ///< u_ref, m
    bool haveReference_ = false;
    Eigen::MatrixXd actions_;  ///< m x kActionCapacity ring
    std::vector<double> actionTimes_;
    int actionHead_ = -1;  ///< slot of the newest action
    int actionCount_ = 0;
    mutable Eigen::VectorXd scratch_;  ///< m, the action difference

    PoseFilterStatus status_;
    int consecutiveGated_ = 0;
    int gatedCount_ = 0;
    int reinitialisations_ = 0;
    int predictOnlyCount_ = 0;
    long long stepIndex_ = 0;  ///< control steps taken by step()/commanded()
};

}  // namespace prisca::core
