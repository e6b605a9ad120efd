// Each of the paper's small equations against a plain brute-force computation of its
// definition (nested loops, nothing shared with the implementation), to 1e-12.
#include "core/DeviationModel.h"
#include "core/FeatureMap.h"
#include "core/InverseDepreciation.h"
#include "core/LocalOptimalBaseline.h"
#include "core/NestedExpectation.h"
#include "core/StepSize.h"

#include <QtTest>

#include <cmath>
#include <random>
#include <vector>

using namespace prisca::core;

namespace {

constexpr double kTol = 1e-12;

// E_{i=a:k} E_{j=i:k} x_j, literally: the mean over i of the mean over j >= i.
double nestedMeanBruteForce(const std::vector<double>& x, int a, int k) {
    double outer = 0.0;
    for (int i = a; i <= k; ++i) {
        double inner = 0.0;
        for (int j = i; j <= k; ++j) {
            inner += x[j];
        }
        outer += inner / (k - i + 1);
    }
    return outer / (k - a + 1);
}

}  // namespace

class TestEquations : public QObject {
    Q_OBJECT
  private slots:
    void nestedWeights_equalLiteralNestedMean() {
        std::mt19937 rng(1);
        std::uniform_real_distribution<double> u(-5, 5);
        for (int H : {0, 1, 2, 5, 10, 37}) {
            for (int k = 0; k < 60; ++k) {
                std::vector<double> x(k + 1);
                for (double& v : x)
                    v = u(rng);
                const Eigen::VectorXd w = smoothingWeights(k, H);
                const int a = std::max(0, k - H);
                QCOMPARE(w.size(), k - a + 1);
                double weighted = 0.0;
                for (int t = 0; t < w.size(); ++t)
                    weighted += w[t] * x[a + t];
                const double brute = nestedMeanBruteForce(x, a, k);
                QVERIFY2(
                    std::abs(weighted - brute) <= kTol,
                    qPrintable(
                        QString("H=%1 k=%2: %3 vs %4").arg(H).arg(k).arg(weighted).arg(brute)));
            }
        }
    }

    void nestedWeights_sumToOneAndFavourRecentSamples() {
        for (int N : {1, 2, 11, 1000}) {
            const Eigen::VectorXd w = nestedExpectationWeights(N);
            QVERIFY(std::abs(w.sum() - 1.0) <= kTol);
            for (int t = 1; t < N; ++t)
                QVERIFY(w[t] > w[t - 1]);
        }
        // N = 2 by hand: w_0 = 1/2 * 1/2, w_1 = 1/2 * (1/2 + 1).
        const Eigen::VectorXd w2 = nestedExpectationWeights(2);
        QVERIFY(std::abs(w2[0] - 0.25) <= kTol && std::abs(w2[1] - 0.75) <= kTol);
    }

    void nestedWeights_rejectEmptyWindow() {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, nestedExpectationWeights(0));
    }

    void inverseDepreciation_matchesEq10() {
        for (int H : {1, 3, 10, 50}) {
            for (double gamma : {0.0, 0.3, 0.9, 1.0}) {
                InverseDepreciation relative(H, gamma);
                InverseDepreciation absolute(H, gamma, InverseDepreciation::Mode::Absolute);
                for (int k = 0; k < 80; ++k) {
                    for (int j = std::max(0, k - H); j <= k; ++j) {
                        double power = 1.0;  // gamma^r by repeated multiplication
                        for (int r = 0; r < j - (k - H); ++r)
                            power *= gamma;
                        QVERIFY(std::abs(relative.at(j, k) - H / (power + 1.0)) <= kTol);
                        double powerAbs = 1.0;
                        for (int r = 0; r < j; ++r)
                            powerAbs *= gamma;
                        QVERIFY(std::abs(absolute.at(j, k) - H / (powerAbs + 1.0)) <= kTol);
                    }
                }
            }
        }
    }

    void inverseDepreciation_growsFromHalfHToH() {
        InverseDepreciation d(10, 0.5);
        QVERIFY(std::abs(d.at(0, 10) - 5.0) <= kTol);  // oldest sample of the window: r = 0
        QVERIFY(d.at(10, 10) > 9.99 && d.at(10, 10) < 10.0);
        InverseDepreciation flat(10, 1.0);
        QVERIFY(std::abs(flat.at(3, 10) - 5.0) <= kTol);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, InverseDepreciation(0, 0.5));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, InverseDepreciation(5, 1.5));
    }

    void stepSize_matchesEq3() {
        StepSize alpha;
        alpha.beta = 7.0;
        for (int k = 0; k < 100; ++k)
            QVERIFY(std::abs(alpha.at(k) - 7.0 / (k + 7.0)) <= kTol);
        QCOMPARE(alpha.at(0), 1.0);
        StepSize fixed;
        fixed.mode = StepSize::Mode::Fixed;
        fixed.fixed = 0.25;
        QCOMPARE(fixed.at(0), 0.25);
        QCOMPARE(fixed.at(1000), 0.25);
    }

    void localOptimalBaseline_matchesEq15OverLastTauPrime() {
        std::mt19937 rng(3);
        std::normal_distribution<double> normal(0.0, 1.0);
        const int p = 3, m = 2, window = 6;
        LocalOptimalBaseline baseline(p, m, window, LocalOptimalBaseline::Mode::PaperEq15);
        std::vector<Eigen::MatrixXd> As, Gs;
        for (int k = 0; k < 25; ++k) {
            Eigen::MatrixXd A(p, m), G(p, m);
            for (int i = 0; i < p; ++i)
                for (int l = 0; l < m; ++l) {
                    A(i, l) = normal(rng);
                    G(i, l) = 2.0 * A(i, l) + 0.3 * normal(rng);
                }
            A(2, 1) = 0.0;  // an entry whose denominator stays zero
            G(2, 1) = normal(rng);
            As.push_back(A);
            Gs.push_back(G);
            baseline.push(A, G);
            const int first = std::max(0, k - window + 1);
            const int count = k - first + 1;
            for (int i = 0; i < p; ++i) {
                for (int l = 0; l < m; ++l) {
                    double ga = 0, aa = 0, a = 0;
                    for (int t = first; t <= k; ++t) {
                        ga += Gs[t](i, l) * As[t](i, l);
                        aa += As[t](i, l) * As[t](i, l);
                        a += As[t](i, l);
                    }
                    ga /= count;
                    aa /= count;
                    a /= count;
                    const double denominator = aa + a * a;
                    const double expected = denominator == 0.0 ? 0.0 : 2.0 * ga / denominator;
                    QVERIFY2(std::abs(baseline.value()(i, l) - expected) <=
                                 kTol * (1 + std::abs(expected)),
                             qPrintable(QString("k=%1 (%2,%3)").arg(k).arg(i).arg(l)));
                }
            }
            QCOMPARE(baseline.size(), count);
        }
        QCOMPARE(baseline.value()(2, 1), 0.0);
        baseline.reset();
        QCOMPARE(baseline.size(), 0);
        QVERIFY(baseline.value().isZero());
    }

    void controlVariateBaseline_isCovarianceOverVarianceAndKeepsTheMean() {
        std::mt19937 rng(4);
        std::normal_distribution<double> normal(0.0, 1.0);
        const int p = 2, m = 2, window = 5;
        LocalOptimalBaseline baseline(p, m, window, LocalOptimalBaseline::Mode::ControlVariate);
        std::vector<Eigen::MatrixXd> As, Gs;
        for (int k = 0; k < 20; ++k) {
            Eigen::MatrixXd A(p, m), G(p, m);
            for (int i = 0; i < p; ++i)
                for (int l = 0; l < m; ++l) {
                    A(i, l) = 1.0 + normal(rng);
                    G(i, l) = 3.0 * A(i, l) + 0.5 * normal(rng);
                }
            A(1, 1) = 2.0;  // constant: no variance, so b = 0 there
            As.push_back(A);
            Gs.push_back(G);
            baseline.push(A, G);
            const int first = std::max(0, k - window + 1);
            const double count = k - first + 1;
            Eigen::MatrixXd g(p, m);
            baseline.gradient(A, G, g);
            for (int i = 0; i < p; ++i) {
                for (int l = 0; l < m; ++l) {
                    double ma = 0, mg = 0;
                    for (int t = first; t <= k; ++t) {
                        ma += As[t](i, l) / count;
                        mg += Gs[t](i, l) / count;
                    }
                    double cov = 0, var = 0;
                    for (int t = first; t <= k; ++t) {
                        cov += (Gs[t](i, l) - mg) * (As[t](i, l) - ma) / count;
                        var += (As[t](i, l) - ma) * (As[t](i, l) - ma) / count;
                    }
                    const double b = var > 1e-12 ? cov / var : 0.0;
                    QVERIFY2(std::abs(baseline.value()(i, l) - b) <= 1e-10 * (1 + std::abs(b)),
                             qPrintable(QString("k=%1 (%2,%3): %4 vs %5")
                                            .arg(k)
                                            .arg(i)
                                            .arg(l)
                                            .arg(baseline.value()(i, l))
                                            .arg(b)));
                    const double expected = G(i, l) - b * (A(i, l) - ma);
                    QVERIFY(std::abs(g(i, l) - expected) <= 1e-10 * (1 + std::abs(expected)));
                }
            }
        }
        QCOMPARE(baseline.value()(1, 1), 0.0);
        // Averaged over the window, the corrected gradient keeps G's mean: the control variate
        // A - E[A] sums to zero over the stored steps.
        Eigen::MatrixXd meanCorrected = Eigen::MatrixXd::Zero(p, m),
                        meanG = Eigen::MatrixXd::Zero(p, m);
        for (int t = 20 - window; t < 20; ++t) {
            Eigen::MatrixXd g(p, m);
            baseline.gradient(As[t], Gs[t], g);
            meanCorrected += g / window;
            meanG += Gs[t] / window;
        }
        QVERIFY((meanCorrected - meanG).cwiseAbs().maxCoeff() <= 1e-12);
    }

    void wrapAngle_isHalfOpenAroundZero() {
        QVERIFY(std::abs(wrapAngle(M_PI) - M_PI) <= kTol);
        QVERIFY(std::abs(wrapAngle(-M_PI) - M_PI) <= kTol);
        QVERIFY(std::abs(wrapAngle(3 * M_PI / 2) + M_PI / 2) <= kTol);
        QVERIFY(std::abs(wrapAngle(-7.0) - (-7.0 + 2 * M_PI)) <= kTol);
        for (double a = -20; a < 20; a += 0.37) {
            const double w = wrapAngle(a);
            QVERIFY(w > -M_PI && w <= M_PI);
            QVERIFY(std::abs(std::remainder(a - w, 2 * M_PI)) <= 1e-9);
        }
    }

    void bodyFrameDeviation_expressesErrorInDesiredFrame() {
        DeviationModel model = DeviationModel::planarVehicle(6);
        Eigen::VectorXd reference(6), state(6);
        // Desired pose at (1, 2) heading +90 deg (facing world +y).
        reference << 1, 2, M_PI / 2, 1.0, 0.0, 0.0;
        // Actual pose 0.5 m further along +y (ahead) and 0.2 m towards -x (left of +y heading).
        state << 0.8, 2.5, M_PI / 2 + 0.1, 1.5, 0.2, 0.3;
        const Eigen::VectorXd e = model.deviation(state, reference);
        QVERIFY(std::abs(e[0] - 0.5) <= kTol);  // longitudinal: ahead
        QVERIFY(std::abs(e[1] - 0.2) <= kTol);  // lateral: to the left
        QVERIFY(std::abs(e[2] - 0.1) <= kTol);  // heading
        QVERIFY(std::abs(e[3] - 0.5) <= kTol);  // body velocities subtract
        QVERIFY(std::abs(e[4] - 0.2) <= kTol);
        QVERIFY(std::abs(e[5] - 0.3) <= kTol);
        // Heading error wraps across +-pi.
        reference[2] = M_PI - 0.05;
        state = reference;
        state[2] = -M_PI + 0.05;
        QVERIFY(std::abs(model.deviation(state, reference)[2] - 0.1) <= kTol);
    }

    void deviationModel_validateNamesBadIndices() {
        DeviationModel model = DeviationModel::planarVehicle(2);
        QVERIFY(!model.validate().isEmpty());
        DeviationModel angles = DeviationModel::euclidean(3);
        angles.angleIndices = {3};
        QVERIFY(angles.validate().contains("angle index 3"));
        QVERIFY(DeviationModel::planarVehicle(6).validate().isEmpty());
    }

    void featureMap_evaluatesEachChannelsTerms() {
        FeatureMap map(
            {{{FeatureTerm::Source::Deviation, 1, 2.0}, {FeatureTerm::Source::Constant, 0, 0.5}},
             {{FeatureTerm::Source::State, 0, -1.0}, {FeatureTerm::Source::Deviation, 2, 1.0}}});
        QCOMPARE(map.featureCount(), 2);
        QCOMPARE(map.channelCount(), 2);
        Eigen::VectorXd e(3), s(3);
        e << 0.1, 0.2, 0.3;
        s << 4, 5, 6;
        Eigen::MatrixXd phi(2, 2);
        map.evaluate(e, s, phi);
        QCOMPARE(phi(0, 0), 0.4);
        QCOMPARE(phi(1, 0), 0.5);
        QCOMPARE(phi(0, 1), -4.0);
        QCOMPARE(phi(1, 1), 0.3);
        QVERIFY(map.validate(3).isEmpty());
        QVERIFY(!map.validate(2).isEmpty());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 FeatureMap({{{FeatureTerm::Source::Deviation, 0, 1.0}}, {}}));
    }
};

QTEST_APPLESS_MAIN(TestEquations)
#include "test_equations.moc"
