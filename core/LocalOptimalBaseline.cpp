#include "LocalOptimalBaseline.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace prisca::core {

LocalOptimalBaseline::LocalOptimalBaseline(int rows, int cols, int window, Mode mode)
    : rows_(rows), cols_(cols), window_(window), mode_(mode) {
    if (rows < 1 || cols < 1 || window < 1) {
        throw std::invalid_argument("LocalOptimalBaseline: shape and window must be >= 1");
    }
    historyA_.setZero(rows * cols, window);
    historyG_.setZero(rows * cols, window);
    meanA_.setZero(rows * cols);
    meanAA_.setZero(rows * cols);
    meanGA_.setZero(rows * cols);
    meanG_.setZero(rows * cols);
    baseline_.setZero(rows, cols);
}

void LocalOptimalBaseline::reset() {
    count_ = 0;
    next_ = 0;
    baseline_.setZero();
    meanA_.setZero();
}

void LocalOptimalBaseline::push(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                const Eigen::Ref<const Eigen::MatrixXd>& g) {
    // Column-major p x m maps onto one ring column entry by entry.
    historyA_.col(next_) = a.reshaped();
    historyG_.col(next_) = g.reshaped();
    next_ = (next_ + 1) % window_;
    if (count_ < window_) {
        ++count_;
    }
    // Recomputed over the ring rather than kept as running sums, so rounding never accumulates.
    const auto storedA = historyA_.leftCols(count_).array();
    const auto storedG = historyG_.leftCols(count_).array();
    const double inv = 1.0 / count_;
    meanA_ = storedA.rowwise().sum() * inv;
    meanAA_ = storedA.square().rowwise().sum() * inv;
    meanGA_ = (storedG * storedA).rowwise().sum() * inv;
    if (mode_ == Mode::ControlVariate) {
        meanG_ = storedG.rowwise().sum() * inv;
    }
    for (int i = 0; i < rows_ * cols_; ++i) {
        double numerator = 0.0;
        double denominator = 0.0;
        if (mode_ == Mode::PaperEq15) {
            numerator = 2.0 * meanGA_[i];
            denominator = meanAA_[i] + meanA_[i] * meanA_[i];
        } else {
            numerator = meanGA_[i] - meanG_[i] * meanA_[i];
            denominator = meanAA_[i] - meanA_[i] * meanA_[i];
        }
        // A variance that rounding left at a sliver of its mean square is no variance at all.
        const double floor = mode_ == Mode::ControlVariate ? 1e-12 * meanAA_[i] : 0.0;
        baseline_.data()[i] = denominator > std::max(floor, std::numeric_limits<double>::min())
                                  ? numerator / denominator
                                  : 0.0;
    }
}

void LocalOptimalBaseline::gradient(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                    const Eigen::Ref<const Eigen::MatrixXd>& g,
                                    Eigen::Ref<Eigen::MatrixXd> out) const {
    if (mode_ == Mode::PaperEq15) {
        out = g - baseline_.cwiseProduct(a);
    } else {
        out = g - baseline_.cwiseProduct(a - meanA_.reshaped(rows_, cols_).matrix());
    }
}

}  // namespace prisca::core
