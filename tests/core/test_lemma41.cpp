// Lemma 4.1 / Fig. 2: Var_tau'(D) of the inverse depreciation D_i = H / (gamma^i + 1) over
// i = 0 .. tau'-1 (tau' = 2H), checked against a plain brute-force computation written here
// (long double, gamma^i by repeated multiplication, the paper's E(D^2) - E(D)^2) and against the
// closed forms at gamma = 0 and gamma = 1.

#include <QtTest>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/Lemma41.h"

using namespace prisca::core;

namespace {

// Agreement required between the library and the brute force. On x86-64 long double carries 64
// mantissa bits and the brute force is good to ~1e-16; where long double is plain double, the
// cancellation of its two ~H^2 = 2500 terms costs ~1e-12 by itself, so allow for that.
const double kTolerance = std::numeric_limits<long double>::digits > 53 ? 1e-12 : 1e-11;

// E(D^2) - E(D)^2 over i = 0 .. tauPrime-1, exactly as the lemma writes it.
double bruteForceVariance(int horizon, double gamma, int tauPrime) {
    long double sumD = 0.0L;
    long double sumD2 = 0.0L;
    long double power = 1.0L;  // gamma^i, with gamma^0 = 1 also for gamma = 0
    for (int i = 0; i < tauPrime; ++i) {
        const long double d = static_cast<long double>(horizon) / (power + 1.0L);
        sumD += d;
        sumD2 += d * d;
        power *= gamma;
    }
    const long double meanD = sumD / tauPrime;
    return static_cast<double>(sumD2 / tauPrime - meanD * meanD);
}

QByteArray describe(int horizon, double gamma, int tauPrime, double actual, double expected) {
    return "H " + QByteArray::number(horizon) + ", gamma " + QByteArray::number(gamma, 'g', 17) +
           ", tau' " + QByteArray::number(tauPrime) + ": got " +
           QByteArray::number(actual, 'g', 17) + ", expected " +
           QByteArray::number(expected, 'g', 17);
}

}  // namespace

class TestLemma41 : public QObject {
    Q_OBJECT

  private slots:
    void variance_matchesBruteForce();
    void variance_isZeroWhenGammaIsOne();
    void variance_matchesClosedFormWhenGammaIsZero();
    void variance_ofSingleExponentIsZero();
    void variance_rejectsInvalidArguments();
    void grid_hasOneCellPerHorizonAndGamma();
    void grid_cellsAgreeWithVarianceAndThreshold();
    void grid_gammaZeroColumnSatisfiedExactlyUpToHorizonEight();
    void grid_isNonTrivial();
    void grid_rejectsInvalidSizes();
    void grid_reportsItsTermsAfterEachHorizon();
};

void TestLemma41::variance_matchesBruteForce() {
    std::mt19937 rng(41u);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<double> gammas = {0.0, 1e-9, 0.01, 0.1,   0.25,        0.5, 0.75,
                                  0.9, 0.95, 0.99, 0.999, 1.0 - 1e-12, 1.0};
    for (int i = 0; i < 20; ++i) {
        gammas.push_back(uniform(rng));
    }
    int checked = 0;
    for (int h = 1; h <= 50; ++h) {
        for (double gamma : gammas) {
            for (int tauPrime : {lemma41TauPrime(h), 1, 2, 7, 100}) {
                const double actual = inverseDepreciationVariance(h, gamma, tauPrime);
                const double expected = bruteForceVariance(h, gamma, tauPrime);
                QVERIFY2(std::abs(actual - expected) <= kTolerance,
                         describe(h, gamma, tauPrime, actual, expected));
                ++checked;
            }
        }
    }
    QCOMPARE(checked, 50 * int(gammas.size()) * 5);
}

void TestLemma41::variance_isZeroWhenGammaIsOne() {
    // gamma^i = 1 for all i: D is the constant H / 2.
    for (int h = 1; h <= 50; ++h) {
        const double v = inverseDepreciationVariance(h, 1.0, lemma41TauPrime(h));
        QVERIFY2(std::abs(v) <= 1e-15, describe(h, 1.0, lemma41TauPrime(h), v, 0.0));
    }
}

void TestLemma41::variance_matchesClosedFormWhenGammaIsZero() {
    // D = H/2 at i = 0 and H afterwards: a two-point distribution with gap H/2 and
    // p = 1 / (2H), so Var = (H/2)^2 p (1 - p) = (2H - 1) / 16.
    for (int h = 1; h <= 50; ++h) {
        const double p = 1.0 / (2.0 * h);
        const double expected = (h / 2.0) * (h / 2.0) * p * (1.0 - p);
        const double v = inverseDepreciationVariance(h, 0.0, lemma41TauPrime(h));
        QVERIFY2(std::abs(v - expected) <= 1e-12, describe(h, 0.0, 2 * h, v, expected));
        QVERIFY2(std::abs(v - (2.0 * h - 1.0) / 16.0) <= 1e-12,
                 describe(h, 0.0, 2 * h, v, (2.0 * h - 1.0) / 16.0));
    }
    // The boundary: 15/16 < 1 at H = 8, 17/16 > 1 at H = 9.
    QVERIFY(inverseDepreciationVariance(8, 0.0, 16) < 1.0);
    QVERIFY(inverseDepreciationVariance(9, 0.0, 18) > 1.0);
}

void TestLemma41::variance_ofSingleExponentIsZero() {
    QCOMPARE(inverseDepreciationVariance(30, 0.3, 1), 0.0);
}

void TestLemma41::variance_rejectsInvalidArguments() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, inverseDepreciationVariance(0, 0.5, 2));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, inverseDepreciationVariance(3, -0.1, 6));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, inverseDepreciationVariance(3, 1.1, 6));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, inverseDepreciationVariance(3, 0.5, 0));
}

void TestLemma41::grid_hasOneCellPerHorizonAndGamma() {
    const std::vector<Lemma41Cell> grid = lemma41Grid();
    QCOMPARE(int(grid.size()), 50 * 101);
    for (int h = 1; h <= 50; ++h) {
        for (int g = 0; g <= 100; ++g) {
            const Lemma41Cell& cell = grid[std::size_t((h - 1) * 101 + g)];
            QCOMPARE(cell.horizon, h);
            QVERIFY2(
                std::abs(cell.gamma - g / 100.0) <= 1e-15,
                qPrintable(QStringLiteral("H %1, g %2: gamma %3").arg(h).arg(g).arg(cell.gamma)));
        }
    }
    // The gamma range is closed: both ends are present exactly.
    QCOMPARE(grid.front().gamma, 0.0);
    QCOMPARE(grid[100].gamma, 1.0);
    QCOMPARE(grid.back().gamma, 1.0);
    QCOMPARE(grid.back().horizon, 50);

    const std::vector<Lemma41Cell> small = lemma41Grid(3, 2);
    QCOMPARE(int(small.size()), 6);
    QCOMPARE(small[4].horizon, 3);
    QCOMPARE(small[4].gamma, 0.0);
    QCOMPARE(small[5].gamma, 1.0);
}

void TestLemma41::grid_cellsAgreeWithVarianceAndThreshold() {
    const std::vector<Lemma41Cell> grid = lemma41Grid(50, 21);
    for (const Lemma41Cell& cell : grid) {
        const double expected = bruteForceVariance(cell.horizon, cell.gamma, 2 * cell.horizon);
        QVERIFY2(std::abs(cell.variance - expected) <= kTolerance,
                 describe(cell.horizon, cell.gamma, 2 * cell.horizon, cell.variance, expected));
        QCOMPARE(cell.satisfied, cell.variance < 1.0);
    }
}

void TestLemma41::grid_gammaZeroColumnSatisfiedExactlyUpToHorizonEight() {
    const std::vector<Lemma41Cell> grid = lemma41Grid();
    for (int h = 1; h <= 50; ++h) {
        const Lemma41Cell& cell = grid[std::size_t((h - 1) * 101)];
        QCOMPARE(cell.gamma, 0.0);
        QVERIFY2(cell.satisfied == (h <= 8),
                 qPrintable(QStringLiteral("H %1: variance %2").arg(h).arg(cell.variance)));
        // gamma = 1 column: variance 0, always satisfied.
        QVERIFY(grid[std::size_t((h - 1) * 101 + 100)].satisfied);
    }
}

void TestLemma41::grid_isNonTrivial() {
    const std::vector<Lemma41Cell> grid = lemma41Grid();
    const int satisfied = lemma41SatisfiedCount(grid);
    int bruteCount = 0;
    for (const Lemma41Cell& cell : grid) {
        bruteCount += cell.variance < 1.0 ? 1 : 0;
    }
    QCOMPARE(satisfied, bruteCount);
    qInfo("Lemma 4.1 grid (H 1..50, gamma step 0.01): %d of %d cells satisfied", satisfied,
          int(grid.size()));
    QVERIFY(satisfied > 0);                 // the lemma: such a combination exists
    QVERIFY(satisfied < int(grid.size()));  // ... but not every combination qualifies
}

void TestLemma41::grid_rejectsInvalidSizes() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, lemma41Grid(0, 101));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, lemma41Grid(50, 1));
    QCOMPARE(lemma41SatisfiedCount({}), 0);
}

void TestLemma41::grid_reportsItsTermsAfterEachHorizon() {
    // tau' = 2H terms per cell: after horizon h, gammaSteps * h * (h + 1) terms in all.
    std::vector<long long> done;
    long long total = 0;
    const auto cells = lemma41Grid(7, 5, [&](long long d, long long t) {
        done.push_back(d);
        total = t;
    });
    QCOMPARE(cells.size(), std::size_t{35});
    QCOMPARE(done, (std::vector<long long>{10, 30, 60, 100, 150, 210, 280}));
    QCOMPARE(total, 280LL);
    QCOMPARE(lemma41Terms(7, 5), 280LL);
    QCOMPARE(lemma41Terms(10000, 10001), 1000200010000LL);  // beyond an int
}

QTEST_GUILESS_MAIN(TestLemma41)
#include "test_lemma41.moc"
