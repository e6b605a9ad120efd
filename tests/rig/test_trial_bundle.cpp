// The trial-bundle reader the window's replay dialog and `prisca-cli replay` share: what it
// refuses (naming the file and line) and what an accepted bundle guarantees the dialog.
#include "core/DemonstrationCsv.h"
#include "rig/TrialBundle.h"
#include "sim/PlantCatalog.h"

#include <QDir>
#include <QFile>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using prisca::rig::BundleSample;
using prisca::rig::TrialBundle;
using prisca::rig::TrialBundleWriter;

namespace {

prisca::core::Demonstration slideCarDemo() {
    return prisca::sim::PlantCatalog::demonstrate(QStringLiteral("slidecar"), 1);
}

// A rig bundle on `plant` with one sample per entry of `poses` (x, y; found).
QString writeBundle(const QTemporaryDir& dir, const QString& name, const QString& plant,
                    const std::vector<std::pair<double, double>>& poses) {
    const QString folder = dir.filePath(name);
    TrialBundleWriter writer;
    QString error;
    const bool opened =
        writer.open(folder, QJsonObject{{"kind", "rig"}, {"method", "pd"}, {"plant", plant}},
                    slideCarDemo(), &error);
    if (!opened) {
        qWarning() << error;
        return {};
    }
    double t = 0.0;
    for (const auto& [x, y] : poses) {
        BundleSample s;
        s.t = t;
        t += 0.04;
        s.found = true;
        s.x = x;
        s.y = y;
        s.psi = 0.1;
        s.state = {x, y, 0.1, 0.0, 0.0, 0.0};
        s.action = {0.2, 0.0};
        writer.append(s);
    }
    writer.finish(QJsonObject{{"failsafe", false}}, &error);
    return folder;
}

// Replaces line `index` (0-based, comment lines counted) of a bundle's samples.csv.
void replaceSampleLine(const QString& folder, int index, const QByteArray& line) {
    QFile file(QDir(folder).filePath("samples.csv"));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QList<QByteArray> lines = file.readAll().split('\n');
    file.close();
    QVERIFY(index < lines.size());
    lines[index] = line;
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(lines.join('\n'));
}

}  // namespace

class TestTrialBundle : public QObject {
    Q_OBJECT
  private slots:
    void aWrittenBundle_readsBack() {
        QTemporaryDir dir;
        const QString folder = writeBundle(dir, "good", "slidecar", {{0.0, 0.0}, {1.0, 0.5}});
        QString error;
        const auto bundle = TrialBundle::load(folder, &error);
        QVERIFY2(bundle, qPrintable(error));
        QCOMPARE(bundle->samples.size(), size_t(2));
        QCOMPARE(bundle->samples[1].x, 1.0);
        QVERIFY(bundle->complete());
    }

    void anUnknownPlant_isRefused() {
        QTemporaryDir dir;
        const QString folder = writeBundle(dir, "b", "hovercraft", {{0.0, 0.0}});
        QString error;
        QVERIFY(!TrialBundle::load(folder, &error));
        QVERIFY2(error.contains("bundle.json: plant 'hovercraft' is not one this build knows") &&
                     error.contains("slidecar"),
                 qPrintable(error));
    }

    void posesOffTheFloor_areRefusedWithTheirLine_data() {
        QTest::addColumn<QByteArray>("line");
        QTest::addColumn<QString>("says");
        QTest::newRow("far out") << QByteArray("0.04,-1,1,1e9,0,0,s,u,0") << "not a floor pose";
        QTest::newRow("not a number")
            << QByteArray("0.04,-1,1,nan,0,0,s,u,0") << "not a floor pose";
        QTest::newRow("empty pose") << QByteArray("0.04,-1,1,,,,s,u,0") << "not a floor pose";
        QTest::newRow("infinite heading")
            << QByteArray("0.04,-1,1,0,0,inf,s,u,0") << "not a floor pose";
        QTest::newRow("a 300-digit time")
            << (QByteArray(300, '9') + ",-1,1,0,0,0,s,u,0") << "is not a trial's time";
        QTest::newRow("no time") << QByteArray("x,-1,1,0,0,0,s,u,0") << "is not a trial's time";
    }

    void posesOffTheFloor_areRefusedWithTheirLine() {
        QFETCH(QByteArray, line);
        QFETCH(QString, says);
        QTemporaryDir dir;
        const QString folder = writeBundle(dir, "b", "slidecar", {{0.0, 0.0}, {1.0, 0.5}});
        replaceSampleLine(folder, 3, line);  // two comment lines, then the samples
        QString error;
        QVERIFY(!TrialBundle::load(folder, &error));
        QVERIFY2(error.contains("samples.csv:4: ") && error.contains(says), qPrintable(error));
    }

    void aPoseNotFound_isNoPose() {
        QTemporaryDir dir;
        const QString folder = writeBundle(dir, "b", "slidecar", {{0.0, 0.0}, {1.0, 0.5}});
        replaceSampleLine(folder, 3, "0.04,-1,0,,,,s,u,1");
        QString error;
        const auto bundle = TrialBundle::load(folder, &error);
        QVERIFY2(bundle, qPrintable(error));
        QVERIFY(!bundle->samples[1].found);
        QVERIFY(std::isnan(bundle->samples[1].x));
        // The last pose found is the first sample's, not (0, 0) from empty fields.
        const QJsonObject summary = prisca::rig::summarizeBundle(*bundle);
        QCOMPARE(summary.value("samplesWithPose").toInt(), 1);
    }

    void aDemonstrationWithoutThePose_isRefused() {
        QTemporaryDir dir;
        const QString folder = writeBundle(dir, "b", "slidecar", {{0.0, 0.0}});
        // Only x and y: the dialog would read a heading column that is not there.
        prisca::core::Demonstration demo = slideCarDemo();
        demo.states = demo.states.leftCols(2).eval();
        demo.stateNames = demo.stateNames.mid(0, 2);
        demo.stateUnits = demo.stateUnits.mid(0, 2);
        QFile::remove(QDir(folder).filePath("demonstration.csv"));
        prisca::core::FileError fileError;
        QVERIFY2(prisca::core::writeDemonstrationCsv(
                     demo, QDir(folder).filePath("demonstration.csv"), &fileError),
                 qPrintable(fileError.toString()));
        QString error;
        QVERIFY(!TrialBundle::load(folder, &error));
        QVERIFY2(error.contains("demonstration.csv: ") && error.contains("of 2 state columns"),
                 qPrintable(error));
    }

    void aLinkOutOfTheBundle_isNotFollowed() {
        QTemporaryDir dir;
        const QString folder = writeBundle(dir, "b", "slidecar", {{0.0, 0.0}});
        QFile::remove(QDir(folder).filePath("samples.csv"));
        QVERIFY(QFile::link(QStringLiteral("/proc/self/environ"),
                            QDir(folder).filePath("samples.csv")));
        QString error;
        QVERIFY(!TrialBundle::load(folder, &error));
        QVERIFY2(error.contains("samples.csv: a symbolic link") && !error.contains("environ"),
                 qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestTrialBundle)
#include "test_trial_bundle.moc"
