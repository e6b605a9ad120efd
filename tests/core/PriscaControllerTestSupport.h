#pragma once

// What the PRISCA controller tests share: random demonstrations, problems and the literal
// Algorithm 1.

#include "TestDemonstrations.h"
#include "core/ActionMapping.h"
#include "core/PdController.h"
#include "core/PgsdController.h"
#include "core/PriscaController.h"
#include "core/StartLaw.h"

#include <QtTest>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

using namespace prisca::core;

namespace {

inline std::shared_ptr<Demonstration> randomDemonstration(int T, int n, int m, double dt,
                                                          std::mt19937& rng) {
    std::normal_distribution<double> normal(0.0, 1.0);
    auto d = std::make_shared<Demonstration>(prisca::test::namedDemonstration(T, n, m, dt));
    for (int k = 0; k < T; ++k) {
        for (int c = 0; c < n; ++c)
            d->states(k, c) = std::sin(0.1 * k + c) + 0.05 * normal(rng);
        for (int l = 0; l < m; ++l)
            d->actions(k, l) = 0.5 * std::cos(0.07 * k + l);
    }
    return d;
}

inline TrackingProblem problemFor(std::shared_ptr<const Demonstration> demo,
                                  MatchingParameters::Mode mode, double limit) {
    TrackingProblem problem;
    problem.demonstration = demo;
    problem.deviation = DeviationModel::euclidean(demo->stateDimension());
    problem.matching.mode = mode;
    problem.matching.window = 5;
    problem.limits = ActionLimits::symmetric(demo->actionDimension(), limit);
    return problem;
}

// Algorithm 1 written out from the definitions, with nested loops and no shared code.
struct LiteralPrisca {
    int H;
    double gamma;
    int tauPrime;
    double beta;
    Eigen::MatrixXd B;  // m x n
    Eigen::VectorXd W;  // cost weights
    double dt;
    Eigen::MatrixXd theta;                // p x m
    std::vector<Eigen::MatrixXd> a;       // a_j, p x m
    std::vector<Eigen::MatrixXd> As, Gs;  // A_k, G_k

    // One step given the error e_k and the features Phi_k; returns theta after the update.
    Eigen::MatrixXd step(int k, const Eigen::VectorXd& e, const Eigen::MatrixXd& phi) {
        const int p = static_cast<int>(phi.rows()), m = static_cast<int>(phi.cols()),
                  n = static_cast<int>(e.size());
        Eigen::MatrixXd ak(p, m);
        for (int l = 0; l < m; ++l) {
            double projection = 0.0;  // e^T W dS_l
            for (int c = 0; c < n; ++c)
                projection += e[c] * W[c] * dt * B(l, c);
            for (int i = 0; i < p; ++i)
                ak(i, l) = phi(i, l) * projection;
        }
        a.push_back(ak);
        const int start = std::max(0, k - H);
        Eigen::MatrixXd A = Eigen::MatrixXd::Zero(p, m), G = Eigen::MatrixXd::Zero(p, m);
        for (int i = start; i <= k; ++i) {  // E_{i=k-H:k} E_{j=i:k}
            Eigen::MatrixXd innerA = Eigen::MatrixXd::Zero(p, m),
                            innerG = Eigen::MatrixXd::Zero(p, m);
            for (int j = i; j <= k; ++j) {
                const double D = H / (std::pow(gamma, j - (k - H)) + 1.0);
                innerA += a[j];
                innerG += a[j] * D;
            }
            A += innerA / (k - i + 1);
            G += innerG / (k - i + 1);
        }
        A /= (k - start + 1);
        G /= (k - start + 1);
        As.push_back(A);
        Gs.push_back(G);
        Eigen::MatrixXd b = Eigen::MatrixXd::Zero(p, m);
        const int first = std::max(0, k - tauPrime + 1);
        for (int i = 0; i < p; ++i) {
            for (int l = 0; l < m; ++l) {
                double ga = 0, aa = 0, am = 0;
                for (int t = first; t <= k; ++t) {
                    ga += Gs[t](i, l) * As[t](i, l);
                    aa += As[t](i, l) * As[t](i, l);
                    am += As[t](i, l);
                }
                const double count = k - first + 1;
                const double denominator = aa / count + (am / count) * (am / count);
                b(i, l) = denominator > 0 ? 2.0 * (ga / count) / denominator : 0.0;
            }
        }
        const Eigen::MatrixXd g = G - b.cwiseProduct(A);
        theta -= beta / (k + beta) * g;
        return theta;
    }
};

// A plant that integrates its action, the model of eq. 5: s_{k+1} = s_k + dt G u_k.
struct IntegratorPlant {
    Eigen::MatrixXd G;  // n x m
    double dt;
    Eigen::VectorXd s;
    void step(const Eigen::VectorXd& u) { s += dt * G * u; }
};

}  // namespace
