// Trial bundles end to end through the CLI: a virtual-rig trial that leaves its fence is saved
// as a bundle and replayed (its samples, frames, the failsafe's reason, its scores); a bundle
// whose writer is killed mid-trial reads up to its last second.
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

#include "support/CliProcess.h"

#include <csignal>

namespace {

using Result = prisca::test::CliResult;

Result cli(const QStringList& arguments, const QString& directory) {
    return prisca::test::runCli(arguments, directory);
}

int sampleLines(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        return 0;
    }
    int n = 0;
    for (const QByteArray& line : f.readAll().split('\n')) {
        n += !line.isEmpty() && !line.startsWith('#');
    }
    return n;
}

}  // namespace

class TestCliBundle : public QObject {
    Q_OBJECT
  private slots:
    void rigTrial_withTheLotOutsideTheFence_doesNotStart() {
        QTemporaryDir dir;
        // A fence 3 m ahead, across the demonstration's path: the pre-trial check refuses.
        const Result r = cli({"rig", "--virtual", "--trials", "1", "--fence",
                              "-0.8,-1.6;3.0,-1.6;3.0,2.0;-0.8,2.0", "--bundle-dir", "bundles"},
                             dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("not ready for a trial (Fence)") &&
                     r.err.contains("outside the fence") && r.err.contains("FAIL Fence"),
                 qPrintable(r.err));
        QVERIFY(!r.out.contains("trial 1:"));
        QVERIFY(QDir(QDir(dir.path()).filePath("bundles"))
                    .entryList(QDir::Dirs | QDir::NoDotAndDotDot)
                    .isEmpty());
    }

    void rigTrial_withAnEmptyFence_isRefused() {
        // An unset shell variable ("--fence $FENCE") must not run the trial unfenced.
        QTemporaryDir dir;
        for (const QString& fence : {QString(), QStringLiteral(";"), QStringLiteral(" ; ;")}) {
            const Result r =
                cli({"rig", "--virtual", "--trials", "1", "--fence", fence}, dir.path());
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains("gives no corner: give at least 3"), qPrintable(r.err));
            QVERIFY(!r.out.contains("trial 1:"));
        }
        // Two corners enclose nothing either.
        const Result r =
            cli({"rig", "--virtual", "--trials", "1", "--fence", "0,0;1,1"}, dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("at least 3 corners, 2 given"), qPrintable(r.err));
    }

    void rigTrial_breakingTheFence_isBundledAndReplayed() {
        QTemporaryDir dir;
        // A fence around the whole path with a speed limit the slide exceeds.
        Result r = cli({"rig", "--virtual", "--trials", "1", "--perturbation", "0", "--fence",
                        "-0.8,-1.6;5.5,-1.6;5.5,2.0;-0.8,2.0", "--max-speed", "2.5", "--bundle-dir",
                        "bundles", "--format", "json"},
                       dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject run = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY(run.value("preTrialCheck").toArray().size() >= 8);
        QCOMPARE(run.value("bundles").toArray().size(), 1);
        const QString bundle = run.value("bundles").toArray().at(0).toString();
        QVERIFY2(run.value("trials")
                     .toArray()
                     .at(0)
                     .toObject()
                     .value("failsafeReason")
                     .toString()
                     .contains("over the fence's"),
                 qPrintable(r.out));
        r = cli({"replay", bundle, "--format", "json"}, dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject replay = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY(replay.value("complete").toBool());
        QCOMPARE(replay.value("kind").toString(), QString("rig"));
        const int samples = replay.value("samples").toInt();
        QCOMPARE(samples, replay.value("result").toObject().value("frames").toInt());
        QVERIFY(samples > 20);
        // 10 frames a second of the trial's video.
        const double seconds = replay.value("seconds").toDouble();
        QVERIFY(std::abs(replay.value("frames").toInt() - seconds * 10.0) <= 2.0);
        QVERIFY(replay.value("result").toObject().value("reason").toString().contains("fence"));
        // The replay's scores from the samples agree with the trial's own.
        QVERIFY(
            std::abs(replay.value("finalPositionErrorCm").toDouble() -
                     replay.value("result").toObject().value("finalPositionErrorCm").toDouble()) <
            0.01);
        r = cli({"replay", bundle}, dir.path());
        QVERIFY2(r.out.contains("ended in failsafe: the car drove at"), qPrintable(r.out));
        // Not a bundle: one line, exit 2.
        r = cli({"replay", "nowhere"}, dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("nowhere"), qPrintable(r.err));
    }

    void simulatedTrials_areBundledToo() {
        QTemporaryDir dir;
        Result r = cli({"demo", "--plant", "slidecar", "--out", "demo.csv"}, dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = cli({"run", "--plant", "slidecar", "--demo", "demo.csv", "--method", "pd-h-lsd",
                 "--trials", "2", "--out", "log.csv", "--bundle-dir", "sim", "--format", "json"},
                dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject run = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const double parked =
            run.value("trials").toArray().at(1).toObject().value("finalPositionErrorCm").toDouble();
        r = cli({"replay", "sim/pd-h-lsd-trial-1", "--format", "json"}, dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject replay = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(replay.value("kind").toString(), QString("simulation"));
        QVERIFY(replay.value("complete").toBool());
        QVERIFY(replay.value("samples").toInt() > 100);
        // The replay's last pose is where the trial ended: the same parking error.
        QVERIFY2(std::abs(replay.value("finalPositionErrorCm").toDouble() - parked) < 1e-6,
                 qPrintable(r.out));
    }

    void failedBundle_keepsTheRunLog() {
        // The bundle folder already holds trial 1's bundle: trial 0's is written, trial 1's is
        // refused, none after it is tried, and the run log still holds every trial.
        QTemporaryDir dir;
        Result r = cli({"demo", "--plant", "slidecar", "--out", "demo.csv"}, dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QDir(dir.path()).mkpath("sim/pd-h-lsd-trial-1"));
        QFile old(dir.filePath("sim/pd-h-lsd-trial-1/bundle.json"));
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("{}");
        old.close();
        r = cli({"run", "--plant", "slidecar", "--demo", "demo.csv", "--method", "pd-h-lsd",
                 "--trials", "3", "--out", "log.csv", "--bundle-dir", "sim"},
                dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--bundle-dir: trial 1:") && r.err.contains("already") &&
                     r.err.contains("the run log log.csv holds every trial"),
                 qPrintable(r.err));
        QFile log(dir.filePath("log.csv"));
        QVERIFY(log.open(QIODevice::ReadOnly));
        QSet<QByteArray> trials;
        for (const QByteArray& line : log.readAll().split('\n')) {
            if (!line.isEmpty() && !line.startsWith('#') && !line.startsWith("trial")) {
                trials.insert(line.left(line.indexOf(',')));
            }
        }
        QCOMPARE(trials.size(), 3);
        QVERIFY(QFile::exists(dir.filePath("sim/pd-h-lsd-trial-0/bundle.json")));
        QVERIFY(!QFile::exists(dir.filePath("sim/pd-h-lsd-trial-2")));
        QCOMPARE(old.size(), qint64(2));  // the old bundle untouched
    }

    void unwritableBundleFolder_leavesNothingBehind() {
        // The bundle parent is a file: each trial's bundle fails, is said, and leaves no folder.
        QTemporaryDir dir;
        QFile file(dir.filePath("taken"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.close();
        const Result r =
            cli({"rig", "--virtual", "--trials", "1", "--bundle-dir", "taken"}, dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains("warning: bundle") && r.err.contains("cannot create the folder"),
                 qPrintable(r.err));
        QVERIFY(r.out.contains("trial 1:"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot),
                 QStringList{"taken"});
    }

    void twoRigsOnOneFolder_keepBothBundles() {
        QTemporaryDir dir;
        QProcess first, second;
        for (QProcess* rig : {&first, &second}) {
            rig->setWorkingDirectory(dir.path());
            rig->start(QStringLiteral(PRISCA_CLI),
                       {"rig", "--virtual", "--trials", "1", "--bundle-dir", "bundles"});
            QVERIFY(rig->waitForStarted());
        }
        for (QProcess* rig : {&first, &second}) {
            QVERIFY(rig->waitForFinished(300000));
            QVERIFY2(rig->exitCode() == 0, rig->readAllStandardError().constData());
        }
        QCOMPARE(QDir(dir.filePath("bundles")).entryList(QDir::Dirs | QDir::NoDotAndDotDot).size(),
                 2);
    }

    void bundle_ofAKilledWriter_readsUpToItsLastSecond() {
        QTemporaryDir dir;
        QProcess rig;
        rig.setWorkingDirectory(dir.path());
        rig.start(QStringLiteral(PRISCA_CLI),
                  {"rig", "--virtual", "--trials", "1", "--bundle-dir", "bundles"});
        QVERIFY(rig.waitForStarted());
        // Wait until the bundle holds more than a second of samples (flushed each second).
        QString samples;
        QVERIFY(QTest::qWaitFor(
            [&] {
                const QStringList made =
                    QDir(dir.filePath("bundles")).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
                if (made.isEmpty()) {
                    return false;
                }
                samples = dir.filePath("bundles/" + made.front() + "/samples.csv");
                return sampleLines(samples) > 40;
            },
            60000));
        ::kill(static_cast<pid_t>(rig.processId()), SIGKILL);
        QVERIFY(rig.waitForFinished(10000));
        const int lines = sampleLines(samples);
        const Result r = cli({"replay", QFileInfo(samples).path(), "--format", "json"}, dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject replay = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY(!replay.value("complete").toBool());
        QVERIFY(replay.value("samples").toInt() >= 40);
        QVERIFY(replay.value("samples").toInt() <= lines);
        QVERIFY(replay.value("seconds").toDouble() >= 1.0);
    }
};

QTEST_GUILESS_MAIN(TestCliBundle)
#include "test_cli_bundle.moc"
