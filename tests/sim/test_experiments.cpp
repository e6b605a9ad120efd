// The experiments' own modules, with assertions on values: Table I's runner and rows, the
// training seeds and PD (selected)'s grid, the profile's trial settings, and the run log.
#include "core/ActionMapping.h"
#include "core/RunLogCsv.h"
#include "sim/PlantCatalog.h"
#include "sim/experiments/LearningCurveExperiment.h"
#include "sim/experiments/Table1Experiment.h"
#include "sim/run/MethodTraining.h"
#include "sim/run/RunSetup.h"
#include "sim/tuning/MethodTuning.h"

#include <QtTest>

#include <algorithm>
#include <set>

using namespace prisca;
using namespace prisca::sim;

namespace {

struct CarTask {
    Task task =
        makeTask(PlantCatalog::tuning(PlantCatalog::describe("slidecar")),
                 std::make_shared<core::Demonstration>(PlantCatalog::demonstrate("slidecar", 1)));
    const MethodTuning& profile = task.profile;
    std::shared_ptr<const core::Demonstration> demo = task.demonstration;
};

// The slide-car's scripted demonstration recorded at `hertz` control steps per second.
Task carTaskAt(double hertz) {
    SimulationTiming timing;
    timing.controlPeriod = 1.0 / hertz;
    return makeTask(
        PlantCatalog::tuning(PlantCatalog::describe("slidecar")),
        std::make_shared<core::Demonstration>(PlantCatalog::demonstrate("slidecar", 1, timing)));
}

RunSettings nominal() {
    RunSettings settings;
    settings.perturbation = 0.0;
    settings.sensor = 0.0;
    settings.trainingTrials = 0;
    return settings;
}

double meanPositionCm(const MethodTrials& m) {
    double sum = 0.0;
    for (const TrialSummary& t : m.trials)
        sum += t.finalPositionError * 100.0;
    return sum / m.trials.size();
}

}  // namespace

class TestExperiments : public QObject {
    Q_OBJECT
  private slots:
    void table1_nominalPlaybackIsExactAndRowsCarryTheirLabels() {
        CarTask task;
        Table1Settings settings;
        settings.methods = {"playback", "pd-h-lsd"};
        settings.trials = 2;
        settings.run = nominal();
        const Table1Result result = runTable1(settings, task.task);
        QCOMPARE(result.methods.size(), size_t(2));
        // With nothing perturbed, the demonstration's own actions put the car on its lot (to
        // Box2D's single precision: within 0.1 mm).
        for (const TrialSummary& t : result.methods[0].trials) {
            QVERIFY2(t.finalPositionError < 1e-4,
                     qPrintable(QString::number(t.finalPositionError)));
        }
        QVERIFY(std::abs(result.lot[0] - task.demo->states(task.demo->length() - 1, 0)) < 1e-12);
        int finished = 0;
        const std::vector<core::Table1Row> rows = table1Rows(result, &finished);
        QCOMPARE(finished, 4);
        QCOMPARE(rows[0].label, QStringLiteral("ACTION PLAYBACK"));
        QCOMPARE(rows[1].label, QStringLiteral("PD+H+LSD"));
        QCOMPARE(rows[0].position.count, 2);
        QVERIFY(!rows[0].limit && !rows[1].limit);
    }

    void table1_feedbackBeatsPlaybackUnderPerturbationWhateverTheThreads() {
        CarTask task;
        Table1Settings settings;
        settings.methods = {"playback", "pd-h-lsd"};
        settings.trials = 4;
        settings.run.trainingTrials = 0;
        settings.run.threads = 1;
        const Table1Result one = runTable1(settings, task.task);
        settings.run.threads = 2;
        const Table1Result two = runTable1(settings, task.task);
        for (size_t m = 0; m < one.methods.size(); ++m) {
            for (size_t t = 0; t < one.methods[m].trials.size(); ++t) {
                QCOMPARE(one.methods[m].trials[t].finalPositionError,
                         two.methods[m].trials[t].finalPositionError);
            }
        }
        // Open loop drifts with friction, gains and trim; the feedback holds the path.
        QVERIFY2(meanPositionCm(one.methods[1]) < 0.5 * meanPositionCm(one.methods[0]),
                 qPrintable(QStringLiteral("%1 vs %2")
                                .arg(meanPositionCm(one.methods[1]))
                                .arg(meanPositionCm(one.methods[0]))));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, [&] {
            Table1Settings bad = settings;
            bad.methods = {"pegasus"};  // no Table I row
            runTable1(bad, task.task);
        }());
    }

    void trainingSeeds_areTheirOwnStream() {
        const std::vector<std::uint64_t> training = trainingSeeds(7, 50);
        std::set<std::uint64_t> all(training.begin(), training.end());
        QCOMPARE(all.size(), size_t(50));
        for (int i = 0; i < 1000; ++i) {
            QVERIFY(
                !all.count(mixSeed(7, static_cast<std::uint64_t>(i))));  // never an evaluation seed
        }
        QCOMPARE(trainingSeeds(7, 3),
                 std::vector<std::uint64_t>(training.begin(), training.begin() + 3));
    }

    void selectedPdGains_comeFromTheGrid() {
        CarTask task;
        RunSettings settings;
        settings.seed = 3;
        settings.trainingTrials = 2;
        const RunSetup setup(task.task, "pd-selected", settings);
        QCOMPARE(setup.trainingSeeds(), trainingSeeds(3, 2));
        const core::PdParameters gains = selectPdGains(setup, {}, {0.5, 2.0}, {0.0, 1.0});
        const double kpScale = gains.kp[0] / task.profile.pd.kp[0];
        QVERIFY2(std::abs(kpScale - 0.5) < 1e-12 || std::abs(kpScale - 2.0) < 1e-12,
                 qPrintable(QString::number(kpScale)));
        QVERIFY(((gains.kp / kpScale) - task.profile.pd.kp).cwiseAbs().maxCoeff() < 1e-12);
        QVERIFY(gains.kd.cwiseAbs().maxCoeff() == 0.0 ||
                ((gains.kd - task.profile.pd.kd).cwiseAbs().maxCoeff() < 1e-12));
    }

    // A demonstration recorded at any control rate replays exactly on the nominal plant with a
    // perfect sensor: every experiment steps the plant at the demonstration's own period.
    void runSetup_stepsThePlantAtTheDemonstrationsPeriod_data() {
        QTest::addColumn<double>("hertz");
        for (double hertz : {25.0, 30.0, 40.0, 50.0, 60.0}) {
            QTest::addRow("%g Hz", hertz) << hertz;
        }
    }
    void runSetup_stepsThePlantAtTheDemonstrationsPeriod() {
        QFETCH(double, hertz);
        const Task task = carTaskAt(hertz);
        QCOMPARE(task.demonstration->dt, 1.0 / hertz);
        const RunSetup setup(task, "playback", nominal());
        auto plant = setup.makePlant();
        QCOMPARE(plant->timing().controlPeriod, 1.0 / hertz);
        auto controller = setup.makeController();
        const EpisodeResult run = runEpisode(*plant, *controller, setup.trial(0));
        const TrialSummary summary = summarizeTrial(plant->info(), *task.demonstration, run);
        QVERIFY2(summary.finalPositionError < 1e-4,
                 qPrintable(QStringLiteral("run: %1 m").arg(summary.finalPositionError)));

        Table1Settings table;
        table.methods = {"playback"};
        table.trials = 1;
        table.run = nominal();
        const Table1Result result = runTable1(table, task);
        QVERIFY2(result.methods[0].trials[0].finalPositionError < 1e-4,
                 qPrintable(QStringLiteral("table1: %1 m")
                                .arg(result.methods[0].trials[0].finalPositionError)));

        LearningCurveSettings curves;
        curves.methods = {"playback"};
        curves.runs = 1;
        curves.budgetSteps = task.demonstration->length();
        curves.run = nominal();
        const std::vector<MethodCurves> curve = runLearningCurves(curves, task);
        QVERIFY(!curve[0].runs[0].empty());
        // Mean squared position error over the trial [m^2].
        QVERIFY2(
            curve[0].runs[0][0].trackingError < 1e-8,
            qPrintable(QStringLiteral("curve: %1 m^2").arg(curve[0].runs[0][0].trackingError)));
    }

    void runSetup_oneSetOfDefaultsAndTrialSeeds() {
        const RunSettings defaults;
        QCOMPARE(defaults.trainingTrials, 16);
        const Task task = carTaskAt(40.0);
        const RunSetup setup(task, "prisca", defaults);
        const EpisodeSettings third = setup.trial(2);
        QCOMPARE(third.seed, mixSeed(defaults.seed, 2));
        QVERIFY(third.resetMode == core::ResetMode::WarmStart);
        QVERIFY(setup.trial(0).resetMode == core::ResetMode::Cold);
        QCOMPARE(setup.trainingSeeds(), trainingSeeds(defaults.seed, defaults.trainingTrials));
        // The slide-car's trackers compensate the camera's latency, on the rig as in simulation.
        QCOMPARE(setup.episode().compensatedLoopLatencySteps(),
                 task.profile.measurement.loopLatencySteps);
        QVERIFY(setup.episode().compensatedLoopLatencySteps() > 0);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RunSetup(task, "no-such-method"));
        RunSettings bad;
        bad.threads = 0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RunSetup(task, "pd", bad));
    }

    void profileEpisode_perfectSensorHasNoLatencyAndTheTrialTheDemonstrationsLength() {
        CarTask task;
        const EpisodeSettings real = task.profile.episode(*task.demo, 1.0, 1.0);
        QCOMPARE(real.measurement.loopLatencySteps, task.profile.measurement.loopLatencySteps);
        QVERIFY(real.measurement.loopLatencySteps > 0);
        const EpisodeSettings perfect = task.profile.episode(*task.demo, 0.0, 0.0);
        QCOMPARE(perfect.measurement.loopLatencySteps, 0);
        QCOMPARE(perfect.measurement.dropProbability, 0.0);
        QCOMPARE(perfect.perturbation.parameters, 0.0);
        const double length = task.demo->length() * task.demo->dt;
        QVERIFY(std::abs(real.duration - (length + task.profile.settleTime)) < 1e-12);
        QVERIFY(std::abs(real.stopAtRestAfter - length) < 1e-12);
    }

    void runLog_headerColumnsAndRows() {
        core::RunLog log;
        log.plant = "slidecar";
        log.method = "pd";
        log.dt = 0.025;
        log.metadata.insert("seed", "3");
        log.columns = {"trial", "t"};
        log.units = {"1", "s"};
        log.rows = (Eigen::MatrixXd(2, 2) << 0, 0, 0, 0.025).finished();
        QString problem;
        const QByteArray text = core::formatRunLogCsv(log, &problem);
        QCOMPARE(QString::fromUtf8(text),
                 QStringLiteral("# prisca-run-log 1\n# plant: slidecar\n# method: pd\n# dt: 0.025\n"
                                "# seed: 3\n# columns: trial[1], t[s]\ntrial,t\n0,0\n0,0.025\n"));
        log.units = {"1"};
        QVERIFY(core::formatRunLogCsv(log, &problem).isEmpty());
        QVERIFY2(problem.contains("2 columns, 1 units"), qPrintable(problem));
    }
};

QTEST_APPLESS_MAIN(TestExperiments)
#include "test_experiments.moc"
