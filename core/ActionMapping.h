#pragma once

#include "Demonstration.h"
#include "DeviationModel.h"

#include <Eigen/Core>

#include <QString>
#include <QStringList>

#include <optional>
#include <utility>
#include <vector>

namespace prisca::core {

/// The intuitive action mapping B~ (eq. 6, 7): an m x n matrix of signs in {-1, 0, +1};
/// row l says which state components control l moves, and in which direction
/// ("steer left to turn left").
struct IntuitiveMapping {
    Eigen::MatrixXi signs;  ///< m x n, entries -1, 0 or +1

    int controls() const { return static_cast<int>(signs.rows()); }  ///< m
    int states() const { return static_cast<int>(signs.cols()); }    ///< n

    /// Parses "r0c0,r0c1,...;r1c0,..." (rows = controls separated by ';', entries by ',').
    /// Accepts -1, 0, 1 and +1, spaces allowed. On failure returns nullopt and sets *error
    /// (naming the row and column).
    static std::optional<IntuitiveMapping> parse(const QString& text, QString* error);
    /// The text form accepted by parse().
    QString toString() const;
    /// B~ as a real matrix.
    Eigen::MatrixXd asDouble() const { return signs.cast<double>(); }
};

/// Options of the B_v regression (eq. 8).
struct ActionMappingFitOptions {
    /// What the change of action du_k = u_k - u_{k-1} is regressed against.
    enum class Target {
        /// ds_{k+1} = s_{k+1} - s_k, eq. 8 read literally (docs/architecture.md). Consistent only
        /// for
        /// plants whose state is proportional to the action.
        StateChange,
        /// ds_{k+1} - ds_k, the change of the one-step state change. For a plant
        /// s_{k+1} = s_k + f(s_k) dt + B dt u_k (eq. 5's model) this equals B dt du_k up to a
        /// term of order dt^2, so B is recovered; the literal reading pairs a quantity driven by
        /// u_k with one driven by its change and fits about zero on a smooth demonstration.
        RateChange
    };
    Target target = Target::RateChange;
    /// Latency shift d [steps] >= 0: pairs ds_{k+1+d} with du_k.
    int latency = 0;
    /// Response horizon R >= 1 [steps] of the RateChange target: how far the state moves over R
    /// steps beyond where its last step was taking it, (s_{k+R} - s_k) - R (s_k - s_{k-1}), so
    /// effects that build up over a few steps (a yaw rate turning into heading, then into lateral
    /// position) are seen. R = 1 is the change of the one-step change; R about H matches the
    /// window PRISCA's cost covers.
    int responseSteps = 1;
    /// eq. 5 in full: with the RateChange target and R = 1, regress the change of the one-step
    /// change on the previous one-step change too, d^2 s_{k+1} = A dt ds_k + B dt du_k, so the
    /// state's own drift A is identified alongside B instead of being left in the residual
    /// (where, correlated with du through a closed-loop operator, it biases B). Requires
    /// responseSteps 1 and the RateChange target.
    bool drift = false;
    /// Constrain B_v >= 0, so B keeps the signs of B~ (B~ says which way, B_v how much). An
    /// entry the data would make negative is reported as a sign conflict and set to 0.
    bool nonNegative = true;
    /// Robust regression (iteratively reweighted least squares, Tukey's bisquare on residuals
    /// scaled by their median absolute deviation): samples the linear model cannot explain, such
    /// as a car sliding on saturated tyres, stop dominating the fit of the samples it can.
    bool robust = true;
    /// A channel whose weighted mean square du is below this is reported as never excited.
    double excitationThreshold = 1e-12;
};

/// The fitted action mapping and its diagnostics.
struct ActionMappingFit {
    Eigen::MatrixXd bv;  ///< B_v, m x n (0 where B~ is 0 or the channel was never excited)
    Eigen::MatrixXd b;   ///< B = B_v (.) B~, m x n [state unit / (action unit * s)]
    /// A (n x n) of eq. 5, row c: how the one-step change of state c follows the previous
    /// one-step change of every state [1/s]; zero unless options.drift.
    Eigen::MatrixXd a;
    /// The B_v the data would give without the B_v >= 0 constraint (m x n), for the operator to
    /// see what a sign conflict's zero replaced.
    Eigen::MatrixXd unconstrainedBv;
    Eigen::VectorXd residualRms;   ///< per state component: weighted RMS of ds - B^T dt du
    Eigen::VectorXd rSquared;      ///< per state component; NaN where no control acts on it
    Eigen::VectorXd outlierShare;  ///< per state: share of samples the robust fit set aside
    /// (control, state) where the unconstrained fit of B_v is negative: the data contradicts B~.
    std::vector<std::pair<int, int>> signConflicts;
    std::vector<int> unexcitedChannels;  ///< controls that never changed
    int samples = 0;                     ///< number of (ds, du) pairs used
    /// Per demonstration sample (size T): whether the linear model explains it, i.e. the robust
    /// fit kept it for every modelled state (true everywhere without the robust fit, and at
    /// the few first and last samples no pair covers).
    std::vector<bool> explained;
    QStringList warnings;  ///< one line each, in the operator's words
};

/// The largest |B| fitActionMapping accepts [state unit / (action unit * s)]: the plants' B are
/// of order 1 to 100; 10^6 means the fit divided by action changes that are not there.
inline constexpr double kMaxAbsB = 1e6;

/// Fits B_v (eq. 8): minimises sum_k w_k || y_{k+1+d} - (B_v (.) B~)^T dt du_k ||^2 with the
/// nested-expectation weights w of E_{i=0:T} E_{j=i:T}, du_k = u_k - u_{k-1}, and y the state
/// change chosen by options.target. State changes are expressed by the deviation model (a
/// planar vehicle's displacement is measured in its own frame at the earlier sample). The problem
/// separates into one weighted least-squares problem per state component in the non-zero entries of
/// that column of B~. Throws std::invalid_argument on inconsistent dimensions, a demonstration
/// too short for the latency, or a fit that is not finite or beyond kMaxAbsB.
ActionMappingFit fitActionMapping(const Demonstration& demonstration,
                                  const IntuitiveMapping& mapping, const DeviationModel& deviation,
                                  const ActionMappingFitOptions& options = {});

}  // namespace prisca::core
