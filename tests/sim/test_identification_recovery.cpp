// Identification of the slide-car: a car of known parameters recovered from its noise-free
// demonstration, a car whose static grips trade, and mpc's second search of a poor quick fit.
// About ten minutes of model runs: left out of the sanitizer builds, which run the
// identification's code through test_identification.
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"
#include "sim/demonstrations/SlideCarDemonstrator.h"
#include "sim/planning/Identification.h"
#include "sim/planning/MpcController.h"
#include "sim/plants/PlantParameters.h"
#include "sim/plants/SlideCar.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

using namespace prisca;
using namespace prisca::sim;

namespace {

// The catalog's slide-car with these values set.
PlantParameters catalogCarWith(std::initializer_list<std::pair<const char*, double>> values) {
    PlantParameters p = defaultPlantParameters("slidecar");
    const auto& specs = plantParameterSpecs("slidecar");
    for (const auto& [key, value] : values) {
        for (size_t i = 0; i < specs.size(); ++i) {
            if (specs[i].key == QLatin1String(key)) {
                p.values[i] = value;
            }
        }
    }
    return p;
}

// A car unlike the catalog's: less grip in the slide, a weaker motor, more inertia.
PlantParameters knownCar() {
    return catalogCarWith(
        {{"kineticFriction", 0.40}, {"maxDriveForce", 8.0}, {"yawInertia", 0.017}});
}

core::Demonstration demonstrationOf(const PlantParameters& car) {
    return SlideCarDemonstrator::record(1, SlideCarDemonstrator::Script{}, SimulationTiming{},
                                        slideCarParameters(car));
}

}  // namespace

class TestIdentificationRecovery : public QObject {
    Q_OBJECT
  private slots:
    // Noise-free, from the catalog's values as the prior: the three parameters in which the
    // car differs from the prior are identified within 2 %, every other parameter reported
    // identified within 5 % (measured: the driveline drag lands 1.4 % off, the rolling resistance
    // undetermined), and the model replays the demonstration to
    // within millimetres.
    void knownCar_recoveredFromItsDemonstration() {
        const PlantParameters truth = knownCar();
        const core::Demonstration demonstration = demonstrationOf(truth);
        IdentificationSettings settings;
        settings.restarts = 1;
        long long calls = 0;
        const IdentificationResult result =
            identifyPlant({demonstration}, defaultPlantParameters("slidecar"), settings,
                          [&](long long, long long) {
                              ++calls;
                              return true;
                          });
        QVERIFY2(result.ok(), qPrintable(result.refusal));
        QVERIFY(calls > 0);
        QVERIFY(result.segments.size() >= 4);
        QStringList identified;
        for (const IdentifiedParameter& p : result.table) {
            const double known = truth.value(p.key);
            if (!p.fitted) {
                QCOMPARE(p.value, p.prior);  // held: the mass and the geometry
                continue;
            }
            qInfo("%-18s %.5g (known %.5g, prior %.5g) +- %.2g %s", qPrintable(p.key), p.value,
                  known, p.prior, p.std, p.identified ? "identified" : "held");
            if (p.identified) {
                identified << p.key;
                const bool differs = p.prior != known;
                QVERIFY2(
                    std::abs(p.value - known) <= (differs ? 0.02 : 0.05) * std::abs(known),
                    qPrintable(
                        QStringLiteral("%1 = %2, known %3").arg(p.key).arg(p.value).arg(known)));
            } else {
                QCOMPARE(p.value, p.prior);
            }
        }
        for (const char* key : {"kineticFriction", "maxDriveForce", "yawInertia"}) {
            QVERIFY2(identified.contains(QLatin1String(key)), key);
        }
        QVERIFY2(result.positionRms < 0.005, qPrintable(QString::number(result.positionRms)));
        QVERIFY(result.positionRms < 0.5 * result.priorPositionRms);
        // The model's replay starts where the run starts and follows it.
        const Eigen::MatrixXd replay = replayRun(demonstration, result.parameters);
        QCOMPARE(replay.rows(), demonstration.length());
        QCOMPARE(replay.row(0), demonstration.states.row(0));
    }

    // A car whose static grips one slide hardly determines (they show only at the instants
    // the tyres break away, and front trades against rear): both are reported undetermined (on
    // this day's demonstration the rear one was reported identified 29 % off before segments
    // carried the tyres' sliding from one to the next and the profile check scanned the pair
    // over its range), and since the data reject their prior (the catalog's 0.65 where the car
    // has 0.50) they keep the values fitted with the rest, so that the motor and the top speed
    // are not bent to make up for a wrong static grip (they were, by 20-40 %, before the prior
    // was checked against the data). The operator's prior: measured mass and geometry, the
    // catalog's values for the rest.
    void tradedStaticGrips_priorRejected_theRestRecovered() {
        const PlantParameters truth = catalogCarWith({{"staticFriction", 0.5},
                                                      {"kineticFriction", 0.35},
                                                      {"rearStaticGrip", 0.76},
                                                      {"rearKineticGrip", 0.7429}});
        RecordingConditions conditions;
        conditions.parameters = &truth;
        const core::Demonstration demonstration = DemonstrationStyles::record(
            QStringLiteral("slidecar"), QStringLiteral("stick-180-left"), 301, SimulationTiming{},
            conditions);
        const IdentificationResult result = identifyPlant({demonstration}, measuredPrior(truth));
        QVERIFY2(result.ok(), qPrintable(result.refusal));
        QStringList identified;
        for (const IdentifiedParameter& p : result.table) {
            const double known = truth.value(p.key);
            if (p.identified) {
                identified << p.key;
                QVERIFY2(
                    std::abs(p.value - known) <= 0.10 * std::abs(known),
                    qPrintable(
                        QStringLiteral("%1 = %2, known %3").arg(p.key).arg(p.value).arg(known)));
            }
        }
        for (const char* key :
             {"kineticFriction", "rearKineticGrip", "maxDriveForce", "topSpeed"}) {
            QVERIFY2(identified.contains(QLatin1String(key)), key);
        }
        for (const char* key : {"staticFriction", "rearStaticGrip"}) {
            const auto grip = std::find_if(
                result.table.begin(), result.table.end(),
                [&](const IdentifiedParameter& p) { return p.key == QLatin1String(key); });
            QVERIFY(grip != result.table.end());
            QVERIFY2(!grip->identified, key);
        }
        const auto front = std::find_if(
            result.table.begin(), result.table.end(),
            [](const IdentifiedParameter& p) { return p.key == QLatin1String("staticFriction"); });
        QVERIFY2(front->value != front->prior, "the rejected prior was put back");
        QVERIFY2(result.positionRms < 0.005, qPrintable(QString::number(result.positionRms)));
    }

    // A quick identification that fits worse than poorFit is searched again with the thorough
    // budget, and the better model kept; one that fits well is not searched again.
    void poorQuickFit_isSearchedAgain() {
        const std::vector<core::Demonstration> data{PlantCatalog::demonstrate("slidecar", 1)};
        const PlantParameters prior =
            catalogCarWith({{"kineticFriction", 0.3}, {"maxDriveForce", 6.0}});
        MpcParameters p;
        p.identifyEvaluations = 8;
        p.retryEvaluations = 0;
        const IdentificationResult quick = identifyForMpc(data, prior, p);
        QVERIFY2(quick.ok(), qPrintable(quick.refusal));
        p.poorFit = quick.positionRms / 2.0;
        p.retryEvaluations = 24;
        const IdentificationResult again = identifyForMpc(data, prior, p);
        QVERIFY(again.ok());
        QVERIFY2(
            again.positionRms < quick.positionRms,
            qPrintable(
                QStringLiteral("%1 against %2").arg(again.positionRms).arg(quick.positionRms)));
        p.poorFit = 2.0 * quick.positionRms;
        const IdentificationResult kept = identifyForMpc(data, prior, p);
        QCOMPARE(kept.positionRms, quick.positionRms);
        QCOMPARE(kept.parameters.values, quick.parameters.values);
    }
};

QTEST_GUILESS_MAIN(TestIdentificationRecovery)
#include "test_identification_recovery.moc"
