#include "NestedExpectation.h"

#include <algorithm>
#include <stdexcept>

namespace prisca::core {

Eigen::VectorXd nestedExpectationWeights(int count) {
    if (count < 1) {
        throw std::invalid_argument("nestedExpectationWeights: count must be >= 1");
    }
    Eigen::VectorXd w(count);
    // The inner sum over i is a running sum: sample t adds the term of i = a + t, 1/(N - t).
    double inner = 0.0;
    for (int t = 0; t < count; ++t) {
        inner += 1.0 / static_cast<double>(count - t);
        w[t] = inner / static_cast<double>(count);
    }
    return w;
}

Eigen::VectorXd smoothingWeights(int step, int horizon) {
    if (step < 0 || horizon < 0) {
        throw std::invalid_argument("smoothingWeights: step and horizon must be >= 0");
    }
    return nestedExpectationWeights(std::min(step, horizon) + 1);
}

}  // namespace prisca::core
