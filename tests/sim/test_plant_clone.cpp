// Plant::clone(): a copy of a trial's plant continues exactly as the plant does (the oracle's
// foresight), and without actuator noise it applies its actions as given.
#include "sim/PlantCatalog.h"

#include <QtTest>

#include <random>

using namespace prisca::sim;

namespace {

// Random but smooth actions within the plant's limits.
std::vector<Eigen::VectorXd> actions(const PlantInfo& info, int steps, std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<Eigen::VectorXd> out;
    Eigen::VectorXd u = 0.5 * (info.actionLower + info.actionUpper);
    for (int k = 0; k < steps; ++k) {
        for (int l = 0; l < u.size(); ++l) {
            const double target =
                info.actionLower[l] + uniform(random) * (info.actionUpper[l] - info.actionLower[l]);
            u[l] += 0.2 * (target - u[l]);
        }
        out.push_back(u);
    }
    return out;
}

}  // namespace

class TestPlantClone : public QObject {
    Q_OBJECT
  private slots:
    void clone_withNoiseContinuesAsThePlantDoes_data() {
        QTest::addColumn<QString>("plant");
        QTest::addColumn<double>("tolerance");
        // One body without contacts: bit for bit. The acrobot's joints restart their solver's
        // warm start in the copy: equal to the solver's tolerance.
        QTest::newRow("slidecar") << "slidecar" << 0.0;
        QTest::newRow("aircraft") << "aircraft" << 0.0;
        QTest::newRow("acrobot") << "acrobot" << 1e-4;
    }
    void clone_withNoiseContinuesAsThePlantDoes() {
        QFETCH(QString, plant);
        QFETCH(double, tolerance);
        auto original = PlantCatalog::create(plant);
        original->reset(7, Perturbation::realistic());
        const auto u = actions(original->info(), 240, 3);
        for (int k = 0; k < 60; ++k) {
            original->step(u[k]);
        }
        auto copy = original->clone(true);
        QCOMPARE(copy->time(), original->time());
        QVERIFY((copy->state() - original->state()).cwiseAbs().maxCoeff() <= tolerance);
        for (int k = 60; k < 240; ++k) {
            const Eigen::VectorXd a = original->step(u[k]);
            const Eigen::VectorXd b = copy->step(u[k]);
            QVERIFY2((a - b).cwiseAbs().maxCoeff() <= std::max(tolerance, 0.0),
                     qPrintable(
                         QStringLiteral("step %1: %2").arg(k).arg((a - b).cwiseAbs().maxCoeff())));
        }
    }

    void clone_withoutNoiseFollowsTheNoiseFreeTwin() {
        // Two plants of the same trial, one with and one without actuator noise: the quiet copy
        // of the noisy one must move as the noise-free one does (same perturbed parameters).
        for (const QString& plant : {QStringLiteral("slidecar"), QStringLiteral("aircraft")}) {
            Perturbation noisy = Perturbation::realistic();
            Perturbation quiet = noisy;
            quiet.actuatorNoise = 0.0;
            auto a = PlantCatalog::create(plant);
            auto b = PlantCatalog::create(plant);
            a->reset(11, noisy);
            b->reset(11, quiet);
            auto copy = a->clone(false);
            const auto u = actions(a->info(), 120, 5);
            double differenceToNoisy = 0.0;
            for (const Eigen::VectorXd& action : u) {
                const Eigen::VectorXd s = copy->step(action);
                QCOMPARE(s, b->step(action));
                differenceToNoisy =
                    std::max(differenceToNoisy, (s - a->step(action)).cwiseAbs().maxCoeff());
            }
            QVERIFY2(differenceToNoisy > 1e-4, qPrintable(plant));  // the noise did act on a
        }
    }

    void clone_isIndependentOfTheOriginal() {
        auto original = PlantCatalog::create(QStringLiteral("slidecar"));
        original->reset(2, Perturbation::realistic());
        const Eigen::VectorXd before = original->state();
        auto copy = original->clone();
        Eigen::VectorXd full(2);
        full << 1.0, 1.0;
        for (int k = 0; k < 40; ++k) {
            copy->step(full);
        }
        QCOMPARE(original->state(), before);
        QVERIFY((copy->state() - before).norm() > 0.1);
    }
};

QTEST_APPLESS_MAIN(TestPlantClone)
#include "test_plant_clone.moc"
