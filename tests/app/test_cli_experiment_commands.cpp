// prisca-cli's commands that run trials, end to end on real files: run, table1, curve and
// lemma41, their formats and figures, every method on every plant.
#include "CliCommandTest.h"

using namespace prisca::clitest;

class TestCliExperimentCommands : public QObject, private CliWorkspace {
    Q_OBJECT
  private slots:
    void initTestCase() { writeCarDemonstration(); }

    void table1_variantsGiveAPerVariantBreakdownAndLearningCurves() {
        QDir(dir_.path()).mkpath("variants");
        for (const auto& [name, json] : std::vector<std::pair<QString, QByteArray>>{
                 {"heavy", R"({"plant": "slidecar", "parameters": {"mass": 2.2}})"},
                 {"grip", R"({"plant": "slidecar", "parameters": {"staticFriction": 0.55,
                             "kineticFriction": 0.4}})"}}) {
            QFile f(path("variants/" + name + ".json"));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(json);
        }
        const CliResult r =
            cli({"table1", "--styles", "stick-90-left", "--trials", "2", "--training-trials", "3",
                 "--variants", "variants", "--methods", "prisca,pd", "--learning-out",
                 "learning.csv", "--learning-plot", "learning.png", "--format", "md"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("| method | grip | heavy |"), qPrintable(r.out));
        QVERIFY(r.out.contains("2 plant variants from variants"));
        QVERIFY(r.out.contains("session perturbation model"));
        QFile csv(path("learning.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts);
        // PRISCA: 3 training + 2 evaluation trials; PD: 2 evaluation trials; and the header.
        QCOMPARE(lines.size(), 1 + 5 + 2);
        QVERIFY2(lines[1].startsWith("prisca,1,training,2,"), qPrintable(lines[1]));
        QVERIFY2(lines[4].startsWith("prisca,4,evaluation,2,"), qPrintable(lines[4]));
        QVERIFY2(lines[6].startsWith("pd,1,evaluation,2,"), qPrintable(lines[6]));
        QVERIFY(!QImage(path("learning.png")).isNull());
        // Refused: a folder with no plant file, a bad one, both --plant-params and --variants.
        QDir(dir_.path()).mkpath("empty");
        CliResult bad = cli({"table1", "--styles", "stick-90-left", "--variants", "empty"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("no plant file"), qPrintable(bad.err));
        QFile f(path("variants/zz-bad.json"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"plant": "slidecar", "parameters": {"topSpeed": -1}})");
        f.close();
        bad = cli({"table1", "--styles", "stick-90-left", "--variants", "variants"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("zz-bad.json: topSpeed = -1 m/s is outside"),
                 qPrintable(bad.err));
        QCOMPARE(cli({"table1", "--variants", "variants"}).exitCode, 2);  // needs --styles
    }

    void table1_stylesAndSeedSetsGiveMeansIntervalsAndABreakdown() {
        const CliResult r =
            cli({"table1", "--styles", "stick-90-left,fast-180-right", "--seed-sets", "2", "--seed",
                 "40", "--trials", "2", "--training-trials", "1", "--methods", "pd-h-lsd,ilc",
                 "--format", "json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject root = parseJson(r.out);
        QCOMPARE(root.value("seedSets").toArray().size(), 2);
        const QJsonArray rows = root.value("rows").toArray();
        QCOMPARE(rows.size(), 2);
        for (const QJsonValue& value : rows) {
            const QJsonObject row = value.toObject();
            const QJsonObject position = row.value("positionCm").toObject();
            QCOMPARE(position.value("cells").toInt(), 4);
            QCOMPARE(row.value("trials").toInt(), 8);
            const double mean = position.value("meanAbsoluteError").toDouble();
            QVERIFY(position.value("lower").toDouble() <= mean &&
                    mean <= position.value("upper").toDouble());
            QVERIFY(row.value("orientationDeg").toObject().contains("meanAbsoluteError"));
            // Per style: the mean over its two seed sets; the cells average to the whole.
            const QJsonArray styles = row.value("styles").toArray();
            QCOMPARE(styles.size(), 2);
            double sum = 0.0;
            for (const QJsonValue& style : styles) {
                sum += style.toObject()
                           .value("positionCm")
                           .toObject()
                           .value("meanAbsoluteError")
                           .toDouble();
            }
            QVERIFY(std::abs(sum / 2.0 - mean) < 1e-9);
        }
        // (Under the trial model, where this trial leaves the oracle a measurable error.)
        const CliResult md =
            cli({"table1", "--styles", "stick-90-left", "--trials", "1", "--training-trials", "1",
                 "--methods", "pd,oracle", "--perturbation-model", "trial"});
        QVERIFY2(md.exitCode == 0, qPrintable(md.err));
        QVERIFY2(md.out.contains("| LIMIT (oracle) | 1 | 1 |") && md.out.contains("| 1.0x |"),
                 qPrintable(md.out));
        QVERIFY(md.out.contains("| method | stick-90-left |"));
        const CliResult bad = cli({"table1", "--styles", "stick-90-left,nope", "--out", "x.md"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY(bad.err.contains("'nope'"));
        QVERIFY(!QFile::exists(path("x.md")));
        QCOMPARE(cli({"table1", "--seed-sets", "2"}).exitCode, 2);
    }

    void curve_stylesPoolTheRunsAndBreakDownTheFinalError() {
        const CliResult r =
            cli({"curve", "--plant", "acrobot", "--styles", "swing-small,swing-large", "--methods",
                 "ilc,pd", "--runs", "2", "--budget", "960", "--out", "styles-curve.csv",
                 "--format", "json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject root = parseJson(r.out);
        QCOMPARE(root.value("cells").toInt(), 2);
        const QJsonArray methods = root.value("methods").toArray();
        QCOMPARE(methods.size(), 2);
        QCOMPARE(methods[0].toObject().value("runs").toInt(), 4);  // 2 runs x 2 cells
        QCOMPARE(methods[0].toObject().value("styles").toArray().size(), 2);
    }

    // A demonstration at any camera rate replays exactly on the nominal plant with a perfect
    // sensor in every command: each steps the plant at the demonstration's own period.
    void anyRate_playbackRepeatsTheDemonstrationInRunTable1AndCurve_data() {
        QTest::addColumn<int>("hertz");
        for (int hertz : {25, 30, 50, 60}) {
            QTest::addRow("%d Hz", hertz) << hertz;
        }
    }

    void anyRate_playbackRepeatsTheDemonstrationInRunTable1AndCurve() {
        QFETCH(int, hertz);
        const QString demo = QStringLiteral("car-%1hz.csv").arg(hertz);
        const CliResult made = cli({"demo", "--plant", "slidecar", "--rate", QString::number(hertz),
                                    "--out", demo, "--format", "json"});
        QVERIFY2(made.exitCode == 0, qPrintable(made.err));
        QCOMPARE(parseJson(made.out).value("dt").toDouble(), 1.0 / hertz);
        const QStringList nominal = {"--perturbation", "0", "--sensor", "0"};

        const CliResult run =
            cli(QStringList{"run", "--plant", "slidecar", "--demo", demo, "--method", "playback",
                            "--out", "rate-log.csv", "--format", "json"} +
                nominal);
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const double runCm = parseJson(run.out)
                                 .value("trials")
                                 .toArray()
                                 .at(0)
                                 .toObject()
                                 .value("finalPositionErrorCm")
                                 .toDouble(-1);
        QVERIFY2(runCm >= 0.0 && runCm < 0.01, qPrintable(QString::number(runCm)));

        const CliResult table = cli(QStringList{"table1", "--demo", demo, "--methods", "playback",
                                                "--trials", "1", "--format", "json"} +
                                    nominal);
        QVERIFY2(table.exitCode == 0, qPrintable(table.err));
        const double tableCm = parseJson(table.out)
                                   .value("rows")
                                   .toArray()
                                   .at(0)
                                   .toObject()
                                   .value("positionCm")
                                   .toObject()
                                   .value("meanAbsoluteError")
                                   .toDouble(-1);
        QVERIFY2(tableCm >= 0.0 && tableCm < 0.01, qPrintable(QString::number(tableCm)));

        const CliResult curve =
            cli(QStringList{"curve", "--plant", "slidecar", "--demo", demo, "--methods", "playback",
                            "--runs", "1", "--budget", "2000", "--out", "rate-curve.csv",
                            "--format", "json"} +
                nominal);
        QVERIFY2(curve.exitCode == 0, qPrintable(curve.err));
        // Mean squared position error over a trial [m^2]: (0.1 mm)^2 at most.
        const double curveM2 = parseJson(curve.out)
                                   .value("methods")
                                   .toArray()
                                   .at(0)
                                   .toObject()
                                   .value("finalMean")
                                   .toDouble(-1);
        QVERIFY2(curveM2 >= 0.0 && curveM2 < 1e-8, qPrintable(QString::number(curveM2)));
    }

    void run_logsEveryStepOfEveryTrial() {
        const CliResult r =
            cli({"run", "--plant", "slidecar", "--demo", "car.csv", "--method", "prisca",
                 "--trials", "2", "--seed", "5", "--out", "log.csv", "--format", "json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject summary = parseJson(r.out);
        const QJsonArray trials = summary.value("trials").toArray();
        QCOMPARE(trials.size(), 2);
        for (const QJsonValue& t : trials) {
            const double error = t.toObject().value("finalPositionErrorCm").toDouble(-1);
            QVERIFY(error >= 0.0 && error < 1000.0);
        }
        QFile file(path("log.csv"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
        QVERIFY(lines.first().startsWith("# prisca-run-log 1"));
        int header = 0;
        while (lines[header].startsWith('#'))
            ++header;
        const QList<QByteArray> columns = lines[header].split(',');
        QCOMPARE(columns.first(), QByteArray("trial"));
        QVERIFY(columns.contains("theta_0_steering") && columns.contains("e_lat") &&
                columns.contains("ref_index"));
        QSet<int> trialIds;
        for (int i = header + 1; i < lines.size(); ++i) {
            const QList<QByteArray> fields = lines[i].split(',');
            QCOMPARE(fields.size(), columns.size());
            trialIds.insert(fields.first().toInt());
        }
        QCOMPARE(trialIds, (QSet<int>{0, 1}));
        // The same seed gives the same log, byte for byte.
        QCOMPARE(cli({"run", "--plant", "slidecar", "--demo", "car.csv", "--method", "prisca",
                      "--trials", "2", "--seed", "5", "--out", "again.csv"})
                     .exitCode,
                 0);
        QFile again(path("again.csv"));
        QVERIFY(again.open(QIODevice::ReadOnly));
        QVERIFY(file.seek(0));
        QVERIFY(file.readAll() == again.readAll());
    }

    void run_longTrialReportsItsProgressOnStderr() {
        // A 20,000-sample drive (500 s at 40 Hz): the trial says every tenth how far it is, on
        // stderr only; stdout is the usual one line per trial.
        QByteArray actions("throttle,steering\n");
        for (int k = 0; k < 20000; ++k) {
            const double t = 0.025 * k;
            actions += QByteArray::number(std::min(1.0, t / 2.0) * 0.25) + ',' +
                       QByteArray::number(0.35 * std::sin(2.0 * M_PI * t / 23.0)) + '\n';
        }
        writeFile(path("long-actions.csv"), actions);
        QCOMPARE(cli({"simulate", "--plant", "slidecar", "--actions", "long-actions.csv", "--dt",
                      "0.025", "--out", "long.csv"})
                     .exitCode,
                 0);
        const CliResult r = cli({"run", "--plant", "slidecar", "--demo", "long.csv", "--method",
                                 "playback", "--out", "long-log.csv"});
        QCOMPARE(r.exitCode, 0);
        for (int percent = 10; percent <= 90; percent += 10) {
            QVERIFY2(r.err.contains(QStringLiteral("run: trial 1/1, %1%").arg(percent)),
                     qPrintable(r.err));
        }
        QVERIFY2(r.out.startsWith("trial 0: final position error ") &&
                     r.out.endsWith("wrote long-log.csv\n") && r.out.count(u'\n') == 2,
                 qPrintable(r.out));
    }

    void run_everyMethodOnEveryPlant_data() {
        QTest::addColumn<QString>("plant");
        QTest::addColumn<QString>("method");
        // Every catalog method on every catalog plant: a new entry is tested without a word here.
        for (const QString& plant : prisca::sim::PlantCatalog::names()) {
            for (const QString& method : prisca::sim::MethodCatalog::ids()) {
                QTest::newRow(qPrintable(QStringLiteral("%1 %2").arg(plant, method)))
                    << plant << method;
            }
        }
    }

    void run_everyMethodOnEveryPlant() {
        QFETCH(QString, plant);
        QFETCH(QString, method);
        const QString demo = plant + "-demo.csv";
        if (!QFile::exists(path(demo))) {
            QCOMPARE(cli({"demo", "--plant", plant, "--out", demo}).exitCode, 0);
        }
        // Small training budgets: this checks the plumbing, not the tuning.
        const CliResult r = cli({"run", "--plant", plant, "--demo", demo, "--method", method,
                                 "--param", "pegasus.iterations=1", "--training-trials", "1",
                                 "--out", plant + "-" + method + ".csv", "--format", "json"});
        if (!prisca::sim::MethodCatalog::get(method).runsOn(plant)) {
            // A method that does not run on this plant is refused, saying where it runs.
            QVERIFY2(r.exitCode != 0 && r.err.contains(QLatin1String("runs on")),
                     qPrintable(r.err));
            return;
        }
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject trial = parseJson(r.out).value("trials").toArray().at(0).toObject();
        QVERIFY(trial.value("trackingRms").toDouble(-1) >= 0.0);
        QVERIFY(trial.value("cpuMicrosecondsPerStep").toDouble(-1) > 0.0);
        QVERIFY(trial.value("runOutSeconds").toDouble(-1) >= 0.0);
        QVERIFY(QFile::exists(path(plant + "-" + method + ".csv")));
    }

    void table1_writesEveryFormatWellFormed() {
        const QStringList base = {"table1", "--trials", "3", "--training-trials",
                                  "2",      "--seed",   "4"};
        const CliResult md = cli(base);
        QCOMPARE(md.exitCode, 0);
        for (const char* label : {"OURS (PRISCA)", "PRISCA (paper)", "PD (SELECTED)", "PD+H+LSD",
                                  "LQR", "ACTION PLAYBACK", "PGSD", "ILC", "LIMIT (oracle)"}) {
            QVERIFY2(md.out.contains(QStringLiteral("| %1 | 3 |").arg(label)), qPrintable(md.out));
        }
        QVERIFY(md.err.contains("table1:"));  // progress on stderr, the table on stdout
        const CliResult json = cli(base + QStringList{"--format", "json"});
        QCOMPARE(json.exitCode, 0);
        const QJsonArray rows = parseJson(json.out).value("rows").toArray();
        QCOMPARE(rows.size(), 12);
        for (const QJsonValue& row : rows) {
            const QJsonObject position = row.toObject().value("positionCm").toObject();
            QCOMPARE(position.value("count").toInt(), 3);
            QVERIFY(position.value("meanAbsoluteError").toDouble(-1) >= 0.0);
            QVERIFY(std::abs(position.value("variance").toDouble() -
                             std::pow(position.value("standardDeviation").toDouble(), 2)) < 1e-9);
        }
        // The same seed gives the same table (all but the measured CPU times); --out writes it
        // to a file instead.
        int measured = 0;
        const auto withoutCpu = [&measured](const QString& text) -> QJsonObject {
            QJsonObject root = parseJson(text);
            QJsonArray rows = root.value("rows").toArray();
            for (int i = 0; i < rows.size(); ++i) {
                QJsonObject row = rows[i].toObject();
                measured += row.value("cpuMicrosecondsPerStep").toDouble() > 0.0;
                row.remove("cpuMicrosecondsPerStep");
                rows[i] = row;
            }
            root.insert("rows", rows);
            return root;
        };
        QCOMPARE(withoutCpu(cli(base + QStringList{"--format", "json"}).out), withoutCpu(json.out));
        QCOMPARE(measured, 24);
        const CliResult csv = cli(base + QStringList{"--format", "csv", "--out", "table.csv"});
        QCOMPARE(csv.exitCode, 0);
        QCOMPARE(csv.out, QString());
        QFile file(path("table.csv"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll().trimmed().split('\n').size(), 13);
        const CliResult tex =
            cli(base + QStringList{"--format", "latex", "--methods", "prisca,pd"});
        QCOMPARE(tex.exitCode, 0);
        QVERIFY(tex.out.contains("\\begin{tabular}") && tex.out.contains("OURS (PRISCA) & 3"));
    }

    void curve_writesAMeanAndBandPerMethod() {
        // 12800 steps: one PEGASUS iteration (36 rollouts of 320 steps) fits in the budget.
        const CliResult r = cli({"curve", "--runs", "2", "--budget", "12800", "--out", "curve.csv",
                                 "--format", "json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(parseJson(r.out).value("methods").toArray().size(), 3);
        QFile file(path("curve.csv"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
        QCOMPARE(lines.first(), QByteArray("method,steps,time_s,mean,lower,upper,runs"));
        QSet<QByteArray> methods;
        for (int i = 1; i < lines.size(); ++i) {
            const QList<QByteArray> f = lines[i].split(',');
            QCOMPARE(f.size(), 7);
            methods.insert(f[0]);
            const double mean = f[3].toDouble(), lower = f[4].toDouble(), upper = f[5].toDouble();
            QVERIFY(lower <= mean + 1e-12 && mean <= upper + 1e-12 && mean >= 0.0);
            QCOMPARE(f[1].toLongLong() % 320, 0LL);  // one point per demonstration length
            QVERIFY(f[6].toInt() >= 1 && f[6].toInt() <= 2);
        }
        QCOMPARE(methods, (QSet<QByteArray>{"prisca", "pgsd", "pegasus"}));
    }

    void lemma41_writesTheGridAndCountsTheCells() {
        const CliResult r = cli({"lemma41", "--out", "lemma.csv", "--format", "json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject summary = parseJson(r.out);
        QCOMPARE(summary.value("cells").toInt(), 5050);
        QCOMPARE(summary.value("satisfied").toInt(),
                 800);  // the count Lemma41Grid's tests pin down
        // gamma = 1 makes D constant: the lemma holds there for every H.
        for (const QJsonValue& t : summary.value("thresholds").toArray()) {
            QVERIFY(t.toObject().value("satisfiedFromGamma").toDouble() <= 1.0);
        }
        QFile file(path("lemma.csv"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), 5051);
        QCOMPARE(lines.first(), QByteArray("H,gamma,variance,satisfied"));
        // H = 1, gamma = 0: D = (1/2, 1) over tau' = 2 steps, variance 1/16.
        QCOMPARE(lines[1], QByteArray("1,0,0.0625,1"));
    }

    void plots_areWrittenAsPngAndSvg() {
        QCOMPARE(cli({"table1", "--trials", "2", "--training-trials", "1", "--plot", "fig7.png"})
                     .exitCode,
                 0);
        QCOMPARE(QImage(path("fig7.png")).size(), QSize(1500, 1000));
        QCOMPARE(cli({"lemma41", "--out", "l.csv", "--plot", "fig2.svg"}).exitCode, 0);
        QFile svg(path("fig2.svg"));
        QVERIFY(svg.open(QIODevice::ReadOnly));
        QVERIFY(svg.readAll().contains("<svg"));
        const CliResult bad = cli({"lemma41", "--out", "l.csv", "--plot", "fig2.gif"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("fig2.gif"), qPrintable(bad.err));
    }

    void run_compareRunsBothMethodsOnTheSameTrialsAndPlotsThem() {
        if (!QFile::exists(path("aircraft-demo.csv"))) {
            QCOMPARE(cli({"demo", "--plant", "aircraft", "--out", "aircraft-demo.csv"}).exitCode,
                     0);
        }
        const QStringList base = {"run",      "--plant", "aircraft", "--demo", "aircraft-demo.csv",
                                  "--trials", "2",       "--format", "json"};
        const CliResult both = cli(base + QStringList{"--method", "prisca", "--compare", "pd",
                                                      "--out", "cmp.csv", "--plot", "fig4.png"});
        QVERIFY2(both.exitCode == 0, qPrintable(both.err));
        const QJsonObject summary = parseJson(both.out);
        const QJsonArray compared = summary.value("compare").toObject().value("trials").toArray();
        QCOMPARE(compared.size(), 2);
        QCOMPARE(QImage(path("fig4.png")).size(), QSize(1400, 700));
        // The comparison is the plain run of that method on the same seeds.
        const CliResult alone = cli(base + QStringList{"--method", "pd", "--out", "pd.csv"});
        QCOMPARE(alone.exitCode, 0);
        const QJsonArray pdTrials = parseJson(alone.out).value("trials").toArray();
        for (int t = 0; t < 2; ++t) {
            QCOMPARE(compared[t].toObject().value("trackingRms").toDouble(),
                     pdTrials[t].toObject().value("trackingRms").toDouble());
            // On the path is never farther than on the timed trajectory.
            const double pathRms = pdTrials[t].toObject().value("pathRms").toDouble(-1);
            QVERIFY(pathRms >= 0.0);
            QVERIFY(pathRms <= pdTrials[t].toObject().value("trackingRms").toDouble());
        }
        QCOMPARE(cli(base + QStringList{"--method", "prisca", "--compare", "lqg", "--out", "x.csv"})
                     .exitCode,
                 2);
    }

    // An interrupted table goes to NAME.partial; a complete previous table at NAME stays.
    void table1_interruptKeepsWhatFinished() {
        const QString out = dir_.filePath("interrupted-table.md");
        const QString partial = out + ".partial";
        QFile::remove(partial);
        QVERIFY(prisca::core::writeFileAtomically(out, "a complete previous table\n", nullptr));
        QProcess process;
        process.setWorkingDirectory(dir_.path());
        process.start(QStringLiteral(PRISCA_CLI),
                      {"table1", "--trials", "2000", "--training-trials", "0", "--methods", "pd",
                       "--jobs", "1", "--out", out});
        QVERIFY(process.waitForStarted());
        // Interrupt once some trials have finished (its progress line, every 5 %, says so).
        QByteArray progress;
        QVERIFY(QTest::qWaitFor(
            [&] {
                progress += process.readAllStandardError();
                return progress.contains("table1: ");
            },
            60000));
        process.terminate();  // SIGTERM, handled like Ctrl-C
        QVERIFY(process.waitForFinished(60000));
        QCOMPARE(process.exitCode(), 128 + SIGTERM);
        const QString err = QString::fromLocal8Bit(process.readAllStandardError());
        QVERIFY2(err.contains("stopped by SIGTERM; kept the") && err.contains(partial),
                 qPrintable(err));
        QFile previous(out);
        QVERIFY(previous.open(QIODevice::ReadOnly));
        QCOMPARE(previous.readAll(), QByteArray("a complete previous table\n"));
        QFile kept(partial);
        QVERIFY(kept.open(QIODevice::ReadOnly));
        const QString table = QString::fromUtf8(kept.readAll());
        QVERIFY2(table.contains("interrupted:") && table.contains("| PD (partial: "),
                 qPrintable(table));
    }

    // --start demo: PRISCA and the PD family start from the law derived from the demonstration
    // alone, on every catalog plant, in run, table1 and curve; a value that is neither is refused.
    void start_demoRunsOnEveryPlantInRunTable1AndCurve_data() {
        QTest::addColumn<QString>("plant");
        for (const QString& plant : prisca::sim::PlantCatalog::names()) {
            QTest::newRow(qPrintable(plant)) << plant;
        }
    }

    void start_demoRunsOnEveryPlantInRunTable1AndCurve() {
        QFETCH(QString, plant);
        const QString demo = plant + "-start-demo.csv";
        QCOMPARE(cli({"demo", "--plant", plant, "--out", demo}).exitCode, 0);
        for (const char* method : {"prisca", "pd-h-lsd"}) {
            const CliResult r =
                cli({"run", "--plant", plant, "--demo", demo, "--method", method, "--start", "demo",
                     "--trials", "2", "--out", plant + "-start.csv", "--format", "json"});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            const QJsonArray trials = parseJson(r.out).value("trials").toArray();
            QCOMPARE(trials.size(), 2);
            for (const QJsonValue& trial : trials) {
                const double rms = trial.toObject().value("trackingRms").toDouble(-1);
                QVERIFY2(rms >= 0.0 && std::isfinite(rms), qPrintable(r.out));
            }
        }
        if (prisca::sim::PlantCatalog::describe(plant).pose) {  // table1 is for vehicles
            const CliResult table = cli({"table1", "--plant", plant, "--demo", demo, "--trials",
                                         "1", "--training-trials", "1", "--methods", "prisca,pd",
                                         "--start", "demo", "--format", "json"});
            QVERIFY2(table.exitCode == 0, qPrintable(table.err));
        }
        const CliResult curve =
            cli({"curve", "--plant", plant, "--demo", demo, "--methods", "prisca", "--runs", "1",
                 "--budget", "400", "--start", "demo", "--out", plant + "-start-curve.csv"});
        QVERIFY2(curve.exitCode == 0, qPrintable(curve.err));
        const CliResult bad = cli({"run", "--plant", plant, "--demo", demo, "--method", "prisca",
                                   "--start", "guess", "--out", plant + "-bad.csv"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("--start"), qPrintable(bad.err));
    }
};

QTEST_GUILESS_MAIN(TestCliExperimentCommands)
#include "test_cli_experiment_commands.moc"
