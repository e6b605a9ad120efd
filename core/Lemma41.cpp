#include "Lemma41.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "InverseDepreciation.h"

namespace prisca::core {

double inverseDepreciationVariance(int horizon, double gamma, int tauPrime) {
    if (tauPrime < 1) {
        throw std::invalid_argument("inverseDepreciationVariance: tau' must be >= 1");
    }
    // InverseDepreciation validates H and gamma and is the D the controller actually uses.
    const InverseDepreciation depreciation(horizon, gamma, InverseDepreciation::Mode::Absolute);
    std::vector<double> d(static_cast<std::size_t>(tauPrime));
    double sum = 0.0;
    for (int i = 0; i < tauPrime; ++i) {
        d[static_cast<std::size_t>(i)] = depreciation.forExponent(i);
        sum += d[static_cast<std::size_t>(i)];
    }
    const double mean = sum / tauPrime;
    // Two passes rather than E(D^2) - E(D)^2: the latter cancels (D ~ H, variance ~ 1).
    double squares = 0.0;
    double residual = 0.0;
    for (double v : d) {
        squares += (v - mean) * (v - mean);
        residual += v - mean;
    }
    return std::max(0.0, (squares - residual * residual / tauPrime) / tauPrime);
}

std::vector<Lemma41Cell> lemma41Grid(
    int maxHorizon, int gammaSteps,
    const std::function<void(long long done, long long total)>& progress) {
    if (maxHorizon < 1) {
        throw std::invalid_argument("lemma41Grid: maxHorizon must be >= 1");
    }
    if (gammaSteps < 2) {
        throw std::invalid_argument("lemma41Grid: gammaSteps must be >= 2 (gamma 0 and 1)");
    }
    std::vector<Lemma41Cell> cells;
    cells.reserve(static_cast<std::size_t>(maxHorizon) * gammaSteps);
    for (int h = 1; h <= maxHorizon; ++h) {
        for (int g = 0; g < gammaSteps; ++g) {
            Lemma41Cell cell;
            cell.horizon = h;
            // g / (steps - 1) rather than an accumulated step: the last cell is exactly 1.
            cell.gamma = static_cast<double>(g) / (gammaSteps - 1);
            cell.variance = inverseDepreciationVariance(h, cell.gamma, lemma41TauPrime(h));
            cell.satisfied = cell.variance < 1.0;
            cells.push_back(cell);
        }
        if (progress) {
            progress(lemma41Terms(h, gammaSteps), lemma41Terms(maxHorizon, gammaSteps));
        }
    }
    return cells;
}

int lemma41SatisfiedCount(const std::vector<Lemma41Cell>& cells) {
    return static_cast<int>(std::count_if(cells.begin(), cells.end(),
                                          [](const Lemma41Cell& c) { return c.satisfied; }));
}

}  // namespace prisca::core
