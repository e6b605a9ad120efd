// The one streaming recorder (the window's driving and the rig's camera): the header on disk at
// once, rows as they flush, samples at their own times onto the format's even steps, a ".part"
// file renamed only when the take ends, and a full disk reported without touching an older file.
#include "core/DemonstrationCsv.h"
#include "core/DemonstrationStream.h"
#include "core/DeviationModel.h"
#include "support/FileSizeLimit.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace prisca::core;

namespace {

Demonstration header(double dt = 0.025) {
    Demonstration d;
    d.plant = "slidecar";
    d.dt = dt;
    d.stateNames = {"x", "psi"};
    d.stateUnits = {"m", "rad"};
    d.actionNames = {"u"};
    d.actionUnits = {"1"};
    return d;
}

const std::vector<int> kAngles{1};

QByteArray contents(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// An older file where the take is going, which must survive until the take ends.
bool writeOlderTake(const QString& path) {
    QFile old(path);
    return old.open(QIODevice::WriteOnly) && old.write("the older take\n") > 0;
}

}  // namespace

class TestDemonstrationStream : public QObject {
    Q_OBJECT
  private slots:
    void headerIsOnDiskAtOnceAndRowsWhenTheyFlush() {
        QTemporaryDir dir;
        const QString path = dir.filePath("take/rec.csv");  // the folder is made
        const QString part = DemonstrationStream::partPath(path);
        DemonstrationStream stream(60000);  // no timed flush in this test
        QString error;
        QVERIFY2(stream.open(path, header(), kAngles, &error), qPrintable(error));
        // Killed now, the take would still be a file that says what it is.
        QVERIFY(contents(part).startsWith("# prisca-demonstration 1\n"));
        QVERIFY(!QFile::exists(path));  // the final name only once the take ends
        const int headerSize = contents(part).size();
        QVERIFY(stream.append(0.0, Eigen::Vector2d(0.0, 1.0), Eigen::VectorXd::Constant(1, 0.5),
                              &error));
        const int firstRowSize = contents(part).size();  // the first row at once
        QVERIFY(firstRowSize > headerSize);
        QVERIFY(readDemonstrationCsv(part, nullptr));  // a demonstration from the first sample on
        for (int k = 1; k < 4; ++k) {
            QVERIFY(stream.append(k * 0.025, Eigen::Vector2d(0.1 * k, 1.0),
                                  Eigen::VectorXd::Constant(1, 0.5), &error));
        }
        QCOMPARE(contents(part).size(), firstRowSize);  // pending until a flush
        QVERIFY(stream.flush(&error));
        QVERIFY(contents(part).size() > firstRowSize);
        QVERIFY2(stream.finish(&error), qPrintable(error));
        QVERIFY(!QFile::exists(part));
        FileError readError;
        const auto demo = readDemonstrationCsv(path, &readError);
        QVERIFY2(demo, qPrintable(readError.toString()));
        QCOMPARE(demo->length(), 4);
        QCOMPARE(demo->states(3, 0), 0.1 * 3);
        QCOMPARE(demo->plant, QStringLiteral("slidecar"));
        QCOMPARE(stream.demonstration().states, demo->states);
    }

    void aZeroIntervalFlushesEveryRow() {
        QTemporaryDir dir;
        const QString path = dir.filePath("rec.csv");
        DemonstrationStream stream(0);
        QString error;
        QVERIFY(stream.open(path, header(), kAngles, &error));
        int last = contents(DemonstrationStream::partPath(path)).size();
        for (int k = 0; k < 3; ++k) {
            QVERIFY(
                stream.append(k * 0.025, Eigen::Vector2d(k, 0), Eigen::VectorXd::Zero(1), &error));
            const int now = contents(DemonstrationStream::partPath(path)).size();
            QVERIFY(now > last);
            last = now;
        }
    }

    void aBurstOfSamples_isFlushedByTheTakesOwnTime() {
        // A backlog of camera frames handled at once: 1.9 s of the take handed over in far less
        // than the quarter second of wall time. The file must still lag the take by at most a
        // quarter second of the take, not hold only its first row.
        QTemporaryDir dir;
        const QString path = dir.filePath("rec.csv");
        const QString part = DemonstrationStream::partPath(path);
        DemonstrationStream stream(250);
        QString error;
        QVERIFY(stream.open(path, header(), kAngles, &error));
        const double last = 1.9;
        for (int k = 0; k * 0.025 <= last + 1e-9; ++k) {
            QVERIFY(stream.append(k * 0.025, Eigen::Vector2d(0.01 * k, 0.0),
                                  Eigen::VectorXd::Zero(1), &error));
        }
        FileError readError;
        const auto onDisk = readDemonstrationCsv(part, &readError);  // as a kill would leave it
        QVERIFY2(onDisk, qPrintable(readError.toString()));
        const double written = (onDisk->length() - 1) * onDisk->dt;
        QVERIFY2(written >= last - 0.25 - 1e-9, qPrintable(QString::number(written)));
    }

    void samplesAtTheirOwnTimes_becomeEvenRows() {
        // A 60 fps camera, 1 ms of jitter on every third frame, frames 10 and 11 lost, and a
        // pose-less gap from frame 50 to 69 (no samples): the rows keep the gap's length. The car
        // drives at 2 m/s along x and turns through psi = pi at 3 rad/s.
        QTemporaryDir dir;
        DemonstrationStream stream;
        QString error;
        QVERIFY(stream.open(dir.filePath("rec.csv"), header(1.0 / 60.0), kAngles, &error));
        const double origin = 1234.5;  // a camera clock's own origin
        double lastTime = 0.0;
        for (int f = 0; f < 120; ++f) {
            if (f == 10 || f == 11 || (f >= 50 && f < 70))
                continue;
            const double t = f / 60.0 + (f % 3 == 1 ? 0.001 : 0.0);
            const Eigen::Vector2d s(2.0 * t, wrapAngle(3.0 + 3.0 * t));
            QVERIFY(stream.append(origin + t, s, Eigen::VectorXd::Constant(1, f < 60 ? 0.5 : 0.0),
                                  &error));
            lastTime = t;
        }
        // Out of order and non-finite samples are ignored.
        QVERIFY(stream.append(origin, Eigen::Vector2d(9, 9), Eigen::VectorXd::Zero(1), &error));
        QVERIFY(stream.append(NAN, Eigen::Vector2d(9, 9), Eigen::VectorXd::Zero(1), &error));
        const Demonstration d = stream.demonstration();
        QCOMPARE(d.length(), static_cast<int>(std::floor(lastTime * 60.0 + 1e-9)) + 1);
        for (int k = 0; k < d.length(); ++k) {
            const double t = k / 60.0;
            QVERIFY(std::abs(d.time[k] - t) < 1e-12);
            QVERIFY2(std::abs(d.states(k, 0) - 2.0 * t) < 1e-9, qPrintable(QString::number(k)));
            // Heading interpolated the short way round across the wrap at pi.
            QVERIFY2(std::abs(wrapAngle(d.states(k, 1) - (3.0 + 3.0 * t))) < 1e-9,
                     qPrintable(QString::number(k)));
        }
        // Each action is the one in force at t_k: 0.5 until frame 49, 0 after the gap.
        QCOMPARE(d.actions(49, 0), 0.5);
        QCOMPARE(d.actions(69, 0), 0.5);  // still frame 49's: the next sample is frame 70
        QCOMPARE(d.actions(70, 0), 0.5);  // frame 70 came 1 ms after t_70
        QCOMPARE(d.actions(71, 0), 0.0);
        QVERIFY2(stream.finish(&error), qPrintable(error));
        FileError readError;
        const auto back = readDemonstrationCsv(dir.filePath("rec.csv"), &readError);
        QVERIFY2(back, qPrintable(readError.toString()));
        QCOMPARE(back->length(), d.length());
    }

    void finishReplacesAnOlderFileWhole_abandonLeavesItAlone() {
        QTemporaryDir dir;
        const QString path = dir.filePath("rec.csv");
        QVERIFY(writeOlderTake(path));
        QString error;
        {
            DemonstrationStream stream;
            QVERIFY(stream.open(path, header(), kAngles, &error));
            QVERIFY(stream.append(0.0, Eigen::Vector2d(0, 0), Eigen::VectorXd::Zero(1), &error));
            stream.abandon();
            QVERIFY(!QFile::exists(DemonstrationStream::partPath(path)));
            QCOMPARE(contents(path), QByteArray("the older take\n"));
        }
        DemonstrationStream stream;
        QVERIFY(stream.open(path, header(), kAngles, &error));
        QVERIFY(stream.append(0.0, Eigen::Vector2d(0, 0), Eigen::VectorXd::Zero(1), &error));
        QVERIFY(stream.append(0.025, Eigen::Vector2d(1, 0), Eigen::VectorXd::Zero(1), &error));
        QCOMPARE(contents(path), QByteArray("the older take\n"));  // untouched while recording
        QVERIFY2(stream.finish(&error), qPrintable(error));
        QVERIFY(contents(path).startsWith("# prisca-demonstration 1\n"));
    }

    void aStreamDestroyedMidTake_leavesAReadablePartFile() {
        QTemporaryDir dir;
        const QString path = dir.filePath("rec.csv");
        {
            DemonstrationStream stream(60000);
            QString error;
            QVERIFY(stream.open(path, header(), kAngles, &error));
            for (int k = 0; k < 10; ++k) {
                QVERIFY(stream.append(k * 0.025, Eigen::Vector2d(k, 0), Eigen::VectorXd::Zero(1),
                                      &error));
            }
        }
        FileError readError;
        const auto demo = readDemonstrationCsv(DemonstrationStream::partPath(path), &readError);
        QVERIFY2(demo, qPrintable(readError.toString()));
        QCOMPARE(demo->length(), 10);
    }

    void aFullDisk_isReportedAndTheOlderFileKept() {
        QTemporaryDir dir;
        const QString path = dir.filePath("rec.csv");
        QVERIFY(writeOlderTake(path));
        DemonstrationStream stream(0);
        QString error;
        QVERIFY(stream.open(path, header(), kAngles, &error));
        const qint64 headerSize = contents(DemonstrationStream::partPath(path)).size();
        bool failed = false;
        {
            const FileSizeLimit full(static_cast<rlim_t>(headerSize + 40));
            QVERIFY(full.active());
            for (int k = 0; k < 20 && !failed; ++k) {
                failed = !stream.append(k * 0.025, Eigen::Vector2d(k, 0), Eigen::VectorXd::Zero(1),
                                        &error);
            }
            QVERIFY2(failed, "a write past the limit must fail");
            QVERIFY2(error.contains(DemonstrationStream::partPath(path)), qPrintable(error));
            QVERIFY(!stream.finish(&error));
        }
        QCOMPARE(contents(path), QByteArray("the older take\n"));
    }

    void unwritablePathIsNamed() {
        DemonstrationStream stream;
        QString error;
        QVERIFY(!stream.open("/proc/no-such-dir/rec.csv", header(), kAngles, &error));
        QVERIFY2(error.contains("/proc/no-such-dir/rec.csv"), qPrintable(error));
        QVERIFY(!stream.open(QDir::tempPath() + "/rec.csv", header(1e-9), kAngles, &error));
        QVERIFY2(error.contains("sampling period"), qPrintable(error));
    }
};

QTEST_APPLESS_MAIN(TestDemonstrationStream)
#include "test_demonstration_stream.moc"
