#pragma once

#include <Eigen/Core>

namespace prisca::core {

/// The local baseline, the paper's variance reducer (eq. 13-15), per parameter entry, over the
/// smoothed gradient terms A_k = E_i E_j a_j and G_k = E_i E_j a_j D_j of the last tau' steps
/// (tau' = 2H in the paper). E below is the plain mean over those steps.
///
/// PaperEq15, eq. 15 as printed (docs/architecture.md):
///     b = 2 E[G (.) A] / (E[A (.) A] + E[A] (.) E[A]),   g = G - b (.) A.
/// Because G and A are built from the same a_j, G ~ c A over the window, and this b then makes
/// g ~ 0 (steady A) or g ~ -G (A fluctuating around 0): the update stalls or climbs the cost.
/// Measured on a linear plant, it diverges (tests/core/test_prisca_controller.cpp).
///
/// ControlVariate, the minimiser of Var(g) that eq. 15's derivation aims at, taken with the
/// constraint that b must not move the mean of g:
///     b = Cov(G, A) / Var(A),   g = G - b (.) (A - E[A]),
/// so E[g] = E[G] and the part of G's fluctuation that A explains is removed.
///
/// b = 0 wherever the denominator is zero. Not thread-safe; one instance per controller.
class LocalOptimalBaseline {
  public:
    enum class Mode { PaperEq15, ControlVariate };

    /// @param rows, cols  shape of A and G (p x m)
    /// @param window      tau' >= 1 [steps]
    LocalOptimalBaseline(int rows, int cols, int window, Mode mode = Mode::ControlVariate);

    /// Forgets the stored history; b becomes 0.
    void reset();
    /// Stores A_k and G_k (evicting the oldest beyond tau') and recomputes b over the history,
    /// the new pair included. No allocation.
    void push(const Eigen::Ref<const Eigen::MatrixXd>& a,
              const Eigen::Ref<const Eigen::MatrixXd>& g);
    /// The current b (p x m).
    const Eigen::MatrixXd& value() const { return baseline_; }
    /// The gradient of the last push: G - b (.) A (PaperEq15) or G - b (.) (A - E[A]).
    /// No allocation.
    void gradient(const Eigen::Ref<const Eigen::MatrixXd>& a,
                  const Eigen::Ref<const Eigen::MatrixXd>& g,
                  Eigen::Ref<Eigen::MatrixXd> out) const;
    Mode mode() const { return mode_; }
    /// Number of stored steps (<= window).
    int size() const { return count_; }
    int window() const { return window_; }

  private:
    int rows_;
    int cols_;
    int window_;
    Mode mode_;
    int count_ = 0;
    int next_ = 0;              // ring position of the next write
    Eigen::MatrixXd historyA_;  // (p*m) x tau', one column per step
    Eigen::MatrixXd historyG_;
    Eigen::ArrayXd meanA_, meanAA_, meanGA_, meanG_;
    Eigen::MatrixXd baseline_;
};

}  // namespace prisca::core
