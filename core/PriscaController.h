#pragma once

#include "Controller.h"
#include "FeatureMap.h"
#include "InverseDepreciation.h"
#include "LeastStateDeviationMatcher.h"
#include "LocalOptimalBaseline.h"
#include "PdFeedback.h"
#include "StepSize.h"

#include <Eigen/Core>

#include <vector>

namespace prisca::core {

/// Tuning of PRISCA (Algorithm 1, inputs 4-6). Plain data.
struct PriscaParameters {
    int horizon = 10;    ///< H, the smoothing horizon [steps] (>= 1)
    double gamma = 0.9;  ///< rate of inverse depreciation in [0, 1] (eq. 10)
    InverseDepreciation::Mode depreciationMode = InverseDepreciation::Mode::RelativeToWindow;
    bool useInverseDepreciation = true;  ///< false: D = 1 (the PGSD special case)
    bool useBaseline = true;             ///< false: b = 0 (the PGSD special case)
    /// Which local baseline (see LocalOptimalBaseline): eq. 15 as printed diverges on a
    /// linear plant, so the unbiased control-variate form is the default.
    LocalOptimalBaseline::Mode baselineMode = LocalOptimalBaseline::Mode::ControlVariate;
    int baselineWindow = 0;  ///< tau' [steps] for eq. 15; 0 means 2H
    StepSize stepSize;       ///< alpha_k (eq. 3)
    bool learning = true;    ///< false: theta stays as set (policy evaluation)
    /// How the gradient of the window's cost with respect to theta is formed.
    enum class Gradient {
        /// eq. 4 truncated to one step, as the paper prints it (eq. 14):
        /// a_j = phi_l(s_j) (e_j^T W dS_l). Summed over a window it is a positive form in e, so
        /// it raises the feedback gains whenever there is error, past the best gain as well.
        OneStep,
        /// eq. 4's chain rule carried over the window through the identified closed loop
        /// e_{t+1} = (I + dt A) e_t + dt B^T (u_{t-d} - u*_{t-d}), u - u* = theta^T phi(e):
        ///     S_{t+1} = (I + dt A) S_t + dt B^T [ E_l phi_l(e_{t-d})^T + K S_{t-d} ],
        /// S = de/dtheta_l reset at the window's start, K the policy's own feedback gain, and
        /// a_t = 2 S_t^T W e_t. A is the fitted drift (setDrift) plus the error's own
        /// kinematics at each sample's reference (DeviationModel::kinematics: for a vehicle,
        /// heading error turns into lateral error at the reference's speed). Once the gains make
        /// the loop ring, the sensitivities change sign
        /// and the update turns round: learning settles without a bound on theta.
        ClosedLoop
    };
    Gradient gradient = Gradient::OneStep;
    /// N [steps] of the one-step form's state effect (OneStep only), >= 1. eq. 5 prints
    /// ds_{k+N}/du_k as sum_{i<N} (I + dt A)^i dt B before truncating it to dt B (N = 1, the
    /// paper's form). With N > 1 the sum is kept, A the fitted drift plus the error's own
    /// kinematics at the reference (DeviationModel::kinematics): a throttle then moves the
    /// position error it will cause, not only the speed error of the next sample, so a feature
    /// of the position error learns a gain at all.
    int effectHorizon = 1;
    /// d [steps]: the measurement's age in the closed-loop model (ClosedLoop only), >= 0.
    int modelDelay = 0;
    /// R per control (m; empty: none): the cost also charges the policy's own effort,
    /// C = e^T W e + (u - u*)^T R (u - u*), as LQR does (ClosedLoop only). Its gradient pulls
    /// every gain back in proportion to how hard it pushes, whatever the model says.
    Eigen::VectorXd effortWeights;
    /// Honour latency compensation (Controller::setLoopLatencySteps): the reference is
    /// matched for the time the observation was taken, the demonstration's action is the one of
    /// now. false: the paper's form, which pairs an old observation with today's reference.
    bool honourLoopLatency = true;
    /// If > 0, theta is projected onto the box |theta_i| <= thetaBound after each update
    /// (projected subgradient descent, which keeps the convergence argument of Theorem 4.4 on a
    /// compact set) so an unlucky run of errors cannot carry the policy into an unstable loop.
    double thetaBound = 0.0;
    /// A feedback the policy starts from (empty gains: none): u = u* + prior + theta^T phi,
    /// the prior being the PD law of PdController (combined error, its H-step nested
    /// expectation, proportional and derivative gains). PRISCA then learns a correction to a
    /// policy that already holds the robot on the path, instead of building the feedback from
    /// nothing; theta = 0 is that policy.
    PdParameters prior;
};

/// PRISCA as an online controller (Algorithm 1, lines 10-19). Each step:
///   1. match the reference j_k (eq. 12, or by time) and form e_k = s_k (-) s*_{j_k};
///   2. a_k = phi_l(s_k) (e_k^T W dS_l) per channel, dS_l = dt B[l, :] (eq. 4-6, 14);
///   3. A_k = sum_j w_j a_j and G_k = sum_j w_j a_j D_j over the H-step window (eq. 13, 14);
///   4. b from the last tau' pairs (A, G) (eq. 15) and g = G_k - b (.) A_k, or the unbiased
///      control-variate form (LocalOptimalBaseline explains the choice);
///   5. theta -= alpha_k g (eq. 2, 3);
///   6. u_k = theta^T phi(s_k) + u*_{j_k} per channel, saturated (line 18).
/// step() does not allocate. Single-threaded; clone() for parallel trials.
class PriscaController : public Controller {
  public:
    /// @param problem        demonstration, deviation model, matching, cost weights, limits
    /// @param features       phi_l for each of the m channels
    /// @param actionMapping  B (m x n): B_v (.) B~ for PRISCA, B~ itself for a sign-only model
    PriscaController(TrackingProblem problem, FeatureMap features, Eigen::MatrixXd actionMapping,
                     PriscaParameters parameters, QString name = QStringLiteral("prisca"));

    QString name() const override { return name_; }
    void reset(ResetMode mode = ResetMode::Cold) override;
    const ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) override;
    std::unique_ptr<Controller> clone() const override;
    const Eigen::MatrixXd* learnedParameters() const override { return &theta_; }
    void setLoopLatencySteps(int steps) override;

    /// theta (p x m), column l = theta_l.
    const Eigen::MatrixXd& theta() const { return theta_; }
    /// Replaces theta (p x m), e.g. to evaluate a fixed policy or to warm start from a session.
    void setTheta(const Eigen::MatrixXd& theta);
    /// The theta a cold reset returns to (zero unless set), e.g. a fixed policy found offline.
    /// Also sets the current theta.
    void setInitialTheta(const Eigen::MatrixXd& theta);
    /// Where along the demonstration the model holds (one flag per sample, e.g. the samples a
    /// robust fit explained): the closed-loop gradient learns only from errors at references
    /// the model explains, and its sensitivities start afresh after one it does not (a car
    /// sliding on saturated tyres answers its controls otherwise). Empty: everywhere.
    void setModelValidity(std::vector<bool> valid);
    /// Per demonstration sample, the share of the prior's feedback acting at that reference
    /// (PdFeedback::setReferenceGate).
    void setPriorGate(std::vector<double> gate) { prior_.setReferenceGate(std::move(gate)); }
    /// Per demonstration sample, a factor on each error component the prior sees
    /// (PdFeedback::setErrorSchedule).
    void setPriorErrorSchedule(Eigen::MatrixXd schedule) {
        prior_.setErrorSchedule(std::move(schedule));
    }
    /// The identified drift A (n x n, eq. 5) the closed-loop gradient propagates through; zero
    /// (no drift, the state moves only as the actions push it) unless set.
    void setDrift(const Eigen::MatrixXd& a);
    /// g of the last step (p x m).
    const Eigen::MatrixXd& gradient() const { return gradient_; }
    /// b of the last step (p x m); zero when the baseline is off.
    const Eigen::MatrixXd& baseline() const { return baseline_.value(); }
    /// Phi of the last step (p x m).
    const Eigen::MatrixXd& features() const { return phi_; }
    /// alpha_k of the last step.
    double stepSize() const { return alpha_; }
    /// D of the samples of the last window, oldest first (size min(k, H) + 1).
    const Eigen::VectorXd& depreciation() const { return depreciationOfWindow_; }
    /// dS (m x n): row l is the state effect dt B[l, :] of control l.
    const Eigen::MatrixXd& stateEffect() const { return stateEffect_; }
    const PriscaParameters& parameters() const { return parameters_; }
    /// Steps taken since the last cold reset (the k of alpha_k).
    int learningSteps() const { return learningStep_; }

  private:
    void closedLoopTerms(int k, int count);
    /// Adds a step's curvature, averaged over `parameters` of theta.
    void addCurvature(double curvature, double parameters);
    /// What holding each control for `steps` steps from reference sample j does to the error.
    void heldEffect(int j, int steps);
    /// stepTransition_ = I + dt (A + the error's own kinematics at demonstration sample j).
    void transitionAt(int j);

    TrackingProblem problem_;
    FeatureMap featureMap_;
    PriscaParameters parameters_;
    QString name_;
    LeastStateDeviationMatcher matcher_;
    LocalOptimalBaseline baseline_;
    InverseDepreciation depreciation_;

    Eigen::MatrixXd referenceStates_;             // n x T
    Eigen::MatrixXd referenceActions_;            // m x T
    Eigen::MatrixXd stateEffect_;                 // m x n, dt * B
    Eigen::MatrixXd transition_;                  // n x n, I + dt A (the fitted drift)
    Eigen::MatrixXd stepTransition_;              // n x n, with the error's own kinematics at t
    Eigen::MatrixXd effectTerm_;                  // n x m scratch: (I + dt A)^i dt B^T
    Eigen::MatrixXd effectSum_;                   // n x m scratch: their sum over N steps
    Eigen::MatrixXd effectNext_;                  // n x m scratch
    PdFeedback prior_;                            // the PD law the policy starts from
    std::vector<int> referenceHistory_;           // ring of j_t, as errorHistory_
    std::vector<bool> modelValid_;                // per demonstration sample (empty: all)
    Eigen::MatrixXd errorHistory_;                // n x (H+1+d) ring of e_j
    Eigen::MatrixXd featureHistory_;              // (p*m) x (H+1+d) ring of Phi_j
    std::vector<Eigen::MatrixXd> sensitivity_;    // [t]: S_t, n x (p*m), over the window
    Eigen::MatrixXd feedbackGain_;                // m x n, K = d(theta^T phi)/de
    Eigen::MatrixXd drive_;                       // n x (p*m) scratch
    Eigen::VectorXd sample_;                      // (p*m) scratch: a_t
    Eigen::MatrixXd actionSensitivity_;           // m x (p*m) scratch: du_t/dtheta
    Eigen::VectorXd effort_;                      // m scratch: R (u_t - u*_t)
    std::vector<Eigen::VectorXd> windowWeights_;  // [c - 1]: nested weights of c samples

    Eigen::MatrixXd theta_;
    Eigen::MatrixXd feedbackMask_;   // p x m: 1 where a term is charged as effort (not a phase)
    bool hasPhases_ = false;         // any Phase term in the feature map
    Eigen::ArrayXXd moved_;          // 1 x (p*m) scratch: how much each parameter moves the step
    Eigen::MatrixXd initialTheta_;   // what a cold reset returns to
    Eigen::MatrixXd previousTheta_;  // before the last update (restored if it overflowed)
    Eigen::MatrixXd phi_;
    Eigen::MatrixXd gradient_;
    Eigen::MatrixXd smoothedA_;
    Eigen::MatrixXd smoothedG_;
    Eigen::MatrixXd historyA_;  // (p*m) x (H+1) ring of a_j
    Eigen::VectorXd weightedError_;
    Eigen::VectorXd projected_;
    Eigen::VectorXd depreciationOfWindow_;
    ControlStep record_;
    double alpha_ = 0.0;
    double curvatureSum_ = 0.0;  // sum of the steps' curvatures (StepSize::normalised)
    double curvatureSteps_ = 0.0;
    int step_ = 0;              // k within the trial
    int learningStep_ = 0;      // k of alpha_k, kept across warm starts
    int loopLatencySteps_ = 0;  // the sensor latency compensated [steps]
};

}  // namespace prisca::core
