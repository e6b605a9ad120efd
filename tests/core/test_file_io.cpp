// Files read and written safely: a write that cannot complete (a full disk) leaves the previous
// file as it was and says so; a read is bounded while reading (devices, FIFOs, files growing
// past the cap) and never opens what would block; messages quoting hostile text stay one line.
#include "core/DemonstrationCsv.h"
#include "core/FileIo.h"
#include "support/FileSizeLimit.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/stat.h>
#include <sys/sysmacros.h>

using namespace prisca::core;

namespace {

QByteArray contents(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<unreadable>");
}

}  // namespace

class TestFileIo : public QObject {
    Q_OBJECT
  private slots:
    void write_onAFullDiskFailsAndKeepsThePreviousFile_data() {
        QTest::addColumn<int>("bytes");
        QTest::newRow("small, still in the buffer at commit") << 100;
        QTest::newRow("large, written at once") << 100000;
    }

    void write_onAFullDiskFailsAndKeepsThePreviousFile() {
        QFETCH(int, bytes);
        QTemporaryDir dir;
        const QString path = dir.filePath("out.csv");
        QVERIFY(writeFileAtomically(path, "previous\n", nullptr));
        FileError error;
        {
            const FileSizeLimit full(50);
            QVERIFY(full.active());
            QVERIFY(!writeFileAtomically(path, QByteArray(bytes, 'x'), &error));
        }
        QCOMPARE(error.path, path);
        QVERIFY2(error.message.contains("cannot write"), qPrintable(error.toString()));
        QCOMPARE(contents(path), QByteArray("previous\n"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"out.csv"});
        // The same through the demonstration writer, which every save of a take goes through.
        Demonstration demo;
        demo.stateNames = {"x"};
        demo.stateUnits = {"m"};
        demo.actionNames = {"u"};
        demo.actionUnits = {"1"};
        demo.time = Eigen::VectorXd::LinSpaced(3, 0.0, 0.05);
        demo.states = Eigen::MatrixXd::Zero(3, 1);
        demo.actions = Eigen::MatrixXd::Zero(3, 1);
        {
            const FileSizeLimit full(50);
            QVERIFY(!writeDemonstrationCsv(demo, path, &error));
        }
        QCOMPARE(contents(path), QByteArray("previous\n"));
    }

    void write_replacesOnlyARegularFileAndKeepsItsMode() {
        QTemporaryDir dir;
        FileError error;
        // A FIFO (opening it to write would block, replacing it would lose it).
        const QString fifo = dir.filePath("fifo");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QVERIFY(!writeFileAtomically(fifo, "data\n", &error));
        QCOMPARE(error.path, fifo);
        QVERIFY2(error.message.contains("not a regular file"), qPrintable(error.toString()));
        struct stat after {};
        QCOMPARE(::stat(QFile::encodeName(fifo).constData(), &after), 0);
        QVERIFY(S_ISFIFO(after.st_mode));
        // A character device like /dev/null, made here (only root may make one).
        const QString device = dir.filePath("null");
        if (::mknod(QFile::encodeName(device).constData(), S_IFCHR | 0666, makedev(1, 3)) == 0) {
            QVERIFY(!writeFileAtomically(device, "data\n", &error));
            QVERIFY2(error.message.contains("not a regular file"), qPrintable(error.toString()));
            QCOMPARE(::stat(QFile::encodeName(device).constData(), &after), 0);
            QVERIFY(S_ISCHR(after.st_mode));
        }
        // A folder.
        QVERIFY(!writeFileAtomically(dir.path(), "data\n", &error));
        QVERIFY2(error.message.contains("folder"), qPrintable(error.toString()));
        // A replaced file keeps its permissions.
        const QString shared = dir.filePath("shared.csv");
        QVERIFY(writeFileAtomically(shared, "old\n", nullptr));
        QCOMPARE(::chmod(QFile::encodeName(shared).constData(), 0640), 0);
        QVERIFY(writeFileAtomically(shared, "new\n", &error));
        QCOMPARE(contents(shared), QByteArray("new\n"));
        QCOMPARE(::stat(QFile::encodeName(shared).constData(), &after), 0);
        QCOMPARE(after.st_mode & 07777, 0640u);
        // A read-only file: replaced only where the user may (root), and then still read-only.
        const QString locked = dir.filePath("locked.csv");
        QVERIFY(writeFileAtomically(locked, "old\n", nullptr));
        QCOMPARE(::chmod(QFile::encodeName(locked).constData(), 0444), 0);
        if (writeFileAtomically(locked, "new\n", &error)) {
            QCOMPARE(contents(locked), QByteArray("new\n"));
        } else {
            QCOMPARE(contents(locked), QByteArray("old\n"));
        }
        QCOMPARE(::stat(QFile::encodeName(locked).constData(), &after), 0);
        QCOMPARE(after.st_mode & 07777, 0444u);
    }

    void read_isBoundedAndRefusesWhatWouldNotEnd() {
        QTemporaryDir dir;
        FileError error;
        QVERIFY(!readFileBounded("/dev/zero", 1 << 20, &error));  // would never end
        QVERIFY2(error.message.contains("not a regular file"), qPrintable(error.toString()));
        const QString fifo = dir.filePath("fifo");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QVERIFY(!readFileBounded(fifo, 1 << 20, &error));  // opening it would block
        QVERIFY2(error.message.contains("not a regular file"), qPrintable(error.toString()));
        QVERIFY(!readFileBounded(dir.path(), 1 << 20, &error));
        QVERIFY2(error.message.contains("folder"), qPrintable(error.toString()));
        QVERIFY(!readFileBounded(dir.filePath("missing"), 1 << 20, &error));
        QVERIFY2(error.message.contains("no such file"), qPrintable(error.toString()));
        const QString big = dir.filePath("big");
        QVERIFY(writeFileAtomically(big, QByteArray(1001, 'x'), nullptr));
        QVERIFY(!readFileBounded(big, 1000, &error));
        QVERIFY2(error.message.contains("1000 bytes"), qPrintable(error.toString()));
        // Its size is known before reading: an 8 GiB file (sparse, nothing on disk) is refused
        // without a byte read.
        const QString huge = dir.filePath("huge");
        {
            QFile file(huge);
            QVERIFY(file.open(QIODevice::WriteOnly));
            QVERIFY(file.resize(qint64(8) << 30));
        }
        QVERIFY(!readFileBounded(huge, 1 << 20, &error));
        QVERIFY2(error.message.contains("8589934592 bytes, more than"),
                 qPrintable(error.toString()));
        const auto exact = readFileBounded(big, 1001, &error);
        QVERIFY(exact);
        QCOMPARE(exact->size(), 1001);
        // The demonstration reader goes through it.
        QVERIFY(!readDemonstrationCsv("/dev/zero", &error));
        QCOMPARE(error.path, QStringLiteral("/dev/zero"));
    }

    void messages_escapeControlCharacters() {
        QCOMPARE(printable(QStringLiteral("a\x1b[2Jb")), QStringLiteral("a\\x1b[2Jb"));
        QCOMPARE(printable(QString::fromUtf8("x\0y\nz\x7f", 6)),
                 QStringLiteral("x\\x00y\\x0az\\x7f"));
        QCOMPARE(printable(QStringLiteral("ψ, 0.5 m")), QStringLiteral("ψ, 0.5 m"));  // text stays
        // A column name with an escape sequence, quoted by the reader: one line, no ESC.
        FileError error;
        QVERIFY(!parseDemonstrationCsv("# prisca-demonstration 1\n# states: a\x1b[31m\n", "mem",
                                       &error));
        const QString text = error.toString();
        QVERIFY2(!text.contains(QChar(0x1b)) && !text.contains('\n'), qPrintable(text));
    }

    void twoHundredThousandColumnNames_areRead() {
        // 200,000 state names: the duplicate check against every earlier name was quadratic
        // (25 s); a set makes it linear (this whole test suite takes about 0.2 s). This checks
        // the outcome, not the time.
        QByteArray text = "# prisca-demonstration 1\n# dt: 0.025\n# states: ";
        QByteArray header = "t";
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
            const QByteArray name = "s" + QByteArray::number(i);
            text += (i ? "," : "") + name;
            header += "," + name;
        }
        text += "\n# actions: u\n" + header + ",u\n";
        FileError error;
        QVERIFY(!parseDemonstrationCsv(text, "mem", &error));  // no rows
        QVERIFY2(error.message.contains("no data rows"), qPrintable(error.toString()));
    }
};

QTEST_APPLESS_MAIN(TestFileIo)
#include "test_file_io.moc"
