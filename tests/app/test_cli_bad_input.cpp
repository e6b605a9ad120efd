// Every bad-input path of prisca-cli: one line on stderr naming the problem, exit code 2,
// nothing written; a full disk keeps the previous file.
#include "CliCommandTest.h"

using namespace prisca::clitest;

class TestCliBadInput : public QObject, private CliWorkspace {
    Q_OBJECT
  private slots:
    void initTestCase() { writeCarDemonstration(); }

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
};

QTEST_GUILESS_MAIN(TestCliBadInput)
#include "test_cli_bad_input.moc"
