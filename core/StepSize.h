#pragma once

namespace prisca::core {

/// The learning-rate schedule alpha_k of the update theta -= alpha_k g (eq. 2).
struct StepSize {
    enum class Mode {
        Decaying,  ///< eq. 3: alpha_k = beta / (k + beta), square summable but not summable
        Fixed      ///< alpha_k = fixed (PGSD)
    };
    Mode mode = Mode::Decaying;
    double beta = 1000.0;  ///< rate of learning in eq. 3 (> 0) [steps]
    double fixed = 1e-3;   ///< alpha in Fixed mode (>= 0)

    /// alpha_k for step k >= 0.
    double at(int step) const {
        return mode == Mode::Fixed ? fixed : beta / (static_cast<double>(step) + beta);
    }
};

}  // namespace prisca::core
