#pragma once

#include <Eigen/Core>

namespace prisca::core {

/// The local optimal baseline, the paper's variance reducer (eq. 15), per parameter entry:
///
///     b = 2 E_tau'[G (.) A] / (E_tau'[A (.) A] + E_tau'[A] (.) E_tau'[A])
///
/// where A_k = E_i E_j a_j and G_k = E_i E_j a_j D_j are the smoothed gradient terms of the
/// last tau' steps (tau' = 2H in the paper), and b = 0 wherever the denominator is zero.
/// Not thread-safe; one instance per controller.
class LocalOptimalBaseline {
public:
    /// @param rows, cols  shape of A and G (p x m)
    /// @param window      tau' >= 1 [steps]
    LocalOptimalBaseline(int rows, int cols, int window);

    /// Forgets the stored history; b becomes 0.
    void reset();
    /// Stores A_k and G_k (evicting the oldest beyond tau') and recomputes b over the history,
    /// the new pair included. No allocation.
    void push(const Eigen::Ref<const Eigen::MatrixXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& g);
    /// The current b (p x m).
    const Eigen::MatrixXd& value() const { return baseline_; }
    /// Number of stored steps (<= window).
    int size() const { return count_; }
    int window() const { return window_; }

private:
    int rows_;
    int cols_;
    int window_;
    int count_ = 0;
    int next_ = 0;              // ring position of the next write
    Eigen::MatrixXd historyA_;  // (p*m) x tau', one column per step
    Eigen::MatrixXd historyG_;
    Eigen::ArrayXd meanA_, meanAA_, meanGA_;
    Eigen::MatrixXd baseline_;
};

}  // namespace prisca::core
