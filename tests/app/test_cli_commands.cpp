// prisca-cli simulate, demo, fit and run end to end on real files, and every bad-input path:
// one line on stderr naming the problem, exit code 2, nothing written.
#include <QDir>
#include <QElapsedTimer>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "core/FileIo.h"
#include "devices/PseudoTerminal.h"
#include "devices/SyntheticCamera.h"
#include "rig/PreTrialCheck.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"

#include <fcntl.h>
#include <pty.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>
#include <cmath>
#include <csignal>
#include <memory>

namespace {

// A pty for a CLI's link whose ends the CLI does not inherit: closing them unplugs it for good.
bool keptFromChildren(const Pty& pty) {
    return pty.master >= 0 && fcntl(pty.master, F_SETFD, FD_CLOEXEC) == 0 &&
           fcntl(pty.slave, F_SETFD, FD_CLOEXEC) == 0;
}

struct CliResult {
    int exitCode = -1;
    QString out;
    QString err;
};

CliResult runCli(const QStringList& arguments, const QString& directory) {
    QProcess process;
    process.setWorkingDirectory(directory);
    process.start(QStringLiteral(PRISCA_CLI), arguments);
    CliResult result;
    if (!process.waitForFinished(120000) || process.exitStatus() != QProcess::NormalExit) {
        result.err = QStringLiteral("did not finish: ") + process.errorString();
        return result;
    }
    result.exitCode = process.exitCode();
    result.out = QString::fromLocal8Bit(process.readAllStandardOutput());
    result.err = QString::fromLocal8Bit(process.readAllStandardError());
    return result;
}

QJsonObject parseJson(const QString& text) {
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(text.toUtf8(), &error);
    if (error.error != QJsonParseError::NoError || !document.isObject()) {
        qWarning("not JSON: %s\n%s", qPrintable(error.errorString()), qPrintable(text));
        return {};
    }
    return document.object();
}

void writeFile(const QString& path, const QByteArray& content) {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(content);
}

// The last data row of a CSV written by the CLI, as numbers.
QList<double> lastRow(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return {};
    }
    const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
    QList<double> values;
    for (const QByteArray& field : lines.last().split(',')) {
        values << field.toDouble();
    }
    return values;
}

}  // namespace

class TestCliCommands : public QObject {
    Q_OBJECT
  private:
    QTemporaryDir dir_;
    QString path(const QString& name) const { return dir_.filePath(name); }
    CliResult cli(const QStringList& arguments) const { return runCli(arguments, dir_.path()); }

  private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        const CliResult demo =
            cli({"demo", "--plant", "slidecar", "--seed", "2", "--out", "car.csv"});
        QCOMPARE(demo.exitCode, 0);
        QVERIFY(QFile::exists(path("car.csv")));
    }

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

    void rig_virtualRunsTheWholeChainHeadless() {
        // Camera -> tracker -> estimator -> PRISCA -> link -> pseudo-terminal -> car, in real
        // time: one trial of the scripted demonstration (about 6 s).
        const CliResult r = cli({"rig", "--virtual", "--trials", "1", "--format", "json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject root = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(root.value("method").toString(), QStringLiteral("prisca"));
        const QJsonArray trials = root.value("trials").toArray();
        QCOMPARE(trials.size(), 1);
        const QJsonObject t = trials[0].toObject();
        QVERIFY(t.value("frames").toInt() > 100);
        QVERIFY(!t.value("stopped").toBool() && !t.value("failsafe").toBool());
        // The trial lasts the demonstration plus its settling by the frames' clock (4 + 2 s).
        QVERIFY2(t.value("seconds").toDouble() > 5.9 && t.value("seconds").toDouble() < 6.2,
                 qPrintable(QString::number(t.value("seconds").toDouble())));
        QVERIFY(t.value("framesWithPose").toInt() >= t.value("frames").toInt() - 2);
        QVERIFY(t.value("linkFramesDecoded").toDouble() >= t.value("frames").toInt());
        const double miss = t.value("finalPositionErrorCm").toDouble(-1.0);
        QVERIFY2(miss >= 0.0 && miss < 50.0, qPrintable(QString::number(miss)));
        // What a rig cannot run, and the real rig, are refused with the reason.
        // The rig's one rule, in the pre-trial check's words, before any device is opened.
        CliResult bad = cli({"rig", "--virtual", "--method", "oracle"});
        QVERIFY2(bad.exitCode == 2 &&
                     bad.err.contains(QStringLiteral("--method oracle: ") +
                                      prisca::rig::methodRigProblem(true, false, QString())),
                 qPrintable(bad.err));
        for (const QString& id : prisca::sim::MethodCatalog::ids()) {
            const prisca::sim::MethodSpec* spec = prisca::sim::MethodCatalog::find(id);
            if (spec->trainsOffline() && !spec->simulationOnly) {
                bad = cli({"rig", "--virtual", "--method", id});
                QVERIFY2(bad.exitCode == 2 && bad.err.contains(prisca::rig::methodRigProblem(
                                                  false, true, spec->label)),
                         qPrintable(bad.err));
            }
        }
        bad = cli({"rig", "--trials", "1"});
        QVERIFY(bad.exitCode != 0 && bad.err.contains("--virtual"));
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
        QVERIFY(QFile::exists(path(plant + "-" + method + ".csv")));
    }

    void link_sendsTheChannelsOnAPseudoTerminalThenFailsafe() {
        // The far end of the "transmitter": the test reads the pty master.
        int master = -1, slave = -1;
        char name[256] = {};
        termios raw{};
        cfmakeraw(&raw);
        QCOMPARE(openpty(&master, &slave, name, &raw, nullptr), 0);
        fcntl(master, F_SETFL, fcntl(master, F_GETFL) | O_NONBLOCK);
        QProcess process;
        process.setWorkingDirectory(dir_.path());
        process.start(QStringLiteral(PRISCA_CLI),
                      {"link", "--port", QString::fromLocal8Bit(name), "--protocol", "sbus",
                       "--channels", "1400, 1500,1700", "--duration", "1", "--format", "json"});
        QByteArray received;
        char buffer[4096];
        while (!process.waitForFinished(10)) {
            const ssize_t n = ::read(master, buffer, sizeof buffer);
            if (n > 0)
                received.append(buffer, static_cast<int>(n));
        }
        for (ssize_t n; (n = ::read(master, buffer, sizeof buffer)) > 0;) {
            received.append(buffer, static_cast<int>(n));
        }
        ::close(master);
        ::close(slave);
        QCOMPARE(process.exitCode(), 0);
        const QJsonObject summary = parseJson(QString::fromUtf8(process.readAllStandardOutput()));
        QCOMPARE(summary.value("protocol").toString(), QStringLiteral("sbus"));
        const int frames = summary.value("framesSent").toInt();
        QVERIFY2(frames >= 40 && frames <= 70, qPrintable(QString::number(frames)));
        // SBUS frames, 25 bytes each: the channels as given, then failsafe at the end.
        QVERIFY(received.size() >= 25 * 40);
        int start = received.indexOf('\x0f');
        QVERIFY(start >= 0);
        const auto channel = [&](int frameStart, int index) {
            int value = 0;
            for (int b = 0; b < 11; ++b) {
                const int bit = index * 11 + b;
                if (static_cast<unsigned char>(received[frameStart + 1 + bit / 8]) &
                    (1 << (bit % 8))) {
                    value |= 1 << b;
                }
            }
            return value;
        };
        QCOMPARE(channel(start, 0), 831);   // 1400 us
        QCOMPARE(channel(start, 1), 992);   // 1500 us
        QCOMPARE(channel(start, 2), 1312);  // 1700 us
        const int last = static_cast<int>(received.size()) - 25;
        QCOMPARE(static_cast<unsigned char>(received[last]), 0x0f);
        QCOMPARE(channel(last, 0), 992);  // failsafe: everything back to centre
        QCOMPARE(channel(last, 2), 992);
        QCOMPARE(static_cast<unsigned char>(received[last + 23]) & 0x08, 0x08);
    }

    // The link ended by a signal: SIGTERM and SIGINT send failsafe frames before exiting and say
    // so; unplugged first, it says no failsafe frame could go out; SIGKILL leaves the last
    // command as the last frame and silence after it (the receiver's own failsafe then acts).
    void link_endedBySignals_data() {
        QTest::addColumn<int>("signal");
        QTest::addColumn<bool>("unplugFirst");
        QTest::newRow("SIGTERM") << int(SIGTERM) << false;
        QTest::newRow("SIGINT") << int(SIGINT) << false;
        QTest::newRow("SIGTERM while unplugged") << int(SIGTERM) << true;
        QTest::newRow("SIGKILL") << int(SIGKILL) << false;
    }

    void link_endedBySignals() {
        QFETCH(int, signal);
        QFETCH(bool, unplugFirst);
        Pty pty;
        QVERIFY(keptFromChildren(pty));
        QTemporaryDir ports;
        const QString port = ports.filePath("ttyRC");  // a stable path, as udev gives
        QVERIFY(QFile::link(pty.path, port));
        QProcess process;
        process.start(QStringLiteral(PRISCA_CLI),
                      {"link", "--port", port, "--protocol", "sbus", "--channels", "1400,1500,1700",
                       "--duration", "600"});
        QByteArray received;
        const auto drain = [&] { received += pty.read(); };
        // Wait on the frames themselves: ten of them.
        QVERIFY(QTest::qWaitFor(
            [&] {
                drain();
                return received.size() >= 250;
            },
            30000));
        if (unplugFirst) {
            pty.closeAll();
            QFile::remove(port);  // the device node goes with the cable
        }
        QElapsedTimer sinceSignal;
        sinceSignal.start();
        ::kill(static_cast<pid_t>(process.processId()), signal);
        qint64 lastByteMs = -1;
        while (!process.waitForFinished(5)) {
            if (!unplugFirst) {
                const qsizetype before = received.size();
                drain();
                if (received.size() > before) {
                    lastByteMs = sinceSignal.elapsed();
                }
            }
        }
        if (!unplugFirst) {
            drain();
            pty.closeAll();
        }
        const QString out = QString::fromLocal8Bit(process.readAllStandardOutput());
        if (signal == SIGKILL) {
            QCOMPARE(process.exitStatus(), QProcess::CrashExit);
            // The last whole frame is the command, not failsafe: nothing ran after the kill.
            const qsizetype last = received.lastIndexOf('\x0f', received.size() - 25);
            QVERIFY(last >= 0);
            QCOMPARE(static_cast<unsigned char>(received[last + 23]) & 0x08, 0);  // no failsafe
            if (lastByteMs < 0) {
                qInfo("SIGKILL: no byte after the signal, silence from then on");
            } else {
                qInfo("SIGKILL: the last bytes %lld ms after the signal, then silence",
                      static_cast<long long>(lastByteMs));
            }
            return;
        }
        QCOMPARE(process.exitCode(), 128 + signal);
        if (unplugFirst) {
            QVERIFY2(out.contains("no failsafe frame could go out"), qPrintable(out));
            return;
        }
        QVERIFY2(out.contains("ending in failsafe"), qPrintable(out));
        // The last frame on the wire carries SBUS's failsafe flag.
        const qsizetype last = received.size() - 25;
        QCOMPARE(static_cast<unsigned char>(received[last]), 0x0f);
        QVERIFY2(static_cast<unsigned char>(received[last + 23]) & 0x08,
                 "the last frame is not failsafe");
    }

    // The cable pulled and put back while prisca-cli link runs: the pty's far end goes away
    // and a new one appears behind the same path; frames resume on it.
    void link_resumesAfterUnplugAndReplug() {
        auto first = std::make_unique<Pty>();
        QVERIFY(keptFromChildren(*first));
        QTemporaryDir ports;
        const QString port = ports.filePath("ttyRC");
        QVERIFY(QFile::link(first->path, port));
        QProcess process;
        process.start(QStringLiteral(PRISCA_CLI),
                      {"link", "--port", port, "--protocol", "sbus", "--channels", "1400,1500,1700",
                       "--duration", "600"});
        QByteArray received;
        QVERIFY(QTest::qWaitFor(
            [&] {
                received += first->read();
                return received.size() >= 250;
            },
            30000));
        first.reset();  // unplugged: the device node goes with the cable
        QFile::remove(port);
        Pty second;
        QVERIFY(keptFromChildren(second));
        QElapsedTimer sincePlug;
        sincePlug.start();
        QVERIFY(QFile::link(second.path, port));
        QByteArray resumed;
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         resumed += second.read();
                         return resumed.size() >= 250;  // ten frames on the new port
                     },
                     30000),
                 qPrintable(process.readAllStandardError()));
        qInfo("frames resumed on the replugged port; ten frames %lld ms after the plug",
              static_cast<long long>(sincePlug.elapsed()));
        const qsizetype at = resumed.indexOf('\x0f');
        QVERIFY(at >= 0 && at + 25 <= resumed.size());
        QCOMPARE(static_cast<unsigned char>(resumed[at + 24]), 0x00);  // an SBUS frame's end
        ::kill(static_cast<pid_t>(process.processId()), SIGTERM);
        QVERIFY(process.waitForFinished(30000));
        QCOMPARE(process.exitCode(), 128 + SIGTERM);
    }

    // SIGTERM or SIGINT in the middle of a trial of prisca-cli rig --virtual: the trial ends
    // stopped, the link's last frames are failsafe, and the car's receiver is left neutral.
    void rig_endedBySignalLeavesTheCarNeutral_data() {
        QTest::addColumn<int>("signal");
        QTest::newRow("SIGTERM") << int(SIGTERM);
        QTest::newRow("SIGINT") << int(SIGINT);
    }

    void rig_endedBySignalLeavesTheCarNeutral() {
        QFETCH(int, signal);
        QProcess process;
        process.start(QStringLiteral(PRISCA_CLI),
                      {"rig", "--virtual", "--trials", "1", "--format", "json"});
        QByteArray err;
        // One second into the trial the car is being driven (the demonstration's commands).
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         process.waitForReadyRead(5);
                         err += process.readAllStandardError();
                         return err.contains("rig: trial 1/1: 1 of") ||
                                process.state() == QProcess::NotRunning;
                     },
                     60000),
                 err.constData());
        QVERIFY2(process.state() == QProcess::Running, err.constData());
        ::kill(static_cast<pid_t>(process.processId()), signal);
        QVERIFY(process.waitForFinished(30000));
        QCOMPARE(process.exitCode(), 128 + signal);
        const QJsonObject out = QJsonDocument::fromJson(process.readAllStandardOutput()).object();
        const QJsonObject trial = out["trials"].toArray().at(0).toObject();
        QVERIFY2(trial["stopped"].toBool(), qPrintable(QJsonDocument(out).toJson()));
        QVERIFY(trial["linkFramesDecoded"].toDouble() > 0);
        // The frame-to-command latency's median, 99th percentile and worst, in order.
        const double median = trial["medianFrameToCommandMs"].toDouble(-2.0);
        const double p99 = trial["p99FrameToCommandMs"].toDouble(-2.0);
        const double worst = trial["worstFrameToCommandMs"].toDouble(-2.0);
        QVERIFY2(median >= 0.0 && median <= p99 && p99 <= worst,
                 qPrintable(QJsonDocument(trial).toJson()));
        const QJsonArray held = out["receiverLastCommand"].toArray();
        QCOMPARE(held.size(), 2);  // steering, throttle
        for (const QJsonValue& u : held) {
            QVERIFY2(std::abs(u.toDouble()) <= 2.0 / 512.0,
                     qPrintable(QJsonDocument(out).toJson()));
        }
        QVERIFY(out["receiverNeutral"].toBool());
    }

    // Input that means nothing is refused by name, and every message names the right culprit
    // (issue 23's probes, each by its own command).
    void reliability_meaninglessInputIsRefusedByName() {
        // A start state the physics cannot hold: refused before it reaches it (it aborted).
        CliResult r = cli({"simulate", "--plant", "slidecar", "--zero-action", "--duration", "1",
                           "--initial", "0,0,1e300,0,0,0", "--out", "s.csv"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--initial: psi = 1e+300 rad is outside [-10000, 10000] rad"),
                 qPrintable(r.err));
        for (const QString plant : {"acrobot", "diffdrive"}) {
            const QString initial = plant == "acrobot" ? "0,0,1e300,0" : "0,0,1e300,0,0,0";
            r = cli({"simulate", "--plant", plant, "--zero-action", "--duration", "1", "--initial",
                     initial, "--out", "s.csv"});
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains("--initial:"), qPrintable(r.err));
        }
        // A position far off is blamed on --initial, not on the output file.
        r = cli({"simulate", "--plant", "slidecar", "--zero-action", "--duration", "1", "--initial",
                 "1e7,0,0,0,0,0", "--out", "s.csv"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--initial: x = 1e+07 m") && !r.err.contains("s.csv"),
                 qPrintable(r.err));
        // A latency shift that leaves one pair to fit on (T samples give T - 2 - d pairs).
        QFile demoFile(path("car.csv"));
        QVERIFY(demoFile.open(QIODevice::ReadOnly));
        int samples = 0;
        for (const QByteArray& row : demoFile.readAll().split('\n')) {
            samples += !row.isEmpty() && !row.startsWith('#') && !row.startsWith('t') ? 1 : 0;
        }
        const QString latency = QString::number(samples - 3);
        r = cli({"fit", "--demo", "car.csv", "--latency", latency});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("latency " + latency + " and response 1 that leaves 1 pairs") &&
                     r.err.contains("at least 4 are needed"),
                 qPrintable(r.err));
        // A demonstration whose actions never change: no fit; a run says so.
        QFile source(path("car.csv"));
        QVERIFY(source.open(QIODevice::ReadOnly));
        QByteArray constant;
        for (const QByteArray& row : source.readAll().split('\n')) {
            if (row.isEmpty() || row.startsWith('#') || row.startsWith('t')) {
                constant += row + '\n';
                continue;
            }
            QList<QByteArray> fields = row.split(',');
            fields[fields.size() - 2] = "0.3";  // throttle held
            fields[fields.size() - 1] = "0";    // steering centred
            constant += fields.join(',') + '\n';
        }
        QVERIFY(prisca::core::writeFileAtomically(path("held.csv"), constant, nullptr));
        r = cli({"fit", "--demo", "held.csv"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("held.csv: the actions never change"), qPrintable(r.err));
        r = cli({"run", "--plant", "slidecar", "--demo", "held.csv", "--method", "playback",
                 "--out", "held-run.csv"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.err.contains("warning: held.csv: the actions never change"), qPrintable(r.err));
        // Outputs never replace what is not a regular file.
        const QString fifo = path("out.fifo");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        r = cli({"demo", "--plant", "slidecar", "--out", fifo});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(fifo) && r.err.contains("not a regular file"), qPrintable(r.err));
        QFileInfo stillFifo(fifo);
        QVERIFY(stillFifo.exists() && !stillFifo.isFile());
        // A FIFO as the video: refused at once instead of blocking in the decoder's open.
        const prisca::devices::FloorCalibration floor = prisca::devices::syntheticCeilingCamera();
        QString error;
        QVERIFY(floor.save(path("floor.json"), &error));
        r = cli({"track", "--video", fifo, "--calibration", "floor.json", "--out", "p.csv"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("not a regular file"), qPrintable(r.err));
        // Valid JSON that is not a calibration.
        QVERIFY(prisca::core::writeFileAtomically(path("list.json"), "[]", nullptr));
        r = cli({"track", "--video", "car.csv", "--calibration", "list.json", "--out", "p.csv"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("valid JSON, but not a floor calibration") &&
                     !r.err.contains("no error occurred"),
                 qPrintable(r.err));
        // A bare port name is the file of that name here, and a regular file is no port.
        QVERIFY(prisca::core::writeFileAtomically(path("A"), "not a device", nullptr));
        r = cli({"link", "--port", "A", "--channels", "1500"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QDir(dir_.path()).absoluteFilePath("A") +
                                ": is a regular file, not a serial device"),
                 qPrintable(r.err));
    }

    void link_badInputGivesOneLineAndExitTwo() {
        CliResult r = cli({"link", "--port", "/dev/null", "--channels", "1500,abc"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("CH2") && r.err.count('\n') == 1, qPrintable(r.err));
        r = cli({"link", "--port", "/dev/null", "--protocol", "ppm", "--channels", "1500"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("ppm"), qPrintable(r.err));
        r = cli({"link", "--port", "/dev/no-such-transmitter", "--channels", "1500", "--duration",
                 "3"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("/dev/no-such-transmitter"), qPrintable(r.err));
        r = cli({"link", "--port", "/dev/null", "--channels", "1500,2500"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("800 to 2200"), qPrintable(r.err));
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

    void badInput_oneLineErrorExitTwoNothingWritten_data() {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("mentions");
        writeFile(path("bad-actions.csv"), "throttle,steering\n1,0\n1,abc\n");
        writeFile(path("no-steering.csv"), "throttle\n1\n");
        writeFile(path("short-actions.csv"), "throttle,steering\n1,0\n1,0\n");
        writeFile(
            path("bad-demo.csv"),
            "# prisca-demonstration 1\n# plant: slidecar\n# dt: 0.025\n"
            "# states: x[m], y[m], psi[rad], vx[m/s], vy[m/s], r[rad/s]\n"
            "# actions: throttle[1], steering[1]\n"
            "t,x,y,psi,vx,vy,r,throttle,steering\n0,0,0,0,0,0,0,0,0\n0.025,0,0,0,nan,0,0,0,0\n");
        const QStringList out = {"--out", "never.csv"};
        QTest::newRow("simulate: no plant")
            << (QStringList{"simulate", "--zero-action", "--duration", "1"} + out)
            << "--plant is required";
        QTest::newRow("simulate: unknown plant")
            << (QStringList{"simulate", "--plant", "boat", "--zero-action", "--duration", "1"} +
                out)
            << "unknown plant 'boat'";
        QTest::newRow("simulate: no actions")
            << (QStringList{"simulate", "--plant", "slidecar"} + out) << "exactly one of --actions";
        QTest::newRow("simulate: both actions")
            << (QStringList{"simulate", "--plant", "slidecar", "--zero-action", "--actions",
                            "a.csv", "--duration", "1"} +
                out)
            << "exactly one of --actions";
        QTest::newRow("simulate: zero without duration")
            << (QStringList{"simulate", "--plant", "slidecar", "--zero-action"} + out)
            << "--zero-action needs --duration";
        QTest::newRow("simulate: initial count")
            << (QStringList{"simulate", "--plant", "slidecar", "--zero-action", "--duration", "1",
                            "--initial", "0,0"} +
                out)
            << "--initial has 2 values";
        QTest::newRow("simulate: initial text")
            << (QStringList{"simulate", "--plant", "acrobot", "--zero-action", "--duration", "1",
                            "--initial", "0,x,0,0"} +
                out)
            << "'x', for theta2";
        QTest::newRow("simulate: bad duration")
            << (QStringList{"simulate", "--plant", "slidecar", "--zero-action", "--duration",
                            "-3"} +
                out)
            << "--duration must lie in";
        QTest::newRow("simulate: missing actions file")
            << (QStringList{"simulate", "--plant", "slidecar", "--actions", "nope.csv"} + out)
            << "nope.csv: no such file";
        QTest::newRow("simulate: bad action value")
            << (QStringList{"simulate", "--plant", "slidecar", "--actions", "bad-actions.csv"} +
                out)
            << "bad-actions.csv:3:2: 'abc'";
        QTest::newRow("simulate: action column missing")
            << (QStringList{"simulate", "--plant", "slidecar", "--actions", "no-steering.csv"} +
                out)
            << "no column 'steering'";
        QTest::newRow("simulate: actions too short")
            << (QStringList{"simulate", "--plant", "slidecar", "--actions", "short-actions.csv",
                            "--duration", "9"} +
                out)
            << "has 2 action rows";
        QTest::newRow("simulate: no out")
            << QStringList{"simulate", "--plant", "slidecar", "--zero-action", "--duration", "1"}
            << "--out is required";
        QTest::newRow("simulate: unwritable out")
            << QStringList{"simulate",   "--plant", "slidecar", "--zero-action",
                           "--duration", "1",       "--out",    "no/such/dir/x.csv"}
            << "no/such/dir/x.csv";
        QTest::newRow("demo: bad seed")
            << (QStringList{"demo", "--plant", "slidecar", "--seed", "-1"} + out)
            << "--seed must lie in";
        QTest::newRow("demo: bad format")
            << (QStringList{"demo", "--plant", "slidecar", "--format", "xml"} + out)
            << "--format must be one of";
        QTest::newRow("demo: stray argument")
            << (QStringList{"demo", "--plant", "slidecar", "extra"} + out)
            << "unexpected argument 'extra'";
        QTest::newRow("fit: missing file")
            << QStringList{"fit", "--demo", "missing.csv"} << "missing.csv";
        QTest::newRow("fit: malformed demo")
            << QStringList{"fit", "--demo", "bad-demo.csv"} << "bad-demo.csv:8:5";
        QTest::newRow("fit: bad mask entry")
            << QStringList{"fit", "--demo", "car.csv", "--mask", "1,0,0,1,0,0;0,1,2,0,0,1"}
            << "row 2, column 3";
        QTest::newRow("fit: mask shape")
            << QStringList{"fit", "--demo", "car.csv", "--mask", "1,0;0,1"} << "--mask is 2 x 2";
        QTest::newRow("fit: bad target")
            << QStringList{"fit", "--demo", "car.csv", "--target", "speed"} << "--target must be";
        QTest::newRow("fit: wrong plant")
            << QStringList{"fit", "--demo", "car.csv", "--plant", "acrobot"}
            << "recorded on 'slidecar', not 'acrobot'";
        QTest::newRow("run: unknown method")
            << (QStringList{"run", "--plant", "slidecar", "--demo", "car.csv", "--method", "lqg"} +
                out)
            << "unknown method 'lqg'";
        QTest::newRow("run: demo of another plant")
            << (QStringList{"run", "--plant", "acrobot", "--demo", "car.csv", "--method", "pd"} +
                out)
            << "recorded on 'slidecar'";
        QTest::newRow("run: gamma out of range")
            << (QStringList{"run", "--plant", "slidecar", "--demo", "car.csv", "--method", "prisca",
                            "--param", "prisca.gamma=1.5"} +
                out)
            << "--param: prisca.gamma: 1.5 is outside 0 .. 1";
        QTest::newRow("run: unknown parameter")
            << (QStringList{"run", "--plant", "slidecar", "--demo", "car.csv", "--method", "prisca",
                            "--param", "prisca.H2=3"} +
                out)
            << "no method has a parameter 'prisca.H2' (one of: prisca.H ";
        QTest::newRow("run: a gain per control")
            << (QStringList{"run", "--plant", "slidecar", "--demo", "car.csv", "--method", "pd",
                            "--param", "pd.kp=1,2,3"} +
                out)
            << "pd.kp takes 2 values (one per control), got 3";
        QTest::newRow("table1: not NAME=VALUE")
            << QStringList{"table1", "--param", "prisca.H"} << "'prisca.H' is not NAME=VALUE";
        QTest::newRow("table1: not a table method")
            << QStringList{"table1", "--methods", "prisca,pegasus"}
            << "'pegasus' is not a Table I method";
        QTest::newRow("table1: not a vehicle")
            << QStringList{"table1", "--plant", "acrobot"} << "planar vehicles";
        QTest::newRow("table1: bad format")
            << QStringList{"table1", "--format", "xlsx"} << "--format must be one of";
        QTest::newRow("curve: no curve for the method")
            << (QStringList{"curve", "--methods", "prisca,pd-selected"} + out)
            << "'pd-selected' has no learning curve";
        QTest::newRow("curve: no out") << QStringList{"curve"} << "--out is required";
        QTest::newRow("lemma41: a grid of more than a minute")
            << (QStringList{"lemma41", "--max-h", "1000", "--gamma-steps", "10000"} + out)
            << "--gamma-steps must lie in [2, 1498] with --max-h 1000, got 10000: the grid "
               "evaluates gamma-steps x max-h x (max-h + 1) terms";
        QTest::newRow("lemma41: gamma finer than the figure")
            << (QStringList{"lemma41", "--gamma-steps", "100000"} + out)
            << "--gamma-steps must lie in [2, 10001], got 100000: a gamma step of 1e-4";
        QTest::newRow("lemma41: horizon too long")
            << (QStringList{"lemma41", "--max-h", "20000"} + out)
            << "--max-h must lie in [1, 10000], got 20000: the grid's time grows";
        QTest::newRow("run: trials not a number")
            << (QStringList{"run", "--plant", "slidecar", "--demo", "car.csv", "--method", "prisca",
                            "--trials", "two"} +
                out)
            << "--trials needs a whole number";
    }
    void badInput_oneLineErrorExitTwoNothingWritten() {
        QFETCH(QStringList, arguments);
        QFETCH(QString, mentions);
        QFile::remove(path("never.csv"));
        const CliResult r = cli(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith(QStringLiteral("prisca-cli: %1: ").arg(arguments.first())),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains(mentions), qPrintable(r.err));
        QCOMPARE(r.err.count(u'\n'), 1);
        QCOMPARE(r.out, QString());
        QVERIFY(!QFile::exists(path("never.csv")));
    }

    // A full disk (a file-size limit of 0, which fails every write as ENOSPC does): every output
    // is refused with exit 2 naming the file, and the previous file stays byte for byte.
    void fullDisk_exitsTwoAndKeepsThePreviousFile_data() {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("output");
        QTest::newRow("demo --out")
            << QStringList{"demo", "--plant", "slidecar", "--out", "o.csv"} << "o.csv";
        QTest::newRow("simulate --out")
            << QStringList{"simulate",   "--plant", "slidecar", "--zero-action",
                           "--duration", "5",       "--out",    "o.csv"}
            << "o.csv";
        QTest::newRow("run --out")
            << QStringList{"run", "--plant",  "slidecar", "--demo", "car.csv", "--method",
                           "pd",  "--trials", "1",        "--out",  "o.csv"}
            << "o.csv";
        QTest::newRow("lemma41 --out") << QStringList{"lemma41", "--out", "o.csv"} << "o.csv";
        QTest::newRow("table1 --out")
            << QStringList{"table1", "--trials", "1",    "--training-trials", "1", "--methods",
                           "pd",     "--out",    "o.csv"}
            << "o.csv";
    }

    void fullDisk_exitsTwoAndKeepsThePreviousFile() {
        QFETCH(QStringList, arguments);
        QFETCH(QString, output);
        QTemporaryDir full;
        QVERIFY(QFile::copy(path("car.csv"), full.filePath("car.csv")));
        const QByteArray previous = "the previous file, which must survive\n";
        writeFile(full.filePath(output), previous);
        if (output != QLatin1String("o.csv")) {
            writeFile(full.filePath("o.csv"), previous);
        }
        QProcess process;
        process.setWorkingDirectory(full.path());
        // The CLI ignores SIGXFSZ, so its writes fail with EFBIG.
        process.start("/bin/sh", QStringList{"-c", "ulimit -f 0 && exec \"$0\" \"$@\"",
                                             QStringLiteral(PRISCA_CLI)} +
                                     arguments);
        QVERIFY(process.waitForFinished(120000));
        QCOMPARE(process.exitStatus(), QProcess::NormalExit);
        const QString err = QString::fromLocal8Bit(process.readAllStandardError());
        QVERIFY2(process.exitCode() == 2, qPrintable(err));
        QVERIFY2(err.contains(output), qPrintable(err));
        QFile kept(full.filePath(output));
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), previous);
        // No temporary file left behind either.
        const QStringList left = QDir(full.path()).entryList(QDir::Files);
        for (const QString& name : left) {
            QVERIFY2(name == "car.csv" || name == "o.csv" || name == output || name == "log.csv",
                     qPrintable(left.join(' ')));
        }
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

    void help_documentsEachCommandsOptions() {
        for (const char* command :
             {"simulate", "demo", "fit", "methods", "run", "table1", "curve", "lemma41"}) {
            const CliResult r = cli({command, "--help"});
            QCOMPARE(r.exitCode, 0);
            QVERIFY2(r.out.contains("--format"), qPrintable(r.out));
        }
    }
};

QTEST_GUILESS_MAIN(TestCliCommands)
#include "test_cli_commands.moc"
