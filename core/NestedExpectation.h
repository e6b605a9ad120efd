#pragma once

#include <Eigen/Core>

namespace prisca::core {

/// Weights of the paper's nested expectation E_{i=a:k} E_{j=i:k} (eq. 8, 9, 13, 14).
///
/// Over the N = k - a + 1 samples a..k, the nested mean equals a weighted sum over j with
///     w_j = 1/N * sum_{i=a}^{j} 1/(k - i + 1),
/// so recent samples weigh more and the weights sum to 1. Returned oldest first:
/// element t is the weight of sample j = a + t.
Eigen::VectorXd nestedExpectationWeights(int count);

/// Smoothing weights of the H-step window ending at step k (docs/architecture.md "Smoothing"):
/// nestedExpectationWeights(min(k, H) + 1); while k < H only the samples that exist are used.
Eigen::VectorXd smoothingWeights(int step, int horizon);

}  // namespace prisca::core
