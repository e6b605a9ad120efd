// A recording killed with SIGKILL (a crash, a power cut of the process) leaves a readable take
// that lacks at most half a second: the header on disk at once, rows flushed every quarter
// second, in the ".part" file. For the window's recording and the rig's, killed at 0.2 s and 3 s.
#include "core/DemonstrationCsv.h"
#include "core/DemonstrationStream.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace prisca;

class TestRecordingCrash : public QObject {
    Q_OBJECT
  private slots:
    void killedRecording_isReadableAndLosesAtMostHalfASecond_data() {
        QTest::addColumn<QString>("mode");
        QTest::addColumn<double>("killAt");
        QTest::newRow("window, 0.2 s") << "window" << 0.2;
        QTest::newRow("window, 3 s") << "window" << 3.0;
        QTest::newRow("rig, 0.2 s") << "rig" << 0.2;
        QTest::newRow("rig, 3 s") << "rig" << 3.0;
    }

    void killedRecording_isReadableAndLosesAtMostHalfASecond() {
        QFETCH(QString, mode);
        QFETCH(double, killAt);
        QTemporaryDir dir;
        const QString path = dir.filePath("take.csv");
        QProcess child;
        child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        child.start(QStringLiteral(RECORD_CHILD), {mode, path});
        QVERIFY(child.waitForStarted());
        // Wait on the child's own account of how long it has been recording.
        double elapsed = -1.0;
        QByteArray pending;
        const auto readReports = [&] {
            pending += child.readAllStandardOutput();
            int newline;
            while ((newline = pending.indexOf('\n')) >= 0) {
                const QByteArray line = pending.left(newline);
                pending.remove(0, newline + 1);
                if (line.startsWith("elapsed ")) {
                    elapsed = line.mid(8).toDouble();
                }
            }
        };
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         readReports();
                         return elapsed >= killAt || child.state() == QProcess::NotRunning;
                     },
                     120000),
                 "the child never reported");
        QCOMPARE(child.state(), QProcess::Running);
        child.kill();  // SIGKILL: no handler, no flush, no destructor runs
        QVERIFY(child.waitForFinished(30000));
        readReports();                  // what it printed up to the kill
        QVERIFY(!QFile::exists(path));  // the final name only for a finished take
        core::FileError error;
        const auto take =
            core::readDemonstrationCsv(core::DemonstrationStream::partPath(path), &error);
        QVERIFY2(take, qPrintable(error.toString()));
        const double recorded = (take->length() - 1) * take->dt;
        const double lost = elapsed - recorded;
        qInfo("%s killed at %.3f s: %d rows on disk, last at %.3f s, %.3f s lost", qPrintable(mode),
              elapsed, take->length(), recorded, lost);
        QVERIFY2(lost <= 0.5, qPrintable(QString::number(lost)));
    }
};

QTEST_GUILESS_MAIN(TestRecordingCrash)
#include "test_recording_crash.moc"
