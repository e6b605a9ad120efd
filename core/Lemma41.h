#pragma once

#include <functional>
#include <vector>

namespace prisca::core {

// Lemma 4.1 of the paper and its Fig. 2: over H in 1..50 and gamma in [0, 1] there exist
// (H, gamma) with
//     E_tau'(D^2) - E_tau'(D)^2 - 1 < 0,   i.e.   Var_tau'(D) < 1,
// for the inverse depreciation D_i = H / (gamma^i + 1) (eq. 10, class InverseDepreciation).
//
// The paper leaves E_tau' open. Decision for this project: E_tau' is the uniform mean over
// tau' consecutive exponents i = 0 .. tau'-1, and Var_tau' is the population variance (divide
// by tau'), the literal E(D^2) - E(D)^2 of the lemma. tau' = 2H ("tau' is picked as 2 tau"), the
// same window as the local optimal baseline (docs/architecture.md). With this choice gamma = 1
// gives variance 0 for every H, and gamma = 0 gives (2H - 1) / 16, so the lemma holds there for H
// <= 8.
//
// Pure functions; any thread may call them.

/// tau' used by the lemma for a horizon H: 2H.
constexpr int lemma41TauPrime(int horizon) {
    return 2 * horizon;
}

/// Population variance of D_i = H / (gamma^i + 1) over the exponents i = 0 .. tauPrime-1.
/// @param horizon   H >= 1 [steps]
/// @param gamma     rate of inverse depreciation in [0, 1]
/// @param tauPrime  number of exponents averaged over, >= 1 (the lemma uses lemma41TauPrime(H))
/// Throws std::invalid_argument when an argument is out of range.
double inverseDepreciationVariance(int horizon, double gamma, int tauPrime);

/// One (H, gamma) cell of the Fig. 2 grid.
struct Lemma41Cell {
    int horizon = 1;         ///< H [steps]
    double gamma = 0.0;      ///< gamma in [0, 1]
    double variance = 0.0;   ///< Var_tau'(D) with tau' = 2H
    bool satisfied = false;  ///< variance < 1: the lemma's inequality holds (a gray cell in Fig. 2)
};

/// The terms D_i that lemma41Grid(maxHorizon, gammaSteps) evaluates, what its time grows with:
/// tau' = 2H of them per cell, gammaSteps * maxHorizon * (maxHorizon + 1) in all (quadratic in
/// the largest horizon).
constexpr long long lemma41Terms(int maxHorizon, int gammaSteps) {
    return static_cast<long long>(gammaSteps) * maxHorizon * (maxHorizon + 1LL);
}

/// The Fig. 2 grid: H = 1 .. maxHorizon, gamma = g / (gammaSteps - 1) for g = 0 .. gammaSteps-1
/// (so both 0 and 1 are included exactly). maxHorizon * gammaSteps cells, ordered by H first
/// (outer) and gamma second: cell (H, g) is at index (H - 1) * gammaSteps + g.
/// @param maxHorizon  >= 1, default 50 as in the paper
/// @param gammaSteps  >= 2, default 101 (gamma step 0.01)
/// @param progress    if set, called on the calling thread after each H with the terms
///                    evaluated so far and lemma41Terms(maxHorizon, gammaSteps)
/// Throws std::invalid_argument when an argument is out of range.
std::vector<Lemma41Cell> lemma41Grid(
    int maxHorizon = 50, int gammaSteps = 101,
    const std::function<void(long long done, long long total)>& progress = {});

/// Number of cells of a grid in which the lemma's inequality holds.
int lemma41SatisfiedCount(const std::vector<Lemma41Cell>& cells);

}  // namespace prisca::core
