#pragma once

namespace prisca::core {

/// The learning-rate schedule alpha_k of the update theta -= alpha_k g (eq. 2).
struct StepSize {
    enum class Mode {
        Decaying,  ///< eq. 3 scaled: alpha_k = scale * beta / (k + beta), square summable but not
                   ///< summable
        Fixed      ///< alpha_k = fixed (PGSD)
    };
    Mode mode = Mode::Decaying;
    double beta = 1000.0;  ///< rate of learning in eq. 3 (> 0) [steps]
    /// alpha_0 [theta units^2 per gradient unit]: eq. 3 is scale = 1. The gradient's size depends
    /// on the units of e, phi and B, so a fixed alpha_0 = 1 is a choice of units, not a law.
    double scale = 1.0;
    double fixed = 1e-3;  ///< alpha in Fixed mode (>= 0)
    /// Decaying mode, PRISCA: divide alpha_k by the mean Gauss-Newton curvature of the cost in
    /// theta seen so far (the mean over steps of tr(dE/dtheta^T W dE/dtheta) per theta entry), so
    /// that scale is unit-free: the fraction of a scalar Newton step taken per control step,
    /// whatever the units of e, phi and B (MethodTuning::automatic).
    bool normalised = false;

    /// alpha_k for step k >= 0.
    double at(int step) const {
        return mode == Mode::Fixed ? fixed : scale * beta / (static_cast<double>(step) + beta);
    }
};

}  // namespace prisca::core
