// prisca-cli's commands that make and check a task, end to end on real files: demo, plant,
// identify, fit, simulate, methods, and every command's --help.
#include "CliCommandTest.h"

using namespace prisca::clitest;

class TestCliTaskCommands : public QObject, private CliWorkspace {
    Q_OBJECT
  private slots:
    void initTestCase() { writeCarDemonstration(); }

    void demo_writesADemonstrationForEveryPlant_data() {
        QTest::addColumn<QString>("plant");
        QTest::newRow("slidecar") << "slidecar";
        QTest::newRow("acrobot") << "acrobot";
        QTest::newRow("aircraft") << "aircraft";
    }

    void demo_writesADemonstrationForEveryPlant() {
        QFETCH(QString, plant);
        const CliResult r =
            cli({"demo", "--plant", plant, "--out", plant + "-demo.csv", "--format", "json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject summary = parseJson(r.out);
        QCOMPARE(summary.value("plant").toString(), plant);
        QVERIFY(summary.value("samples").toInt() > 50);
        QFile file(path(plant + "-demo.csv"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.readLine().startsWith("# prisca-demonstration 1"));
        // And it reads back: fit it.
        const CliResult fit = cli({"fit", "--demo", plant + "-demo.csv", "--format", "json"});
        QCOMPARE(fit.exitCode, 0);
        QCOMPARE(parseJson(fit.out).value("plant").toString(), plant);
    }

    void demo_listsStylesAndRecordsEach() {
        const CliResult list = cli({"demo", "--plant", "slidecar", "--list-styles"});
        QCOMPARE(list.exitCode, 0);
        const QStringList styles = list.out.trimmed().split('\n');
        QVERIFY(styles.size() >= 6);
        QCOMPARE(styles.front(), QStringLiteral("stick-180-left"));
        const CliResult json =
            cli({"demo", "--plant", "aircraft", "--list-styles", "--format", "json"});
        QCOMPARE(parseJson(json.out).value("styles").toArray().size(), 4);
        // --style is the command's own (not the GUI toolkit's): the file says which it is.
        const CliResult r = cli({"demo", "--plant", "slidecar", "--style", styles.last(), "--seed",
                                 "3", "--out", "styled.csv", "--format", "json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(parseJson(r.out).value("style").toString(), styles.last());
        QFile file(path("styled.csv"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.readAll().contains("# style: " + styles.last().toUtf8()));
        const CliResult bad =
            cli({"demo", "--plant", "slidecar", "--style", "moonwalk", "--out", "never.csv"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY(bad.err.contains("moonwalk") && bad.err.contains("stick-180-left"));
    }

    // A plant file: printed with every key's unit and range, written, edited, loaded by
    // demo, simulate, run and table1 (the car drives differently), and refused by name.
    void plantFiles_printWriteLoadAndRefuse() {
        const CliResult text = cli({"plant", "--plant", "slidecar", "--print-params"});
        QCOMPARE(text.exitCode, 0);
        QVERIFY2(text.out.contains(QRegularExpression("mass +1.5 kg +\\[0.3, 10\\]")),
                 qPrintable(text.out));
        QCOMPARE(cli({"plant", "--plant", "slidecar", "--print-params", "--format", "json", "--out",
                      "mycar.json"})
                     .exitCode,
                 0);
        // Edited: a heavier car with a weaker motor.
        QFile file(path("mycar.json"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
        file.close();
        QJsonObject parameters = root.value("parameters").toObject();
        QJsonObject mass = parameters.value("mass").toObject();
        mass.insert("value", 2.4);
        parameters.insert("mass", mass);
        parameters.insert("maxDriveForce", 6.0);
        root.insert("parameters", parameters);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(QJsonDocument(root).toJson());
        file.close();
        const CliResult checked =
            cli({"plant", "--plant", "slidecar", "--plant-params", "mycar.json"});
        QVERIFY2(checked.exitCode == 0 && checked.out.contains(QRegularExpression("mass +2.4 kg")),
                 qPrintable(checked.out + checked.err));
        // The same drive on both cars: the heavier one covers less ground.
        const auto coast = [&](const QStringList& extra) {
            const CliResult r =
                cli(QStringList{"simulate", "--plant", "slidecar", "--initial", "0,0,0,0,0,0",
                                "--actions", "full.csv", "--out", "s.csv", "--format", "json"} +
                    extra);
            return QJsonDocument::fromJson(r.out.toUtf8())
                .object()
                .value("finalState")
                .toArray()
                .at(0)
                .toDouble();
        };
        QFile actions(path("full.csv"));
        QVERIFY(actions.open(QIODevice::WriteOnly));
        actions.write("throttle,steering\n");
        for (int k = 0; k < 40; ++k) {
            actions.write("1,0\n");
        }
        actions.close();
        const double nominal = coast({});
        const double heavy = coast({"--plant-params", "mycar.json"});
        QVERIFY2(nominal > 0.5 && heavy < 0.8 * nominal,
                 qPrintable(QString("%1 vs %2").arg(heavy).arg(nominal)));
        const CliResult demo = cli(
            {"demo", "--plant", "slidecar", "--plant-params", "mycar.json", "--out", "heavy.csv"});
        QCOMPARE(demo.exitCode, 0);
        const CliResult run =
            cli({"run", "--plant", "slidecar", "--demo", "heavy.csv", "--method", "pd-h-lsd",
                 "--plant-params", "mycar.json", "--out", "heavy-log.csv"});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QFile log(path("heavy-log.csv"));
        QVERIFY(log.open(QIODevice::ReadOnly));
        QVERIFY(log.readAll().contains("# plant-parameters: mycar.json"));
        // Refusals: exit 2, the key, the value and the range; nothing written.
        QFile bad(path("bad.json"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write(R"({"plant": "slidecar", "parameters": {"servoRate": 500}})");
        bad.close();
        for (const QStringList& command :
             {QStringList{"run", "--plant", "slidecar", "--demo", "car.csv", "--method", "pd",
                          "--plant-params", "bad.json", "--out", "bad-log.csv"},
              QStringList{"table1", "--plant-params", "bad.json", "--trials", "1", "--out",
                          "bad-log.csv"},
              QStringList{"demo", "--plant", "slidecar", "--plant-params", "bad.json", "--out",
                          "bad-log.csv"}}) {
            const CliResult r = cli(command);
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains("bad.json: servoRate = 500 rad/s is outside [0.5, 50] rad/s"),
                     qPrintable(r.err));
            QVERIFY(!QFile::exists(path("bad-log.csv")));
        }
        const CliResult missing =
            cli({"simulate", "--plant", "slidecar", "--zero-action", "--duration", "1",
                 "--plant-params", "nope.json", "--out", "bad-log.csv"});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY2(missing.err.contains("nope.json"), qPrintable(missing.err));
        const CliResult model = cli({"table1", "--perturbation-model", "daily", "--trials", "1"});
        QCOMPARE(model.exitCode, 2);
        QVERIFY2(model.err.contains("'daily' is not one of session, trial"), qPrintable(model.err));
    }

    // The new-car protocol: every plant file of a folder on every style and seed set, the
    // breakdown per variant, each method's trials by their place in the day as CSV and figure.
    // identify: a plant file written with the report beside it; what the data determined,
    // each with its deviation (a short search here: the format, not the accuracy, which
    // test_identification_recovery checks); data that cannot identify refused with exit 2.
    void identify_writesAPlantFileAndSaysWhatTheDataDetermined() {
        QCOMPARE(cli({"demo", "--plant", "slidecar", "--out", "id-demo.csv"}).exitCode, 0);
        const CliResult json =
            cli({"identify", "--plant", "slidecar", "--demo", "id-demo.csv", "--out", "id.json",
                 "--evaluations", "40", "--restarts", "0", "--format", "json"});
        QVERIFY2(json.exitCode == 0, qPrintable(json.err));
        const QJsonObject report = parseJson(json.out);
        const QJsonObject kinetic =
            report.value("parameters").toObject().value("kineticFriction").toObject();
        QVERIFY2(kinetic.contains("value") && kinetic.contains("std") &&
                     kinetic.value("identified").isBool() && kinetic.value("fitted").toBool(),
                 qPrintable(json.out));
        QVERIFY(!report.value("parameters")
                     .toObject()
                     .value("mass")
                     .toObject()
                     .value("fitted")
                     .toBool());
        QVERIFY(report.value("segments").toArray().size() >= 4);
        QVERIFY(report.value("positionRms").toDouble() >= 0.0);
        // The file is a plant file: the car loads it.
        const CliResult check = cli({"plant", "--plant", "slidecar", "--plant-params", "id.json"});
        QVERIFY2(check.exitCode == 0, qPrintable(check.err));
        QFile file(path("id.json"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject written = QJsonDocument::fromJson(file.readAll()).object();
        QVERIFY(written.value("identification").toObject().contains("parameters"));
        QVERIFY(written.value("description").toString().contains("id-demo.csv"));
        // mpc plans through it (--model), on the run and the rig alike; a file that is not a
        // plant file is refused naming the option.
        const CliResult planned =
            cli({"run", "--plant", "slidecar", "--demo", "id-demo.csv", "--method", "mpc",
                 "--model", "id.json", "--out", "mpc.csv", "--format", "json"});
        QVERIFY2(planned.exitCode == 0, qPrintable(planned.err));
        const QJsonArray plannedTrials = parseJson(planned.out).value("trials").toArray();
        QVERIFY(plannedTrials.size() == 1);
        // It says which law drove the trial.
        const QString note = plannedTrials.at(0).toObject().value("controllerNote").toString();
        QVERIFY2(note.startsWith(QLatin1String("planned through the model")) ||
                     note.startsWith(QLatin1String("the feedback law drove")),
                 qPrintable(planned.out));
        writeFile(path("not-a-car.json"), "{\"format\": \"something else\"}");
        const CliResult badModel =
            cli({"run", "--plant", "slidecar", "--demo", "id-demo.csv", "--method", "mpc",
                 "--model", "not-a-car.json", "--out", "mpc.csv"});
        QVERIFY2(badModel.exitCode == 2 && badModel.err.contains("--model:"),
                 qPrintable(badModel.err));

        // The first second only: too short.
        QFile demo(path("id-demo.csv"));
        QVERIFY(demo.open(QIODevice::ReadOnly));
        QByteArray cut;
        int kept = 0;
        for (const QByteArray& line : demo.readAll().split('\n')) {
            if (line.startsWith('#') || line.startsWith("t,") || kept++ < 40) {
                cut += line + '\n';
            }
        }
        writeFile(path("id-short.csv"), cut);
        const CliResult refused = cli({"identify", "--plant", "slidecar", "--demo", "id-short.csv",
                                       "--out", "id-short.json"});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains("cannot identify the slidecar from this data: too short"),
                 qPrintable(refused.err));
        QVERIFY(!QFile::exists(path("id-short.json")));
    }

    // On the rig mpc waits for the car's model only where it would plan through one: a turn
    // sliding less than mpc.plan-slide runs without a model, the feedback law driving it, and
    // the trial's line says why.
    void rig_mpcRunsATurnWithoutASlideWithoutAModel() {
        QCOMPARE(cli({"demo", "--plant", "slidecar", "--style", "keyboard-90-right", "--seed", "4",
                      "--out", "turn.csv"})
                     .exitCode,
                 0);
        const CliResult turn =
            cli({"rig", "--virtual", "--demo", "turn.csv", "--method", "mpc", "--trials", "1"});
        QVERIFY2(turn.exitCode == 0, qPrintable(turn.err));
        QVERIFY2(turn.out.contains("mpc: the feedback law drove: the demonstration slides at most"),
                 qPrintable(turn.out));
    }

    void fit_worksOnARobotOutsideTheCatalog() {
        // A robot no catalog knows, flown in closed loop, whose data follow eq. 5 exactly:
        // s_{k+1} = s_k + dt (A s_k + B^T u_k), B = (1, 3).
        QByteArray csv =
            "# prisca-demonstration 1\n# plant: hovercraft\n# dt: 0.025\n"
            "# states: a[m], b[m/s]\n# actions: thrust[1]\nt,a,b,thrust\n";
        double a = 0.0, b = 0.0;
        for (int k = 0; k < 2000; ++k) {
            const double t = k * 0.025;
            const double u = 0.6 * std::sin(0.5 * t) - 0.8 * a - 0.3 * b;
            csv += QByteArray::number(t, 'g', 10) + ',' + QByteArray::number(a, 'g', 17) + ',' +
                   QByteArray::number(b, 'g', 17) + ',' + QByteArray::number(u, 'g', 17) + '\n';
            const double da = -0.8 * a + 0.5 * b + 1.0 * u, db = -1.5 * a - 2.0 * b + 3.0 * u;
            a += 0.025 * da;
            b += 0.025 * db;
        }
        writeFile(path("hover.csv"), csv);
        const CliResult noMask = cli({"fit", "--demo", "hover.csv"});
        QCOMPARE(noMask.exitCode, 2);
        QVERIFY2(noMask.err.contains("hovercraft") && noMask.err.contains("--mask"),
                 qPrintable(noMask.err));
        const CliResult r =
            cli({"fit", "--demo", "hover.csv", "--mask", "1,1", "--drift", "--format", "json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject fit = parseJson(r.out);
        QCOMPARE(fit.value("plant").toString(), QStringLiteral("hovercraft"));
        const QJsonArray bv = fit.value("Bv").toArray()[0].toArray();
        QVERIFY(std::abs(bv[0].toDouble() - 1.0) < 0.05);  // within 5 %
        QVERIFY(std::abs(bv[1].toDouble() - 3.0) < 0.15);
        QVERIFY(std::abs(fit.value("A").toArray()[1].toArray()[1].toDouble() + 2.0) < 0.1);
        // Without the drift the closed loop biases the fit, and the sign conflict shows the
        // value the constraint replaced.
        const QJsonObject plain =
            parseJson(cli({"fit", "--demo", "hover.csv", "--mask", "1,1", "--format", "json"}).out);
        QVERIFY(std::abs(plain.value("Bv").toArray()[0].toArray()[1].toDouble() - 3.0) > 1.0);
        QVERIFY(plain.value("unconstrainedBv").toArray()[0].toArray()[1].toDouble() < 0.0);
        QCOMPARE(cli({"fit", "--demo", "hover.csv", "--mask", "1,1", "--angles", "7"}).exitCode, 2);
    }

    void fit_reportsTheMappingAndDiagnosticsAsJson() {
        const CliResult r = cli({"fit", "--demo", "car.csv", "--format", "json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject fit = parseJson(r.out);
        QCOMPARE(fit.value("B").toArray().size(), 2);
        QCOMPARE(fit.value("B").toArray().at(0).toArray().size(), 6);
        QVERIFY(fit.value("B").toArray().at(0).toArray().at(3).toDouble() > 0.5);  // throttle -> vx
        // R^2 by state for the five states the default mask lets a control act on; vy has none.
        QCOMPARE(fit.value("rSquared").toObject().keys(),
                 (QStringList{"psi", "r", "vx", "x", "y"}));
        QCOMPARE(fit.value("statesNoControlActsOn").toArray(), QJsonArray{"vy"});
        QVERIFY2(!r.out.contains("null") && !r.out.contains("nan"), qPrintable(r.out));
        QVERIFY(fit.contains("warnings") && fit.contains("signConflicts"));
        // A mask that says throttle does nothing to vx: that entry is 0.
        const CliResult masked = cli(
            {"fit", "--demo", "car.csv", "--mask", "1,0,0,0,0,0;0,1,1,0,0,1", "--format", "json"});
        QCOMPARE(masked.exitCode, 0);
        QCOMPARE(parseJson(masked.out).value("B").toArray().at(0).toArray().at(3).toDouble(), 0.0);
        // R^2 is not defined for the states no control acts on: named, never null.
        QVERIFY2(!masked.out.contains("null"), qPrintable(masked.out));
        QCOMPARE(parseJson(masked.out).value("rSquared").toObject().size(), 4);
        QCOMPARE(parseJson(masked.out).value("statesNoControlActsOn").toArray(),
                 (QJsonArray{"vx", "vy"}));
        const CliResult text = cli({"fit", "--demo", "car.csv"});
        QCOMPARE(text.exitCode, 0);
        QVERIFY(text.out.contains("R^2") && text.out.contains("steering"));
    }

    void simulate_replaysActionsOrCoastsFromTheGivenState() {
        writeFile(path("actions.csv"),
                  "# full throttle, straight\nthrottle,steering\n1,0\n1,0\n1,0\n1,0\n");
        const CliResult r =
            cli({"simulate", "--plant", "slidecar", "--initial", "0,0,0,0,0,0", "--actions",
                 "actions.csv", "--out", "sim.csv", "--format", "json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject summary = parseJson(r.out);
        QCOMPARE(summary.value("steps").toInt(), 4);
        const double vx = summary.value("finalState").toArray().at(3).toDouble();
        QVERIFY(vx > 0.1);
        // The file holds the start and every step: 5 rows, the last with the final state.
        const QList<double> last = lastRow(path("sim.csv"));
        QCOMPARE(last.size(), 9);
        QVERIFY(std::abs(last[4] - vx) < 1e-12);
        // Coasting from 2 m/s with zero action: it slows down but keeps going straight.
        const CliResult coast =
            cli({"simulate", "--plant", "slidecar", "--initial", "0,0,0,2,0,0", "--zero-action",
                 "--duration", "1", "--out", "coast.csv", "--format", "json"});
        QCOMPARE(coast.exitCode, 0);
        const QJsonArray end = parseJson(coast.out).value("finalState").toArray();
        QVERIFY(end.at(0).toDouble() > 1.0 && end.at(3).toDouble() < 2.0 &&
                end.at(3).toDouble() > 0.5);
        QCOMPARE(end.at(1).toDouble(), 0.0);
        // A demonstration file is a valid action file too (extra columns ignored).
        QCOMPARE(
            cli({"simulate", "--plant", "slidecar", "--actions", "car.csv", "--out", "replay.csv"})
                .exitCode,
            0);
    }

    // Every method's parameters come from its catalog entry, and docs/methods.md is what
    // `methods --format md` prints (regenerate it with that command when a parameter changes).
    void methods_listEachMethodsParametersAndTheDocsAreGenerated() {
        const CliResult json = cli({"methods", "--format", "json"});
        QCOMPARE(json.exitCode, 0);
        const QJsonArray methods = parseJson(json.out).value("methods").toArray();
        QCOMPARE(methods.size(), 14);
        QJsonObject lqr;
        for (const QJsonValue& m : methods) {
            if (m.toObject().value("id").toString() == QLatin1String("lqr")) {
                lqr = m.toObject();
            }
        }
        const QJsonArray parameters = lqr.value("parameters").toArray();
        QCOMPARE(parameters.size(), 3);
        const QJsonObject effort = parameters.at(0).toObject();
        QCOMPARE(effort.value("name").toString(), QStringLiteral("lqr.effort"));
        QVERIFY(effort.value("perControl").toBool());
        QCOMPARE(effort.value("defaults").toObject().keys(),
                 QStringList({"acrobot", "aircraft", "diffdrive", "slidecar"}));
        const CliResult text = cli({"methods", "--plant", "slidecar"});
        QCOMPARE(text.exitCode, 0);
        QVERIFY2(text.out.contains("prisca.gamma [-] 0 .. 1; default slidecar 0.95"),
                 qPrintable(text.out));
        const CliResult md = cli({"methods", "--format", "md"});
        QCOMPARE(md.exitCode, 0);
        QFile doc(QStringLiteral(PRISCA_SOURCE_DIR "/docs/methods.md"));
        QVERIFY(doc.open(QIODevice::ReadOnly));
        QVERIFY2(QString::fromUtf8(doc.readAll()) == md.out,
                 "docs/methods.md is stale: regenerate it with "
                 "`prisca-cli methods --format md > docs/methods.md`");
        // The parameters a run takes are the ones listed.
        const CliResult run = cli({"run", "--plant", "slidecar", "--demo", "car.csv", "--method",
                                   "lqr", "--param", "lqr.effort=0.3,0.5", "--param",
                                   "lqr.terminal=100", "--out", "lqr.csv", "--format", "json"});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    }

    void help_documentsEachCommandsOptions() {
        for (const char* command :
             {"simulate", "demo", "fit", "methods", "run", "table1", "curve", "lemma41"}) {
            const CliResult r = cli({command, "--help"});
            QCOMPARE(r.exitCode, 0);
            QVERIFY2(r.out.contains("--format"), qPrintable(r.out));
        }
    }
};

QTEST_GUILESS_MAIN(TestCliTaskCommands)
#include "test_cli_task_commands.moc"
