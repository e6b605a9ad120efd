// A demonstration streamed to disk while it is recorded: the header at once, rows as they
// flush, the whole take readable at the end.
#include "core/DemonstrationCsv.h"
#include "core/DemonstrationStream.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace prisca::core;

namespace {

Demonstration header() {
    Demonstration d;
    d.plant = "slidecar";
    d.dt = 0.025;
    d.stateNames = {"x", "v"};
    d.stateUnits = {"m", "m/s"};
    d.actionNames = {"u"};
    d.actionUnits = {"1"};
    return d;
}

QByteArray contents(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace

class TestDemonstrationStream : public QObject {
    Q_OBJECT
  private slots:
    void headerIsOnDiskAtOnceAndRowsWhenTheyFlush() {
        QTemporaryDir dir;
        const QString path = dir.filePath("take/rec.csv");  // the folder is made
        DemonstrationStream stream(60000);                  // no timed flush in this test
        QString error;
        QVERIFY2(stream.open(path, header(), &error), qPrintable(error));
        // Killed now, the take would still be a file that says what it is.
        QVERIFY(contents(path).startsWith("# prisca-demonstration 1\n"));
        const int headerSize = contents(path).size();
        for (int k = 0; k < 4; ++k) {
            QVERIFY(stream.append(k * 0.025, Eigen::Vector2d(0.1 * k, 1.0),
                                  Eigen::VectorXd::Constant(1, 0.5), &error));
        }
        QCOMPARE(contents(path).size(), headerSize);  // pending until a flush
        QVERIFY(stream.flush(&error));
        QVERIFY(contents(path).size() > headerSize);
        QVERIFY(stream.close(&error));
        FileError readError;
        const auto demo = readDemonstrationCsv(path, &readError);
        QVERIFY2(demo, qPrintable(readError.toString()));
        QCOMPARE(demo->length(), 4);
        QCOMPARE(demo->states(3, 0), 0.1 * 3);
        QCOMPARE(demo->plant, QStringLiteral("slidecar"));
    }

    void aZeroIntervalFlushesEveryRow() {
        QTemporaryDir dir;
        const QString path = dir.filePath("rec.csv");
        DemonstrationStream stream(0);
        QString error;
        QVERIFY(stream.open(path, header(), &error));
        int last = contents(path).size();
        for (int k = 0; k < 3; ++k) {
            QVERIFY(
                stream.append(k * 0.025, Eigen::Vector2d(k, 0), Eigen::VectorXd::Zero(1), &error));
            const int now = contents(path).size();
            QVERIFY(now > last);
            last = now;
        }
    }

    void unwritablePathIsNamed() {
        DemonstrationStream stream;
        QString error;
        QVERIFY(!stream.open("/proc/no-such-dir/rec.csv", header(), &error));
        QVERIFY2(error.contains("/proc/no-such-dir/rec.csv"), qPrintable(error));
    }
};

QTEST_APPLESS_MAIN(TestDemonstrationStream)
#include "test_demonstration_stream.moc"
