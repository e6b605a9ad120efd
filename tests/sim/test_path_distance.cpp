// The indexed distance to a demonstrated path against the brute force (distanceToPath), bit for
// bit: random paths and query points near, on and far off them, and the degenerate paths.
#include "sim/episodes/PathDistance.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/plants/SlideCar.h"

#include <QtTest>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace prisca;
using namespace prisca::sim;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
}

// A slide-car demonstration whose positions are the given vertices.
core::Demonstration demonstrationThrough(const std::vector<double>& xs,
                                         const std::vector<double>& ys) {
    const PlantInfo info = SlideCar::describe();
    core::Demonstration demo;
    demo.dt = 0.025;
    demo.states =
        Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(xs.size()), info.stateDimension());
    demo.actions = Eigen::MatrixXd::Zero(demo.states.rows(), info.actionDimension());
    for (size_t j = 0; j < xs.size(); ++j) {
        demo.states(static_cast<Eigen::Index>(j), info.pose->x) = xs[j];
        demo.states(static_cast<Eigen::Index>(j), info.pose->y) = ys[j];
    }
    return demo;
}

// Compares the index with the brute force at every query point; returns the first mismatch.
QString mismatch(const std::vector<double>& xs, const std::vector<double>& ys,
                 const std::vector<std::pair<double, double>>& queries) {
    const PlantInfo info = SlideCar::describe();
    const core::Demonstration demo = demonstrationThrough(xs, ys);
    const PathDistance index(xs, ys);
    const PathDistance fromDemonstration(info, demo);
    for (const auto& [x, y] : queries) {
        const double expected = distanceToPath(info, demo, x, y);
        const double indexed = index.distance(x, y);
        const double viaDemonstration = fromDemonstration.distance(x, y);
        if (!sameBits(indexed, expected) || !sameBits(viaDemonstration, expected)) {
            return QStringLiteral("path of %1 vertices, query (%2, %3): brute force %4, index %5")
                .arg(xs.size())
                .arg(x, 0, 'g', 17)
                .arg(y, 0, 'g', 17)
                .arg(expected, 0, 'g', 17)
                .arg(indexed, 0, 'g', 17);
        }
    }
    return {};
}

// Query points of every kind around a path: on its vertices, near them, on its segments, in its
// bounding box, and far outside it (up to a thousand boxes away).
std::vector<std::pair<double, double>> queriesAround(const std::vector<double>& xs,
                                                     const std::vector<double>& ys,
                                                     std::mt19937_64& random, int count) {
    const auto [minX, maxX] = std::minmax_element(xs.begin(), xs.end());
    const auto [minY, maxY] = std::minmax_element(ys.begin(), ys.end());
    const double cx = 0.5 * (*minX + *maxX), cy = 0.5 * (*minY + *maxY);
    const double size = std::max({*maxX - *minX, *maxY - *minY, 1e-3 * (1.0 + std::abs(cx))});
    std::uniform_int_distribution<size_t> vertex(0, xs.size() - 1);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<std::pair<double, double>> queries;
    for (int i = 0; i < count; ++i) {
        const size_t j = vertex(random);
        const size_t k = std::min(j + 1, xs.size() - 1);
        switch (i % 5) {
            case 0:
                queries.emplace_back(xs[j], ys[j]);
                break;
            case 1:
                queries.emplace_back(xs[j] + 0.01 * size * unit(random),
                                     ys[j] + 0.01 * size * unit(random));
                break;
            case 2: {
                const double s = 0.5 * (unit(random) + 1.0);
                queries.emplace_back(xs[j] + s * (xs[k] - xs[j]), ys[j] + s * (ys[k] - ys[j]));
                break;
            }
            case 3:
                queries.emplace_back(cx + 0.6 * size * unit(random),
                                     cy + 0.6 * size * unit(random));
                break;
            default:
                queries.emplace_back(cx + 1000.0 * size * unit(random),
                                     cy + 1000.0 * size * unit(random));
                break;
        }
    }
    return queries;
}

}  // namespace

class TestPathDistance : public QObject {
    Q_OBJECT

  private slots:
    void randomPaths_equalTheBruteForceBitForBit() {
        std::mt19937_64 random(23);
        std::uniform_int_distribution<int> length(1, 3000);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        for (int path = 0; path < 120; ++path) {
            const int T = path < 10 ? path + 1 : length(random);
            std::vector<double> xs(T), ys(T);
            double x = 10.0 * unit(random), y = 10.0 * unit(random), heading = 0.0;
            for (int j = 0; j < T; ++j) {
                switch (path % 4) {
                    case 0:  // a car: smooth heading, small steps, loops that cross themselves
                        heading += 0.2 * unit(random);
                        x += 0.02 * std::cos(heading);
                        y += 0.02 * std::sin(heading);
                        break;
                    case 1:  // a random walk
                        x += unit(random);
                        y += unit(random);
                        break;
                    case 2:  // scattered points: every segment crosses the box
                        x = 100.0 * unit(random);
                        y = 100.0 * unit(random);
                        break;
                    default:  // on a coarse lattice: repeated vertices, overlapping segments
                        x = std::round(3.0 * unit(random));
                        y = std::round(3.0 * unit(random));
                        break;
                }
                xs[j] = x;
                ys[j] = y;
            }
            const QString failure = mismatch(xs, ys, queriesAround(xs, ys, random, 200));
            QVERIFY2(failure.isEmpty(), qPrintable(failure));
        }
    }

    void oneSampleOrAllEqual_isTheDistanceToThatPoint() {
        std::mt19937_64 random(2);
        for (int T : {1, 2, 9, 50}) {
            const std::vector<double> xs(T, 1.5), ys(T, -2.0);
            const QString failure = mismatch(xs, ys, queriesAround(xs, ys, random, 100));
            QVERIFY2(failure.isEmpty(), qPrintable(failure));
            QCOMPARE(PathDistance(xs, ys).distance(4.5, 2.0), 5.0);
        }
    }

    void pathAlongOneAxis_zeroWidthBox() {
        std::mt19937_64 random(3);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        std::vector<double> along(500), across(500, 0.25);
        for (size_t j = 0; j < along.size(); ++j) {
            along[j] = j % 100 < 50 ? 0.1 * (j % 50) : 0.1 * (50 - j % 50);  // back and forth
        }
        for (const bool alongX : {true, false}) {
            const std::vector<double>& xs = alongX ? along : across;
            const std::vector<double>& ys = alongX ? across : along;
            const QString failure = mismatch(xs, ys, queriesAround(xs, ys, random, 500));
            QVERIFY2(failure.isEmpty(), qPrintable(failure));
        }
        QCOMPARE(PathDistance(along, across).distance(2.0, 1.25), 1.0);
    }

    void hugeAndTinyCoordinates_equalTheBruteForce() {
        std::mt19937_64 random(4);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        // Far from the origin with centimetre steps (x - ax cancels), at scales where the
        // formula's squares overflow, and at subnormal scales where they underflow.
        const std::vector<std::pair<double, double>> cases{
            {1e6, 0.01}, {1e12, 0.01}, {1e150, 1e148}, {1e300, 1e299}, {0.0, 1e-310}};
        for (const auto& [offset, step] : cases) {
            std::vector<double> xs(400), ys(400);
            double x = offset, y = -offset;
            for (size_t j = 0; j < xs.size(); ++j) {
                x += step * unit(random);
                y += step * unit(random);
                xs[j] = x;
                ys[j] = y;
            }
            const QString failure = mismatch(xs, ys, queriesAround(xs, ys, random, 300));
            QVERIFY2(failure.isEmpty(), qPrintable(failure));
        }
    }

    void nanQuery_isNaN_infiniteQuery_asTheBruteForce() {
        const std::vector<double> xs{0.0, 1.0, 1.0}, ys{0.0, 0.0, 1.0};
        const PathDistance index(xs, ys);
        QVERIFY(std::isnan(index.distance(kNaN, 0.0)));
        QVERIFY(std::isnan(index.distance(0.0, kNaN)));
        const QString failure =
            mismatch(xs, ys, {{kNaN, 0.0}, {0.0, kNaN}, {kInf, 0.0}, {-kInf, kInf}, {0.5, -kInf}});
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
    }

    void emptyOrNonFinitePath_asTheBruteForce() {
        QCOMPARE(PathDistance(std::vector<double>{}, std::vector<double>{}).distance(1.0, 2.0),
                 kInf);
        const std::vector<double> xs{0.0, 1.0, kNaN, 2.0, kInf, 3.0},
            ys{0.0, 0.0, 1.0, 1.0, 2.0, 2.0};
        const std::vector<std::pair<double, double>> queries{
            {0.5, 0.1}, {2.5, 1.5}, {3.0, 3.0}, {-5.0, 0.0}, {1.0, 0.5}};
        const QString failure = mismatch(xs, ys, queries);
        QVERIFY2(failure.isEmpty(), qPrintable(failure));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 PathDistance(std::vector<double>{0.0}, std::vector<double>{}));
    }

    void summarizeTrial_pathRmsIsTheBruteForceRms() {
        // A path and a trial that wanders around it: the summary's RMS, step by step by hand.
        const PlantInfo info = SlideCar::describe();
        std::vector<double> xs(2000), ys(2000);
        for (size_t j = 0; j < xs.size(); ++j) {
            xs[j] = 3.0 * std::sin(0.004 * j);
            ys[j] = 2.0 * std::sin(0.009 * j);
        }
        const core::Demonstration demo = demonstrationThrough(xs, ys);
        EpisodeResult result;
        double sum = 0.0;
        for (int k = 0; k < 2500; ++k) {
            StepRecord step;
            step.state = Eigen::VectorXd::Zero(info.stateDimension());
            step.state[info.pose->x] = 3.1 * std::sin(0.0035 * k) + 0.01 * std::cos(0.1 * k);
            step.state[info.pose->y] = 1.9 * std::sin(0.0085 * k);
            const double d =
                distanceToPath(info, demo, step.state[info.pose->x], step.state[info.pose->y]);
            sum += d * d;
            result.steps.push_back(step);
        }
        result.finalState = result.steps.back().state;
        const TrialSummary summary = summarizeTrial(info, demo, result);
        QVERIFY(sameBits(summary.pathRms, std::sqrt(sum / 2500.0)));
    }
};

QTEST_APPLESS_MAIN(TestPathDistance)
#include "test_path_distance.moc"
