#pragma once

#include <Eigen/Core>

#include <vector>

namespace prisca::core {

/// Gains and variant of the PD baselines (docs/architecture.md "Baselines").
struct PdParameters {
    /// Error combination c_l (m x n): row l weighs the tracking error components for control l;
    /// normally B~ (or B), so that "left of the path" becomes "steer right".
    Eigen::MatrixXd errorCombination;
    Eigen::VectorXd kp;  ///< proportional gain per control (m), >= 0 [action unit / error unit]
    Eigen::VectorXd kd;  ///< derivative gain per control (m), >= 0 [action unit * s / error unit]
    /// Smoothing horizon H [steps] for PD+H; 0 means the raw error (plain PD).
    int horizon = 0;
};

/// The PD law on a tracking error, step by step: the combined error eps = c . e_k, its H-step
/// nested-expectation smoothing (the raw eps for H = 0) and its backward difference over one
/// control period (zero on the first step); the feedback is -Kp eps - Kd d(eps)/dt. Shared by
/// the PD baselines, ILC's feedback and the law PRISCA may start from, so all of them form it
/// alike, bit for bit. update() does not allocate.
class PdFeedback {
  public:
    PdFeedback() = default;
    /// Throws std::invalid_argument unless the combination is m x n, the gains of size m and
    /// the horizon >= 0. dt: the control period [s].
    PdFeedback(PdParameters parameters, int n, int m, double dt);

    /// Back to no history (the next update() is a first step).
    void reset();
    /// Takes the step's tracking error e_k (n) and the reference's demonstration sample (-1:
    /// none; with an error schedule, its column for that sample scales e_k first).
    void update(const Eigen::Ref<const Eigen::VectorXd>& error, int referenceIndex = -1);
    /// action -= g (Kp eps), then action -= g (Kd d(eps)/dt) (in that order), g the gate of
    /// the reference sample (1 without a gate or a reference).
    void apply(Eigen::Ref<Eigen::VectorXd> action, int referenceIndex = -1) const;
    /// Per demonstration sample, the share of the feedback that acts while that sample is the
    /// reference (0 to 1); empty: all of it everywhere.
    void setReferenceGate(std::vector<double> gate) { gate_ = std::move(gate); }
    /// Per demonstration sample (n x T): a factor on each error component while that sample
    /// is the reference, before the combination (e.g. -1 on a vehicle's heading and yaw rate
    /// while the demonstration drives backwards); empty: none. std::invalid_argument unless
    /// it has n rows.
    void setErrorSchedule(Eigen::MatrixXd schedule);

    /// eps of the last update, after smoothing (m).
    const Eigen::VectorXd& signal() const { return signal_; }
    const PdParameters& parameters() const { return parameters_; }

  private:
    PdParameters parameters_;
    double dt_ = 1.0;
    std::vector<Eigen::VectorXd> weights_;  // [c - 1]: nested weights of c samples
    Eigen::MatrixXd raw_;                   // m x (H + 1) ring of c . e
    Eigen::VectorXd signal_;
    Eigen::VectorXd previous_;
    Eigen::VectorXd rate_;
    int step_ = 0;
    std::vector<double> gate_;
    Eigen::MatrixXd schedule_;   // n x T, or empty
    Eigen::VectorXd scheduled_;  // n scratch
};

}  // namespace prisca::core
