#pragma once

namespace prisca::core {

/// Inverse depreciation, the paper's cost intensifier (eq. 10): D = H / (gamma^r + 1).
///
/// r counts samples from the start of the H-step window: for the sample j of the window that
/// ends at step k, r = j - (k - H), so r runs 0..H and the newest sample gets r = H (the most
/// weight). The Absolute mode uses r = j instead (the paper's D_i with i the time index).
/// D grows from H/2 (r = 0, or any r when gamma = 1) towards H as r grows (gamma < 1).
class InverseDepreciation {
  public:
    enum class Mode { RelativeToWindow, Absolute };

    /// @param horizon  H >= 1, the smoothing horizon [steps]
    /// @param gamma    rate of inverse depreciation in [0, 1]
    InverseDepreciation(int horizon, double gamma, Mode mode = Mode::RelativeToWindow);

    /// D for the sample j of the window ending at step k (j <= k).
    double at(int j, int k) const;
    /// D for a given exponent r >= 0: H / (gamma^r + 1).
    double forExponent(int r) const;

    int horizon() const { return horizon_; }
    double gamma() const { return gamma_; }
    Mode mode() const { return mode_; }

  private:
    int horizon_;
    double gamma_;
    Mode mode_;
};

}  // namespace prisca::core
