// The plant catalog: one entry per plant, everything the front ends need from it consistent.
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"
#include "sim/run/TaskCheck.h"
#include "sim/tuning/MethodTuning.h"

#include <QSet>
#include <QtTest>
#include <cstring>
#include <limits>

using namespace prisca::sim;

class TestPlantCatalog : public QObject {
    Q_OBJECT
  private slots:
    // A start state outside what a plant holds is refused by name before the physics engine
    // sees it (which would abort on an assertion); the bound itself is accepted.
    void resetTo_refusesStatesOutsideThePlantsBounds() {
        for (const PlantEntry& entry : PlantCatalog::all()) {
            auto plant = PlantCatalog::create(entry.name);
            const PlantInfo info = plant->info();
            const int n = info.stateDimension();
            for (int i = 0; i < n; ++i) {
                for (double bad : {1e300, -1e300, 1.01 * info.stateBound(i),
                                   std::numeric_limits<double>::quiet_NaN()}) {
                    Eigen::VectorXd state = Eigen::VectorXd::Zero(n);
                    state[i] = bad;
                    const QString problem = info.stateProblem(state);
                    QVERIFY2(problem.startsWith(info.stateNames[i] + " = "),
                             qPrintable(entry.name + ": " + problem));
                    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, plant->resetTo(state));
                }
                Eigen::VectorXd edge = Eigen::VectorXd::Zero(n);
                edge[i] = info.stateBound(i) * 0.5;
                QVERIFY2(info.stateProblem(edge).isEmpty(), qPrintable(entry.name));
                const Eigen::VectorXd started = plant->resetTo(edge);
                QVERIFY(started.allFinite());
                QVERIFY(plant->step(Eigen::VectorXd::Zero(info.actionDimension())).allFinite());
            }
            QVERIFY(!info.stateProblem(Eigen::VectorXd::Zero(n + 1)).isEmpty());
        }
    }

    void everyEntry_isConsistentWithItsTuningAndStyles() {
        QSet<QString> names;
        QVERIFY(PlantCatalog::all().size() >= 3);
        for (const PlantEntry& entry : PlantCatalog::all()) {
            QVERIFY2(!names.contains(entry.name), qPrintable(entry.name));
            names.insert(entry.name);
            QVERIFY(std::strlen(entry.displayName) > 0);
            QVERIFY(entry.create && entry.describe && entry.profile);
            const PlantInfo info = entry.describe();
            QCOMPARE(info.name, entry.name);
            auto plant = PlantCatalog::create(entry.name);
            QCOMPARE(plant->info().name, entry.name);
            QCOMPARE(plant->info().stateDimension(), info.stateDimension());
            QCOMPARE(plant->info().actionDimension(), info.actionDimension());
            // Its profile's sign model is m x n for this plant.
            const MethodTuning profile = PlantCatalog::tuning(info);
            QCOMPARE(profile.mapping.controls(), info.actionDimension());
            QCOMPARE(profile.mapping.states(), info.stateDimension());
            // Its styles record demonstrations of it; the first is the classic one.
            const QStringList styles = DemonstrationStyles::names(entry.name);
            QVERIFY2(!styles.isEmpty(), qPrintable(entry.name));
            QCOMPARE(DemonstrationStyles::classic(entry.name), styles.front());
            const prisca::core::Demonstration demo = PlantCatalog::demonstrate(entry.name, 3);
            QCOMPARE(demo.plant, entry.name);
            QCOMPARE(static_cast<int>(demo.states.cols()), info.stateDimension());
            QCOMPARE(static_cast<int>(demo.actions.cols()), info.actionDimension());
            QCOMPARE(demo.metadata.value("style"), styles.front());
            // Planar vehicles have a pose; the arm is drawn as one and has none.
            QCOMPARE(entry.drawing == PlantEntry::Drawing::Arm, !info.pose.has_value());
        }
    }

    void demonstrationCheck_namesWhatDoesNotFit() {
        const PlantInfo aircraft = PlantCatalog::describe("aircraft");
        const auto refused = [&](const prisca::core::Demonstration& d, const char* words) {
            try {
                checkDemonstrationFor(d, aircraft);
            } catch (const std::invalid_argument& e) {
                return QString::fromStdString(e.what()).contains(QString::fromLatin1(words));
            }
            return false;
        };
        prisca::core::Demonstration good = PlantCatalog::demonstrate("aircraft", 4);
        checkDemonstrationFor(good, aircraft);  // no throw
        QVERIFY(refused(PlantCatalog::demonstrate("slidecar", 4), "recorded on 'slidecar'"));
        prisca::core::Demonstration untagged = PlantCatalog::demonstrate("slidecar", 4);
        untagged.plant.clear();  // same column count, other names
        QVERIFY(refused(untagged, "throttle"));
        prisca::core::Demonstration tooShort = good;
        tooShort.states.conservativeResize(3, Eigen::NoChange);
        tooShort.actions.conservativeResize(3, Eigen::NoChange);
        tooShort.time.conservativeResize(3);
        QVERIFY(refused(tooShort, "3 samples; at least 4"));
    }

    void unknownPlant_namesTheKnownOnes() {
        QCOMPARE(PlantCatalog::find("hovercraft"), nullptr);
        QVERIFY(DemonstrationStyles::of("hovercraft").empty());
        for (auto call : {+[] { PlantCatalog::create("hovercraft"); },
                          +[] { PlantCatalog::describe("hovercraft"); },
                          +[] { DemonstrationStyles::record("hovercraft", "any", 1); }}) {
            try {
                call();
                QFAIL("no exception");
            } catch (const std::invalid_argument& e) {
                QVERIFY2(QString::fromStdString(e.what()).contains("hovercraft"), e.what());
            }
        }
        try {
            PlantCatalog::create("hovercraft");
        } catch (const std::invalid_argument& e) {
            QVERIFY2(QString::fromStdString(e.what()).contains("slidecar acrobot aircraft"),
                     e.what());
        }
    }
};

QTEST_APPLESS_MAIN(TestPlantCatalog)
#include "test_plant_catalog.moc"
