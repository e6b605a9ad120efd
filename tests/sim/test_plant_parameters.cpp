// Plant files (the plants' physical parameters) and the lab-session perturbation model.
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"
#include "sim/plants/PlantParameters.h"
#include "sim/plants/SlideCar.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numeric>
#include <vector>

using namespace prisca::sim;

namespace {

QByteArray fileWith(const QString& plant, const QJsonObject& parameters) {
    return QJsonDocument(QJsonObject{{"plant", plant}, {"parameters", parameters}}).toJson();
}

std::optional<PlantParameters> parse(const QByteArray& json, QString* error,
                                     const QString& plant = QStringLiteral("slidecar")) {
    return parsePlantParameters(json, QStringLiteral("car.json"), plant, error);
}

// The car's trajectory under a fixed drive: full throttle for 1 s, then hard left.
Eigen::VectorXd driven(Plant& plant) {
    plant.resetTo(Eigen::VectorXd::Zero(plant.info().stateDimension()));
    Eigen::VectorXd state;
    for (int k = 0; k < 80; ++k) {
        state = plant.step(Eigen::Vector2d(k < 40 ? 1.0 : 0.3, k < 40 ? 0.0 : 1.0));
    }
    return state;
}

double mean(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

double stddev(const std::vector<double>& v) {
    const double m = mean(v);
    double s = 0.0;
    for (double x : v) {
        s += (x - m) * (x - m);
    }
    return std::sqrt(s / static_cast<double>(v.size() - 1));
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    const double ma = mean(a), mb = mean(b);
    double sab = 0.0, saa = 0.0, sbb = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / std::sqrt(saa * sbb);
}

Perturbation sessionTrial(std::uint64_t day, int index) {
    Perturbation p = Perturbation::realistic();
    p.model = Perturbation::Model::Session;
    p.day = day;
    p.trialIndex = index;
    return p;
}

}  // namespace

class TestPlantParameters : public QObject {
    Q_OBJECT
  private slots:
    // The plants a file can describe are the catalog's, in its order (PlantParameters keeps its
    // own table below the catalog), and an unknown one is named with them by both.
    void plants_areTheCatalogsInItsOrder() {
        QCOMPARE(plantParameterPlants(), PlantCatalog::names());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, plantParameterSpecs("boat"));
        try {
            makePlant(PlantParameters{QStringLiteral("boat"), {}, {}});
            QFAIL("a plant nobody declared was built");
        } catch (const std::invalid_argument& e) {
            QVERIFY2(QString::fromUtf8(e.what()).contains(PlantCatalog::names().join(' ')),
                     e.what());
        }
    }

    // Every plant declares its parameters, each default inside its own range, and the
    // catalog's values make exactly the catalog's plant.
    void specs_defaultsInRangeAndTheCatalogPlant() {
        for (const PlantEntry& entry : PlantCatalog::all()) {
            const auto& specs = plantParameterSpecs(entry.name);
            QVERIFY2(specs.size() >= 8, qPrintable(entry.name));
            for (const PlantParameterSpec& s : specs) {
                QVERIFY2(s.lower <= s.value && s.value <= s.upper,
                         qPrintable(entry.name + "." + s.key));
                QVERIFY2(!s.unit.isEmpty() && !s.description.isEmpty(), qPrintable(s.key));
            }
            const PlantParameters defaults = defaultPlantParameters(entry.name);
            QVERIFY(defaults.isCatalogPlant());
            QVERIFY2(plantParametersProblem(entry.name, defaults.values).isEmpty(),
                     qPrintable(plantParametersProblem(entry.name, defaults.values)));
            auto fromFile = PlantCatalog::create(defaults);
            auto catalog = PlantCatalog::create(entry.name);
            const int m = catalog->info().actionDimension();
            fromFile->reset(3, Perturbation::realistic());
            catalog->reset(3, Perturbation::realistic());
            for (int k = 0; k < 40; ++k) {
                const Eigen::VectorXd u = Eigen::VectorXd::Constant(m, 0.5);
                QCOMPARE(fromFile->step(u), catalog->step(u));
            }
        }
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, plantParameterSpecs("hovercraft"));
    }

    // The slide-car's file names what the issue lists: mass, inertia, wheelbase, centre of
    // gravity, grip front and rear (static and kinetic), motor, steering lock, servo, drags.
    void slideCar_declaresTheCarsPhysics() {
        QStringList keys;
        for (const PlantParameterSpec& s : plantParameterSpecs("slidecar")) {
            keys << s.key;
        }
        for (const char* key : {"mass", "yawInertia", "wheelbase", "cgForward", "cgHeight", "width",
                                "staticFriction", "kineticFriction", "rearStaticGrip",
                                "rearKineticGrip", "maxDriveForce", "topSpeed", "maxSteeringAngle",
                                "servoDelay", "servoRate", "rollingResistance", "drivelineDrag"}) {
            QVERIFY2(keys.contains(QLatin1String(key)), key);
        }
    }

    // Written with --print-params' JSON and read back: the same values, for every plant; a
    // changed value survives the round trip, and a file of a few keys keeps the others.
    void roundTrip_everyPlant() {
        for (const PlantEntry& entry : PlantCatalog::all()) {
            PlantParameters p = defaultPlantParameters(entry.name);
            const auto& specs = plantParameterSpecs(entry.name);
            p.values[0] = 0.5 * (specs[0].value + specs[0].upper);  // another valid value
            QString error;
            const auto back = parse(plantParametersJson(p), &error, entry.name);
            QVERIFY2(back, qPrintable(error));
            QCOMPARE(back->values, p.values);
            QCOMPARE(back->plant, entry.name);
            QVERIFY(!back->isCatalogPlant());
        }
        QString error;
        const auto partial = parse(fileWith("slidecar", {{"mass", 2.5}}), &error);
        QVERIFY2(partial, qPrintable(error));
        QCOMPARE(partial->value("mass"), 2.5);
        QCOMPARE(partial->value("wheelbase"), SlideCarParameters{}.wheelbase);
        QCOMPARE(partial->source, QStringLiteral("car.json"));
        // A value given with its unit object, as --print-params writes it.
        const auto withUnit = parse(
            fileWith("slidecar", {{"mass", QJsonObject{{"value", 1.9}, {"unit", "kg"}}}}), &error);
        QVERIFY2(withUnit, qPrintable(error));
        QCOMPARE(withUnit->value("mass"), 1.9);
    }

    // The reality gap: the slide-car's effects the identification model leaves out come in
    // their own group, each off on the catalog car, with a realistic value and its source; the
    // group reads back, and a model parameter put in it is refused.
    void unmodelled_groupedWithRealisticValuesAndReadBack() {
        int unmodelled = 0;
        for (const PlantParameterSpec& s : plantParameterSpecs("slidecar")) {
            if (!s.unmodelled) {
                continue;
            }
            ++unmodelled;
            QVERIFY2(s.realistic >= s.lower && s.realistic <= s.upper, qPrintable(s.key));
            // Off at the catalog's value (the patches' size is inert while their grip is 1).
            QVERIFY2(s.realistic != s.value || s.key == QLatin1String("patchSize"),
                     qPrintable(s.key));
            QVERIFY2(!s.realisticSource.isEmpty(), qPrintable(s.key));
        }
        QCOMPARE(unmodelled, 6);
        PlantParameters p = defaultPlantParameters("slidecar");
        const QJsonObject root = QJsonDocument::fromJson(plantParametersJson(p)).object();
        const QJsonObject group = root.value("unmodelled").toObject();
        QCOMPARE(group.value("tyreStiffness").toObject().value("off").toDouble(), 0.0);
        QVERIFY(group.value("tyreStiffness").toObject().value("realistic").toDouble() > 0.0);
        QVERIFY(!root.value("parameters").toObject().contains("tyreStiffness"));
        QVERIFY(root.value("parameters").toObject().contains("mass"));
        QString error;
        QJsonObject file{{"plant", "slidecar"},
                         {"parameters", QJsonObject{{"mass", 2.0}}},
                         {"unmodelled", QJsonObject{{"servoBacklash", 0.03}}}};
        const auto back = parse(QJsonDocument(file).toJson(), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->value("servoBacklash"), 0.03);
        QCOMPARE(back->value("mass"), 2.0);
        QVERIFY(!back->isCatalogPlant());
        file.insert("unmodelled", QJsonObject{{"mass", 2.0}});
        QVERIFY(!parse(QJsonDocument(file).toJson(), &error));
        QVERIFY2(error.contains("\"mass\" is not an unmodelled effect") &&
                     error.contains("tyreStiffness"),
                 qPrintable(error));
        file.insert("unmodelled", QJsonObject{{"patchFriction", 0.1}});
        QVERIFY(!parse(QJsonDocument(file).toJson(), &error));
        QVERIFY2(error.contains("patchFriction = 0.1 is outside [0.3, 1.5]"), qPrintable(error));
    }

    // Every refusal names the file and what is wrong: the key, the value and the range.
    void refusals_nameTheKeyTheValueAndTheRange() {
        struct Case {
            QByteArray json;
            QStringList expected;
        };
        const std::vector<Case> cases = {
            {fileWith("slidecar", {{"mass", 50.0}}),
             {"car.json", "mass = 50 kg is outside [0.3, 10] kg"}},
            {fileWith("slidecar", {{"mas", 1.0}}), {"unknown slidecar parameter \"mas\"", "mass"}},
            {fileWith("slidecar", {{"mass", "heavy"}}), {"mass is not a number"}},
            {fileWith("slidecar", {{"mass", QJsonObject{{"value", 1.5}, {"unit", "lb"}}}}),
             {"mass is given in \"lb\"", "\"kg\""}},
            {fileWith("acrobot", {}), {"is a plant file for the acrobot, not the slidecar"}},
            {fileWith("hovercraft", {}), {"unknown plant \"hovercraft\""}},
            {fileWith("slidecar", {{"kineticFriction", 0.9}}),
             {"kineticFriction = 0.9 is above staticFriction = 0.65"}},
            {fileWith("slidecar", {{"cgForward", 0.2}}), {"cgForward = 0.2 m", "axle"}},
            {QByteArray("{\"plant\": \"slidecar\""), {"not valid JSON at byte"}},
            {QByteArray("[]"), {"valid JSON, but not a plant file"}},
            {QByteArray("{\"plant\": \"slidecar\", \"params\": {}}"), {"unknown key \"params\""}},
            {QByteArray("{\"plant\": \"slidecar\"}"), {"\"parameters\" is missing"}},
            {QByteArray("{\"plant\": \"slidecar\", \"version\": 7, \"parameters\": {}}"),
             {"version 7 is not one this build reads (it reads version 1)"}},
            {QByteArray("{\"plant\": \"slidecar\", \"version\": \"1\", \"parameters\": {}}"),
             {"\"version\" must be the number 1, not the text \"1\""}},
        };
        for (const Case& c : cases) {
            QString error;
            QVERIFY2(!parse(c.json, &error), c.json.constData());
            for (const QString& part : c.expected) {
                QVERIFY2(error.contains(part), qPrintable(error + " | wanted: " + part));
            }
        }
        // NaN and infinity cannot come from JSON, but the check holds for values from code.
        std::vector<double> values = defaultPlantParameters("slidecar").values;
        values[0] = std::nan("");
        QVERIFY(plantParametersProblem("slidecar", values).startsWith("mass = nan kg"));
        values.pop_back();
        QVERIFY(plantParametersProblem("slidecar", values).contains("parameters"));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, PlantCatalog::create(PlantParameters{
                                                            "slidecar", values, QString()}));
        // A missing file, and a directory, by name.
        QString error;
        QVERIFY(!readPlantParameters("/nonexistent/car.json", "slidecar", &error));
        QVERIFY2(error.contains("/nonexistent/car.json"), qPrintable(error));
        QTemporaryDir dir;
        QVERIFY(!readPlantParameters(dir.path(), "slidecar", &error));
        QVERIFY2(error.contains(dir.path()), qPrintable(error));
    }

    // The values reach the physics: a heavier car with a weaker motor covers less ground, a
    // car with a smaller steering lock turns less; the demonstrator records on the file's car.
    void values_reachThePhysicsAndTheDemonstrator() {
        auto nominal = PlantCatalog::create("slidecar");
        PlantParameters heavy = defaultPlantParameters("slidecar");
        for (size_t i = 0; i < heavy.values.size(); ++i) {
            const QString key = plantParameterSpecs("slidecar")[i].key;
            if (key == "mass")
                heavy.values[i] = 3.0;
            if (key == "maxDriveForce")
                heavy.values[i] = 6.0;
            if (key == "maxSteeringAngle")
                heavy.values[i] = 0.3;
        }
        auto heavier = PlantCatalog::create(heavy);
        const Eigen::VectorXd a = driven(*nominal);
        const Eigen::VectorXd b = driven(*heavier);
        QVERIFY2(b.head<2>().norm() < 0.8 * a.head<2>().norm(),
                 qPrintable(QString("%1 vs %2").arg(b.head<2>().norm()).arg(a.head<2>().norm())));
        RecordingConditions conditions;
        conditions.parameters = &heavy;
        const auto demoNominal = DemonstrationStyles::record("slidecar", "stick-180-left", 4);
        const auto demoHeavy =
            DemonstrationStyles::record("slidecar", "stick-180-left", 4, {}, conditions);
        QVERIFY(demoNominal.states.bottomRows(1) != demoHeavy.states.bottomRows(1));
        PlantParameters arm = defaultPlantParameters("acrobot");
        conditions.parameters = &arm;
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            DemonstrationStyles::record("slidecar", "stick-180-left", 4, {}, conditions));
    }

    // The session model over many days: the day's mismatch has the documented spread and is
    // the same for every trial of the day (up to the small per-trial part); the battery sags
    // with the trial index; under the trial model nothing persists from trial to trial.
    void sessionModel_statisticsOverDays() {
        SlideCar car;
        std::vector<double> trimFirst, trimLater, gainFirst, gainLater, frictionFirst,
            frictionLater, sag;
        std::vector<double> trialTrimA, trialTrimB;
        for (std::uint64_t day = 1; day <= 400; ++day) {
            car.reset(mixSeed(day, 11), sessionTrial(day, 0));
            trimFirst.push_back(car.steeringTrim());
            gainFirst.push_back(car.throttleGain());
            frictionFirst.push_back(car.frictionScale());
            car.reset(mixSeed(day, 12), sessionTrial(day, 30));
            trimLater.push_back(car.steeringTrim());
            gainLater.push_back(car.throttleGain());
            frictionLater.push_back(car.frictionScale());
            sag.push_back(gainLater.back() / gainFirst.back());
            car.reset(mixSeed(day, 11), Perturbation::realistic());
            trialTrimA.push_back(car.steeringTrim());
            car.reset(mixSeed(day, 12), Perturbation::realistic());
            trialTrimB.push_back(car.steeringTrim());
        }
        // Spread of the day's mismatch: trim 0.03 (+ 0.005 per trial), gain 0.08, friction
        // 0.10 (+ 0.03 per trial); 400 days give the std within about 7 %.
        QVERIFY2(std::abs(stddev(trimFirst) - 0.0304) < 0.004,
                 qPrintable(QString::number(stddev(trimFirst))));
        QVERIFY2(std::abs(stddev(gainFirst) - 0.08) < 0.012,
                 qPrintable(QString::number(stddev(gainFirst))));
        QVERIFY2(std::abs(stddev(frictionFirst) - 0.104) < 0.014,
                 qPrintable(QString::number(stddev(frictionFirst))));
        QVERIFY(std::abs(mean(trimFirst)) < 0.005);
        // Persistent within the day: trials 0 and 30 of a day share their mismatch ...
        QVERIFY2(correlation(trimFirst, trimLater) > 0.95,
                 qPrintable(QString::number(correlation(trimFirst, trimLater))));
        QVERIFY(correlation(gainFirst, gainLater) > 0.95);
        QVERIFY(correlation(frictionFirst, frictionLater) > 0.85);
        // ... up to the per-trial part, which does differ.
        QVERIFY(trimFirst != trimLater);
        // The battery: 30 trials at 0.2 % x (1 + 0.25 N) each, about 6 % down.
        QVERIFY2(std::abs((1.0 - mean(sag)) - 0.06) < 0.006,
                 qPrintable(QString::number(1.0 - mean(sag))));
        for (double s : sag) {
            QVERIFY(s <= 1.0);
        }
        // The trial model: two trials of one seed set are unrelated.
        QVERIFY2(std::abs(correlation(trialTrimA, trialTrimB)) < 0.15,
                 qPrintable(QString::number(correlation(trialTrimA, trialTrimB))));
        // A day's first trial and its demonstration's car share the mismatch; no offset then.
        car.reset(5, Perturbation::dayOf(77));
        const double demoTrim = car.steeringTrim();
        car.reset(6, sessionTrial(77, 0));
        QVERIFY(std::abs(demoTrim - car.steeringTrim()) < 0.03);
        QVERIFY(demoTrim != 0.0);
    }

    // A demonstration recorded on a session day's car: the same for the same day, another for
    // another day; the nominal car's when there is no day.
    void sessionModel_demonstrationOnTheDaysCar() {
        RecordingConditions day1, day2;
        day1.perturbation = Perturbation::dayOf(1);
        day2.perturbation = Perturbation::dayOf(2);
        const auto a = DemonstrationStyles::record("slidecar", "stick-180-left", 3, {}, day1);
        const auto b = DemonstrationStyles::record("slidecar", "stick-180-left", 3, {}, day1);
        const auto c = DemonstrationStyles::record("slidecar", "stick-180-left", 3, {}, day2);
        const auto nominal = DemonstrationStyles::record("slidecar", "stick-180-left", 3);
        QCOMPARE(a.states, b.states);
        QVERIFY(a.states.bottomRows(1) != c.states.bottomRows(1));
        QVERIFY(a.states.bottomRows(1) != nominal.states.bottomRows(1));
    }

    // Every plant takes the session model: the same day gives the same plant behaviour for
    // the same trial seed, and the trial index changes it only by the drift.
    void sessionModel_everyPlant() {
        for (const PlantEntry& entry : PlantCatalog::all()) {
            auto plant = PlantCatalog::create(entry.name);
            const Eigen::VectorXd u =
                Eigen::VectorXd::Constant(plant->info().actionDimension(), 0.4);
            auto run = [&](std::uint64_t seed, const Perturbation& p) {
                plant->reset(seed, p);
                Eigen::VectorXd s;
                for (int k = 0; k < 60; ++k) {
                    s = plant->step(u);
                }
                return s;
            };
            QCOMPARE(run(9, sessionTrial(5, 3)), run(9, sessionTrial(5, 3)));
            QVERIFY2(run(9, sessionTrial(5, 3)) != run(9, sessionTrial(6, 3)),
                     qPrintable(entry.name));
        }
    }
};

QTEST_GUILESS_MAIN(TestPlantParameters)
#include "test_plant_parameters.moc"
