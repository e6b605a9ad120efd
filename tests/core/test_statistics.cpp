// Table I error statistics, the Student t distribution and the learning-curve confidence band
// (docs/architecture.md "Metrics"), checked against hand-computed values, closed forms, tabulated
// quantiles and plain brute-force computations written here independently of core/Statistics.cpp.

#include <QtTest>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/Statistics.h"

using namespace prisca::core;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
const double kPi = std::acos(-1.0);

bool closeAbs(double actual, double expected, double tolerance) {
    return std::abs(actual - expected) <= tolerance;
}

bool closeRel(double actual, double expected, double relative) {
    return std::abs(actual - expected) <= relative * std::max(1.0, std::abs(expected));
}

QByteArray describe(const char* what, double actual, double expected) {
    return QByteArray(what) + ": got " + QByteArray::number(actual, 'g', 17) + ", expected " +
           QByteArray::number(expected, 'g', 17) + ", difference " +
           QByteArray::number(actual - expected, 'g', 3);
}

}  // namespace

class TestStatistics : public QObject {
    Q_OBJECT

  private slots:
    void summarizeErrors_matchesHandComputedSmallSample();
    void summarizeErrors_usesAbsoluteValues();
    void summarizeErrors_matchesBruteForceOnLargeOffsetSample();
    void summarizeErrors_varianceIsStandardDeviationSquared();
    void summarizeErrors_skipsAndCountsNonFinite();
    void summarizeErrors_singleValueHasZeroSpread();
    void summarizeErrors_emptyOrAllNonFiniteGivesNaN();
    void meanAndSampleVariance_matchHandValuesAndSkipNonFinite();

    void studentT_matchesTabulatedValues_data();
    void studentT_matchesTabulatedValues();
    void studentT_matchesClosedFormsForOneAndTwoDegrees();
    void studentT_medianIsExactlyZero();
    void studentT_isAntisymmetric();
    void studentT_decreasesTowardsNormalAsDegreesGrow();
    void studentT_cdfMatchesClosedFormsAndInvertsQuantile();
    void studentT_reachesFarTailWithoutOverflow();
    void studentT_handlesBoundsAndRejectsInvalidArguments();

    void confidenceBand_matchesHandComputedRaggedRuns();
    void confidenceBand_coversTrueMeanAtNominalRate();
    void confidenceBand_widensWithLevelAndRejectsInvalidLevel();
    void confidenceBand_noRunsGivesEmptyBand();
};

void TestStatistics::summarizeErrors_matchesHandComputedSmallSample() {
    // |e| = {1, 2, 3, 4}: mean 2.5, squared deviations 2.25 + 0.25 + 0.25 + 2.25 = 5, / (4 - 1).
    const ErrorSummary s = summarizeErrors({1.0, -2.0, 3.0, 4.0});
    QCOMPARE(s.count, 4);
    QCOMPARE(s.nonFinite, 0);
    QVERIFY2(closeAbs(s.meanAbsoluteError, 2.5, 1e-15), describe("MAE", s.meanAbsoluteError, 2.5));
    QVERIFY2(closeAbs(s.variance, 5.0 / 3.0, 1e-15), describe("variance", s.variance, 5.0 / 3.0));
    QVERIFY2(closeAbs(s.standardDeviation, std::sqrt(5.0 / 3.0), 1e-15),
             describe("std", s.standardDeviation, std::sqrt(5.0 / 3.0)));
    QCOMPARE(s.minimum, 1.0);
    QCOMPARE(s.maximum, 4.0);
}

void TestStatistics::summarizeErrors_usesAbsoluteValues() {
    // Signed errors and their magnitudes must give the same Table I row.
    const ErrorSummary signedErrors = summarizeErrors({-5.0, 2.0, -1.5, 0.5, -0.25});
    const ErrorSummary magnitudes = summarizeErrors({5.0, 2.0, 1.5, 0.5, 0.25});
    QCOMPARE(signedErrors.meanAbsoluteError, magnitudes.meanAbsoluteError);
    QCOMPARE(signedErrors.standardDeviation, magnitudes.standardDeviation);
    QCOMPARE(signedErrors.minimum, 0.25);
    QCOMPARE(signedErrors.maximum, 5.0);
    QVERIFY2(closeAbs(signedErrors.meanAbsoluteError, 9.25 / 5.0, 1e-15),
             describe("MAE", signedErrors.meanAbsoluteError, 9.25 / 5.0));
}

void TestStatistics::summarizeErrors_matchesBruteForceOnLargeOffsetSample() {
    // A large common offset defeats the one-pass sum-of-squares formula; compare against a plain
    // two-pass computation in long double.
    std::mt19937 rng(20240611u);
    std::uniform_real_distribution<double> noise(-3.0, 3.0);
    std::vector<double> errors;
    for (int i = 0; i < 1000; ++i) {
        errors.push_back((i % 2 == 0 ? 1.0 : -1.0) * (1e6 + noise(rng)));
    }
    long double sum = 0.0L;
    for (double e : errors) {
        sum += std::abs(static_cast<long double>(e));
    }
    const long double meanRef = sum / errors.size();
    long double squares = 0.0L;
    for (double e : errors) {
        const long double d = std::abs(static_cast<long double>(e)) - meanRef;
        squares += d * d;
    }
    const double varianceRef = static_cast<double>(squares / (errors.size() - 1));

    const ErrorSummary s = summarizeErrors(errors);
    QCOMPARE(s.count, 1000);
    QVERIFY2(closeAbs(s.meanAbsoluteError, static_cast<double>(meanRef), 1e-9),
             describe("MAE", s.meanAbsoluteError, static_cast<double>(meanRef)));
    QVERIFY2(std::abs(s.variance - varianceRef) <= 1e-9 * varianceRef,
             describe("variance", s.variance, varianceRef));
}

void TestStatistics::summarizeErrors_varianceIsStandardDeviationSquared() {
    // Table I reports the variance as the square of the std beside it (2.17^2 = 4.71 cm^2 etc.).
    std::mt19937 rng(7u);
    std::normal_distribution<double> normal(0.0, 28.0);
    std::vector<double> errors;
    for (int i = 0; i < 37; ++i) {
        errors.push_back(normal(rng));
    }
    const ErrorSummary s = summarizeErrors(errors);
    QVERIFY(s.variance > 0.0);
    QVERIFY2(std::abs(s.variance - s.standardDeviation * s.standardDeviation) <= 1e-15 * s.variance,
             describe("variance vs std^2", s.variance, s.standardDeviation * s.standardDeviation));
}

void TestStatistics::summarizeErrors_skipsAndCountsNonFinite() {
    const ErrorSummary s = summarizeErrors({1.0, kNaN, -2.0, kInf, 3.0, -kInf, 4.0});
    QCOMPARE(s.count, 4);
    QCOMPARE(s.nonFinite, 3);
    QVERIFY2(closeAbs(s.meanAbsoluteError, 2.5, 1e-15), describe("MAE", s.meanAbsoluteError, 2.5));
    QVERIFY2(closeAbs(s.variance, 5.0 / 3.0, 1e-15), describe("variance", s.variance, 5.0 / 3.0));
    QCOMPARE(s.maximum, 4.0);
}

void TestStatistics::summarizeErrors_singleValueHasZeroSpread() {
    const ErrorSummary s = summarizeErrors({-7.5});
    QCOMPARE(s.count, 1);
    QCOMPARE(s.meanAbsoluteError, 7.5);
    QCOMPARE(s.standardDeviation, 0.0);
    QCOMPARE(s.variance, 0.0);
    QCOMPARE(s.minimum, 7.5);
    QCOMPARE(s.maximum, 7.5);
}

void TestStatistics::summarizeErrors_emptyOrAllNonFiniteGivesNaN() {
    const ErrorSummary empty = summarizeErrors({});
    QCOMPARE(empty.count, 0);
    QCOMPARE(empty.nonFinite, 0);
    QVERIFY(std::isnan(empty.meanAbsoluteError));
    QVERIFY(std::isnan(empty.standardDeviation));
    QVERIFY(std::isnan(empty.variance));
    QVERIFY(std::isnan(empty.minimum));
    QVERIFY(std::isnan(empty.maximum));

    const ErrorSummary failed = summarizeErrors({kNaN, kInf});
    QCOMPARE(failed.count, 0);
    QCOMPARE(failed.nonFinite, 2);
    QVERIFY(std::isnan(failed.meanAbsoluteError));
    QVERIFY(std::isnan(failed.variance));
}

void TestStatistics::meanAndSampleVariance_matchHandValuesAndSkipNonFinite() {
    // Signed values are kept signed here: {-1, 2, 3, 4} has mean 2 and squared deviations
    // 9 + 0 + 1 + 4 = 14, sample variance 14 / 3.
    QVERIFY2(closeAbs(mean({-1.0, 2.0, 3.0, 4.0}), 2.0, 1e-15),
             describe("mean", mean({-1.0, 2.0, 3.0, 4.0}), 2.0));
    QVERIFY2(closeAbs(sampleVariance({-1.0, 2.0, kNaN, 3.0, 4.0}), 14.0 / 3.0, 1e-14),
             describe("variance", sampleVariance({-1.0, 2.0, kNaN, 3.0, 4.0}), 14.0 / 3.0));
    QCOMPARE(mean({kInf, 6.0}), 6.0);
    QCOMPARE(sampleVariance({6.0}), 0.0);
    QVERIFY(std::isnan(mean({})));
    QVERIFY(std::isnan(sampleVariance({kNaN})));
}

void TestStatistics::studentT_matchesTabulatedValues_data() {
    QTest::addColumn<double>("probability");
    QTest::addColumn<int>("dof");
    QTest::addColumn<double>("expected");
    // Reference values: the 0.975 rows are the widely tabulated double-precision values; the
    // others were computed at 40 significant digits in arbitrary-precision arithmetic. For (0.95,
    // 10) the sometimes quoted 1.8124611228107335 is off by 9e-13, as the even-dof closed-form CDF
    // confirms.
    QTest::newRow("0.975, 1") << 0.975 << 1 << 12.706204736174707;
    QTest::newRow("0.975, 2") << 0.975 << 2 << 4.302652729749464;
    QTest::newRow("0.975, 7") << 0.975 << 7 << 2.3646242515927847;
    QTest::newRow("0.975, 19") << 0.975 << 19 << 2.0930240544083096;
    QTest::newRow("0.95, 10") << 0.95 << 10 << 1.8124611228116759;
    QTest::newRow("0.995, 30") << 0.995 << 30 << 2.749995653567225;
    QTest::newRow("0.9, 5") << 0.9 << 5 << 1.4758840488244813;
}

void TestStatistics::studentT_matchesTabulatedValues() {
    QFETCH(double, probability);
    QFETCH(int, dof);
    QFETCH(double, expected);
    const double t = studentTQuantile(probability, dof);
    QVERIFY2(std::abs(t - expected) <= 1e-12 * expected, describe("quantile", t, expected));
}

void TestStatistics::studentT_matchesClosedFormsForOneAndTwoDegrees() {
    // dof 1 is the Cauchy distribution, t = tan(pi (p - 1/2));
    // dof 2 has t = (2p - 1) / sqrt(2p (1 - p)).
    for (int i = 1; i < 200; ++i) {
        const double p = i / 200.0;
        const double cauchy = std::tan(kPi * (p - 0.5));
        const double two = (2.0 * p - 1.0) / std::sqrt(2.0 * p * (1.0 - p));
        const double t1 = studentTQuantile(p, 1);
        const double t2 = studentTQuantile(p, 2);
        QVERIFY2(std::abs(t1 - cauchy) <= 1e-12 * std::max(1.0, std::abs(cauchy)),
                 describe(qPrintable(QStringLiteral("dof 1, p %1").arg(p)), t1, cauchy));
        QVERIFY2(std::abs(t2 - two) <= 1e-12 * std::max(1.0, std::abs(two)),
                 describe(qPrintable(QStringLiteral("dof 2, p %1").arg(p)), t2, two));
    }
}

void TestStatistics::studentT_medianIsExactlyZero() {
    for (int dof : {1, 2, 3, 10, 100, 1000000}) {
        QCOMPARE(studentTQuantile(0.5, dof), 0.0);
        QCOMPARE(studentTCdf(0.0, dof), 0.5);
    }
}

void TestStatistics::studentT_isAntisymmetric() {
    for (int dof : {1, 2, 5, 19, 200}) {
        for (double p : {0.001, 0.025, 0.05, 0.1, 0.3, 0.45}) {
            const double lowerQ = studentTQuantile(p, dof);
            const double upperQ = studentTQuantile(1.0 - p, dof);
            QVERIFY(lowerQ < 0.0);
            QVERIFY2(std::abs(upperQ + lowerQ) <= 1e-12 * std::abs(upperQ),
                     describe(qPrintable(QStringLiteral("dof %1, p %2").arg(dof).arg(p)), upperQ,
                              -lowerQ));
        }
    }
}

void TestStatistics::studentT_decreasesTowardsNormalAsDegreesGrow() {
    const double normal975 = 1.959963984540054;
    double previous = studentTQuantile(0.975, 1);
    for (int dof = 2; dof <= 300; ++dof) {
        const double t = studentTQuantile(0.975, dof);
        QVERIFY2(t < previous && t > normal975, qPrintable(QStringLiteral("dof %1: %2 after %3")
                                                               .arg(dof)
                                                               .arg(t, 0, 'g', 17)
                                                               .arg(previous, 0, 'g', 17)));
        previous = t;
    }
    const double large = studentTQuantile(0.975, 1000000);
    QVERIFY2(std::abs(large - normal975) <= 1e-5, describe("dof 1e6", large, normal975));
    // First-order Cornish-Fisher: t = z + (z^3 + z) / (4 dof) + O(dof^-2); the first-order term
    // is 2.9e-6, the next about 1e-12. Eigen's incomplete beta forms ln Gamma(5e5) (about 6e6)
    // and so carries about 1e-10 of relative error at this dof, far below what a 95% interval
    // needs.
    const double expansion = normal975 + (std::pow(normal975, 3) + normal975) / 4e6;
    QVERIFY2(std::abs(large - expansion) <= 1e-9, describe("dof 1e6 expansion", large, expansion));
}

void TestStatistics::studentT_cdfMatchesClosedFormsAndInvertsQuantile() {
    for (double t : {-30.0, -4.0, -1.0, -0.1, 0.0, 0.3, 1.0, 2.5, 12.0, 1e4}) {
        const double cauchy = 0.5 + std::atan(t) / kPi;
        const double two = 0.5 + t / (2.0 * std::sqrt(2.0 + t * t));
        QVERIFY2(closeAbs(studentTCdf(t, 1), cauchy, 1e-15),
                 describe("cdf dof 1", studentTCdf(t, 1), cauchy));
        QVERIFY2(closeAbs(studentTCdf(t, 2), two, 1e-15),
                 describe("cdf dof 2", studentTCdf(t, 2), two));
    }
    for (int dof : {1, 3, 8, 25, 99, 4000}) {
        for (double p : {1e-9, 0.01, 0.2, 0.5, 0.7, 0.975, 0.999}) {
            const double back = studentTCdf(studentTQuantile(p, dof), dof);
            // The CDF is I_x(k/2, 1/2) of a double x = k / (k + t^2): as x moves by one ulp,
            // x^(k/2) moves by (k/2) eps, so at large k it is a staircase of that relative step.
            const double resolution = std::max(1e-14, dof * 1.2e-16);
            QVERIFY2(
                std::abs(back - p) <= resolution * std::max(p, 1e-3),
                describe(qPrintable(QStringLiteral("cdf(quantile) dof %1").arg(dof)), back, p));
        }
    }
    QCOMPARE(studentTCdf(kInf, 4), 1.0);
    QCOMPARE(studentTCdf(-kInf, 4), 0.0);
    QVERIFY(std::isnan(studentTCdf(kNaN, 4)));
}

void TestStatistics::studentT_reachesFarTailWithoutOverflow() {
    // Cauchy: t(p) = -cot(pi p) ~ -1 / (pi p); at p = 1e-300 t^2 would overflow a double.
    const double p = 1e-300;
    const double expected = -1.0 / (kPi * p);
    const double t = studentTQuantile(p, 1);
    QVERIFY2(std::abs(t - expected) <= 1e-12 * std::abs(expected),
             describe("far tail", t, expected));
    QVERIFY2(std::abs(studentTCdf(t, 1) - p) <= 1e-12 * p,
             describe("cdf far tail", studentTCdf(t, 1), p));
}

void TestStatistics::studentT_handlesBoundsAndRejectsInvalidArguments() {
    QCOMPARE(studentTQuantile(0.0, 3), -kInf);
    QCOMPARE(studentTQuantile(1.0, 3), kInf);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, studentTQuantile(0.975, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, studentTQuantile(-0.1, 3));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, studentTQuantile(1.5, 3));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, studentTQuantile(kNaN, 3));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, studentTCdf(1.0, -2));
}

void TestStatistics::confidenceBand_matchesHandComputedRaggedRuns() {
    // Point 0: {1, 3, 5}; point 1: {2, 4, 6}; both mean +- t(0.975, 2) * 2 / sqrt(3).
    // Point 2: only run 0 (run 1 is short, run 2 is NaN) -> collapses to 3.
    // Point 3: run 0 is NaN and nobody else reaches it -> count 0, NaN.
    const std::vector<std::vector<double>> runs = {
        {1.0, 2.0, 3.0, kNaN},
        {3.0, 4.0},
        {5.0, 6.0, kNaN},
    };
    const ConfidenceBand band = confidenceBand(runs);
    QCOMPARE(band.mean.size(), std::size_t(4));
    QCOMPARE(band.lower.size(), std::size_t(4));
    QCOMPARE(band.upper.size(), std::size_t(4));
    QCOMPARE(band.standardDeviation.size(), std::size_t(4));
    QCOMPARE(band.count, (std::vector<int>{3, 3, 1, 0}));

    const double half = 4.302652729749464 * 2.0 / std::sqrt(3.0);
    const double means[] = {3.0, 4.0};
    for (int i = 0; i < 2; ++i) {
        QVERIFY2(closeAbs(band.mean[i], means[i], 1e-14), describe("mean", band.mean[i], means[i]));
        QVERIFY2(closeAbs(band.standardDeviation[i], 2.0, 1e-14),
                 describe("std", band.standardDeviation[i], 2.0));
        QVERIFY2(closeAbs(band.lower[i], means[i] - half, 1e-12),
                 describe("lower", band.lower[i], means[i] - half));
        QVERIFY2(closeAbs(band.upper[i], means[i] + half, 1e-12),
                 describe("upper", band.upper[i], means[i] + half));
    }
    QCOMPARE(band.mean[2], 3.0);
    QCOMPARE(band.lower[2], 3.0);
    QCOMPARE(band.upper[2], 3.0);
    QCOMPARE(band.standardDeviation[2], 0.0);
    QVERIFY(std::isnan(band.mean[3]));
    QVERIFY(std::isnan(band.lower[3]));
    QVERIFY(std::isnan(band.upper[3]));
    QVERIFY(std::isnan(band.standardDeviation[3]));
}

void TestStatistics::confidenceBand_coversTrueMeanAtNominalRate() {
    // With N = 5 runs the t band covers the true mean 95% of the time; a normal (z = 1.96) band
    // would cover only ~88%, so this checks that the t quantile with N - 1 dof is the one used.
    std::mt19937 rng(12345u);
    std::normal_distribution<double> normal(10.0, 3.0);
    const int runsPerBand = 5;
    const int points = 4000;
    std::vector<std::vector<double>> runs(runsPerBand, std::vector<double>(points));
    for (auto& run : runs) {
        for (double& v : run) {
            v = normal(rng);
        }
    }
    const ConfidenceBand band = confidenceBand(runs, 0.95);
    int covered = 0;
    for (int i = 0; i < points; ++i) {
        if (band.lower[i] <= 10.0 && 10.0 <= band.upper[i]) {
            ++covered;
        }
    }
    const double rate = double(covered) / points;
    const double sigma = std::sqrt(0.95 * 0.05 / points);  // binomial spread of the rate
    QVERIFY2(
        std::abs(rate - 0.95) <= 4.0 * sigma,
        qPrintable(QStringLiteral("coverage %1, expected 0.95 +- %2").arg(rate).arg(4 * sigma)));
}

void TestStatistics::confidenceBand_widensWithLevelAndRejectsInvalidLevel() {
    const std::vector<std::vector<double>> runs = {{1.0, 5.0}, {2.0, 5.5}, {4.0, 7.0}};
    const ConfidenceBand b95 = confidenceBand(runs, 0.95);
    const ConfidenceBand b99 = confidenceBand(runs, 0.99);
    for (std::size_t i = 0; i < 2; ++i) {
        QCOMPARE(b99.mean[i], b95.mean[i]);
        QVERIFY(b99.upper[i] - b99.lower[i] > b95.upper[i] - b95.lower[i]);
        const double ratio = (b99.upper[i] - b99.lower[i]) / (b95.upper[i] - b95.lower[i]);
        const double expected = studentTQuantile(0.995, 2) / studentTQuantile(0.975, 2);
        QVERIFY2(closeRel(ratio, expected, 1e-12), describe("width ratio", ratio, expected));
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, confidenceBand(runs, 0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, confidenceBand(runs, 1.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, confidenceBand(runs, 95.0));
}

void TestStatistics::confidenceBand_noRunsGivesEmptyBand() {
    const ConfidenceBand none = confidenceBand({});
    QVERIFY(none.mean.empty());
    QVERIFY(none.count.empty());
    const ConfidenceBand emptyRuns = confidenceBand({{}, {}});
    QVERIFY(emptyRuns.upper.empty());
}

QTEST_GUILESS_MAIN(TestStatistics)
#include "test_statistics.moc"
