// Tests for the demonstration CSV reader and writer (core/DemonstrationCsv.h).

#include "DemonstrationCsvTestSupport.h"

class TestDemonstrationCsv : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { QVERIFY(parseDemonstrationCsv(kGood, kSource, nullptr)); }

    // ---- round trips ------------------------------------------------------------------------

    void roundTrip_isBitForBit() {
        const Demonstration demo = makeDemonstration(200);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("demo.csv"));
        FileError error;
        QVERIFY2(writeDemonstrationCsv(demo, path, &error), qPrintable(error.toString()));
        const std::optional<Demonstration> back = readDemonstrationCsv(path, &error);
        QVERIFY2(back, qPrintable(error.toString()));
        QVERIFY(sameDemonstration(demo, *back));
    }

    void streamed_headerThenRowsIsTheWholeFile() {
        // A recording streamed to disk (header, then a row per sample) is the same bytes as the
        // demonstration written at once.
        Demonstration demo = makeDemonstration(50);
        demo.metadata.insert(QStringLiteral("source"), QStringLiteral("streamed"));
        QByteArray streamed = prisca::core::formatDemonstrationCsvHeader(demo);
        for (int k = 0; k < demo.length(); ++k) {
            prisca::core::appendDemonstrationCsvRow(streamed, demo.time[k],
                                                    demo.states.row(k).transpose(),
                                                    demo.actions.row(k).transpose());
        }
        QCOMPARE(streamed, prisca::core::formatDemonstrationCsv(demo));
    }

    void roundTrip_awkwardDoublesKeepEveryBit() {
        const double awkward[] = {0.1,
                                  1e-300,
                                  -0.0,
                                  0.0,
                                  1.0 / 3.0,
                                  -2.0 / 3.0,
                                  3.141592653589793,
                                  std::numeric_limits<double>::denorm_min(),
                                  -std::numeric_limits<double>::denorm_min(),
                                  std::numeric_limits<double>::min(),
                                  std::numeric_limits<double>::epsilon(),
                                  Demonstration::kMaxAbsValue,  // the format's bounds
                                  -Demonstration::kMaxAbsValue,
                                  std::nextafter(Demonstration::kMaxAbsValue, 0.0),
                                  123456.789123456789,
                                  0.30000000000000004,
                                  98765.432101234567};
        const int count = int(sizeof awkward / sizeof awkward[0]);
        Demonstration demo = makeDemonstration(count);
        demo.dt = 0.1;  // not exactly representable
        for (int k = 0; k < count; ++k) {
            demo.time[k] = 0.1 * k;
            for (int c = 0; c < 6; ++c) {
                demo.states(k, c) = awkward[(k + c) % count];
            }
            demo.actions(k, 0) = awkward[(k + 7) % count];
            demo.actions(k, 1) = -awkward[k];
        }
        QCOMPARE(checkDemonstrationForCsv(demo), QString());
        FileError error;
        const auto back = parseDemonstrationCsv(formatDemonstrationCsv(demo), kSource, &error);
        QVERIFY2(back, qPrintable(error.toString()));
        QVERIFY(sameDemonstration(demo, *back));
        QVERIFY(std::signbit(back->states(2, 0)));  // -0.0 stays negative zero
    }

    void roundTrip_randomBitPatternsKeepEveryBit() {
        // Every double the format can mean (within +-kMaxAbsValue, subnormals included).
        std::mt19937_64 random(20240501);
        Demonstration demo = makeDemonstration(500);
        for (Eigen::Index k = 0; k < demo.states.rows(); ++k) {
            for (Eigen::Index c = 0; c < demo.states.cols(); ++c) {
                double value = std::numeric_limits<double>::quiet_NaN();
                while (!(std::abs(value) <= Demonstration::kMaxAbsValue)) {
                    const std::uint64_t bits = random();
                    std::memcpy(&value, &bits, sizeof value);
                }
                demo.states(k, c) = value;
            }
        }
        FileError error;
        const auto back = parseDemonstrationCsv(formatDemonstrationCsv(demo), kSource, &error);
        QVERIFY2(back, qPrintable(error.toString()));
        QVERIFY(sameDemonstration(demo, *back));
    }

    void roundTrip_keepsPlantUnitsMetadataAndEmptyActionList() {
        Demonstration demo = makeDemonstration(5);
        demo.plant = QStringLiteral("acrobot (2-link)");
        demo.stateUnits[0] = QStringLiteral("1");
        demo.stateUnits[1] = QString();  // an empty unit survives as "[]"
        demo.stateNames[2] = QStringLiteral("ψ angle");
        demo.metadata.insert(QStringLiteral("operator"), QStringLiteral("Chan Tai Man"));
        demo.metadata.insert(QStringLiteral("notes"), QStringLiteral("slid at 1.2 s: ok, # fine"));
        demo.metadata.insert(QStringLiteral("empty"), QString());
        demo.actionNames.clear();
        demo.actionUnits.clear();
        demo.actions.resize(5, 0);
        FileError error;
        const auto back = parseDemonstrationCsv(formatDemonstrationCsv(demo), kSource, &error);
        QVERIFY2(back, qPrintable(error.toString()));
        QVERIFY(sameDemonstration(demo, *back));
        QCOMPARE(back->metadata.value(QStringLiteral("notes")),
                 QStringLiteral("slid at 1.2 s: ok, # fine"));
        QCOMPARE(back->actionDimension(), 0);
    }

    // ---- reading good input -----------------------------------------------------------------

    void read_exampleFile_givesNamesUnitsAndValues() {
        FileError error;
        const auto demo =
            readDemonstrationCsv(QStringLiteral(PRISCA_TEST_DATA_DIR "/demo_slidecar.csv"), &error);
        QVERIFY2(demo, qPrintable(error.toString()));
        QCOMPARE(demo->plant, QStringLiteral("slidecar"));
        QCOMPARE(demo->dt, 0.025);
        QCOMPARE(demo->length(), 5);
        QCOMPARE(demo->stateNames, (QStringList{"x", "y", "psi", "vx", "vy", "r"}));
        QCOMPARE(demo->stateUnits, (QStringList{"m", "m", "rad", "m/s", "m/s", "rad/s"}));
        QCOMPARE(demo->actionNames, (QStringList{"throttle", "steering"}));
        QCOMPARE(demo->actionUnits, (QStringList{"1", "1"}));  // "steering" has no brackets
        QCOMPARE(demo->time[4], 0.1);
        QCOMPARE(demo->states(3, 3), 0.24);
        QCOMPARE(demo->actions(4, 1), -0.25);
        QCOMPARE(demo->validate(), QString());
    }

    void read_metadataLinesPreserved_freeCommentsDropped() {
        FileError error;
        const auto demo =
            readDemonstrationCsv(QStringLiteral(PRISCA_TEST_DATA_DIR "/demo_slidecar.csv"), &error);
        QVERIFY2(demo, qPrintable(error.toString()));
        QCOMPARE(demo->metadata.size(), 2);
        QCOMPARE(demo->metadata.value(QStringLiteral("operator")), QStringLiteral("test fixture"));
        // Only the first ':' splits key from value.
        QCOMPARE(demo->metadata.value(QStringLiteral("recorded")),
                 QStringLiteral("2024-05-01T10:00:00"));
        // The reserved keys fill fields and do not leak into metadata.
        QVERIFY(!demo->metadata.contains(QStringLiteral("dt")));
        QVERIFY(!demo->metadata.contains(QStringLiteral("states")));
    }

    void read_crlfBomSpacesAndTrailingBlankLines_accepted() {
        QByteArray messy = "\xEF\xBB\xBF" + kGood;
        messy.replace("\n", "\r\n");
        messy.replace(",", " ,\t");
        messy.replace("# dt: 0.025", "#   DT :  0.025  ");
        messy += "\r\n\r\n   \r\n";
        FileError error;
        const auto clean = parseDemonstrationCsv(kGood, kSource, &error);
        QVERIFY2(clean, qPrintable(error.toString()));
        const auto demo = parseDemonstrationCsv(messy, kSource, &error);
        QVERIFY2(demo, qPrintable(error.toString()));
        QVERIFY(sameDemonstration(*clean, *demo));
    }

    void read_loneCarriageReturnLineEndings_accepted() {
        QByteArray mac = kGood;
        mac.replace('\n', '\r');
        FileError error;
        const auto demo = parseDemonstrationCsv(mac, kSource, &error);
        QVERIFY2(demo, qPrintable(error.toString()));
        QCOMPARE(demo->length(), 4);
        QCOMPARE(demo->states(3, 3), 0.24);
    }

    void read_blankAndCommentRowsAndLeadingPlus_accepted() {
        QByteArray text =
            withLine(8, "\n# a remark between rows\n+0.025,+0.001,0,0,0.08,0,0,0.5,0");
        FileError error;
        const auto demo = parseDemonstrationCsv(text, kSource, &error);
        QVERIFY2(demo, qPrintable(error.toString()));
        QCOMPARE(demo->length(), 4);
        QCOMPARE(demo->states(1, 0), 0.001);
        // Line numbers still count the skipped lines: a bad value after them is on line 12.
        expectError(withLine(12, "0.075,0.009,0,0,zz,0,0,0.5,0", text), 12, 5, {"'zz'", "'vx'"});
    }

    void read_errorIsUntouchedOnSuccess() {
        FileError error{QStringLiteral("sentinel"), 7, 3, QStringLiteral("unchanged")};
        QVERIFY(parseDemonstrationCsv(kGood, kSource, &error));
        QCOMPARE(error.path, QStringLiteral("sentinel"));
        QCOMPARE(error.line, 7);
    }

    // ---- writing ----------------------------------------------------------------------------

    void write_intoMissingDirectory_failsWithoutPartialFile() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("no/such/dir/demo.csv"));
        FileError error;
        QVERIFY(!writeDemonstrationCsv(makeDemonstration(10), path, &error));
        QCOMPARE(error.path, path);
        QVERIFY(!error.message.isEmpty());
        QVERIFY(error.toString().startsWith(path));
        QVERIFY(!QFileInfo::exists(path));
        QVERIFY(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot).isEmpty());
    }

    void write_overExistingFile_replacesItCompletely() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("demo.csv"));
        QVERIFY(writeDemonstrationCsv(makeDemonstration(1000), path, nullptr));
        const Demonstration shorter = makeDemonstration(3);
        FileError error;
        QVERIFY2(writeDemonstrationCsv(shorter, path, &error), qPrintable(error.toString()));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), formatDemonstrationCsv(shorter));
        const QStringList entries = QDir(dir.path()).entryList(QDir::Files | QDir::Hidden);
        QCOMPARE(entries, QStringList{QStringLiteral("demo.csv")});  // no temporary left over
    }

    void write_failure_leavesExistingFileUntouched() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("demo.csv"));
        QVERIFY(writeDemonstrationCsv(makeDemonstration(20), path, nullptr));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray before = file.readAll();
        file.close();

        Demonstration invalid = makeDemonstration(5);
        invalid.states(2, 3) = std::numeric_limits<double>::quiet_NaN();
        FileError error;
        QVERIFY(!writeDemonstrationCsv(invalid, path, &error));
        QCOMPARE(error.path, path);
        QVERIFY2(error.message.contains(QStringLiteral("'vx'")), qPrintable(error.message));

        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), before);
        file.close();

        // A target that cannot be replaced (a directory) fails and leaves nothing behind.
        const QString blocked = dir.filePath(QStringLiteral("blocked.csv"));
        QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("blocked.csv")));
        QVERIFY(!writeDemonstrationCsv(makeDemonstration(5), blocked, &error));
        QCOMPARE(error.path, blocked);
        QVERIFY(QFileInfo(blocked).isDir());
        const QStringList entries =
            QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
        QCOMPARE(entries, (QStringList{QStringLiteral("blocked.csv"), QStringLiteral("demo.csv")}));
    }

    void write_unwritableDemonstration_refusedWithReason_data() {
        QTest::addColumn<int>("defect");
        QTest::addColumn<QString>("mention");
        QTest::newRow("time not increasing") << 0 << "increasing";
        QTest::newRow("no samples") << 1 << "no samples";
        QTest::newRow("comma in name") << 2 << "','";
        QTest::newRow("duplicate name") << 3 << "twice";
        QTest::newRow("reserved metadata key") << 4 << "'dt'";
        QTest::newRow("line break in metadata") << 5 << "line break";
        QTest::newRow("bracket in unit") << 6 << "']'";
        QTest::newRow("name t") << 7 << "time column";
        QTest::newRow("colon in key") << 8 << "':'";
        QTest::newRow("non-positive dt") << 9 << "dt";
    }

    void write_unwritableDemonstration_refusedWithReason() {
        QFETCH(int, defect);
        QFETCH(QString, mention);
        Demonstration demo = makeDemonstration(6);
        switch (defect) {
            case 0:
                demo.time[3] = demo.time[2];
                break;
            case 1:
                demo = makeDemonstration(0);
                break;
            case 2:
                demo.stateNames[1] = QStringLiteral("y,z");
                break;
            case 3:
                demo.actionNames[1] = QStringLiteral("x");
                break;
            case 4:
                demo.metadata.insert(QStringLiteral("dt"), QStringLiteral("0.1"));
                break;
            case 5:
                demo.metadata.insert(QStringLiteral("note"), QStringLiteral("a\nb"));
                break;
            case 6:
                demo.stateUnits[0] = QStringLiteral("m]");
                break;
            case 7:
                demo.stateNames[0] = QStringLiteral("t");
                break;
            case 8:
                demo.metadata.insert(QStringLiteral("a:b"), QStringLiteral("c"));
                break;
            default:
                demo.dt = 0.0;
                break;
        }
        const QString problem = checkDemonstrationForCsv(demo);
        QVERIFY2(problem.contains(mention), qPrintable(problem));
        QString formatProblem;
        QVERIFY(formatDemonstrationCsv(demo, &formatProblem).isEmpty());
        QCOMPARE(formatProblem, problem);

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("demo.csv"));
        FileError error;
        QVERIFY(!writeDemonstrationCsv(demo, path, &error));
        QVERIFY2(error.message.contains(problem), qPrintable(error.message));
        QVERIFY(!QFileInfo::exists(path));
    }

    void read_missingFile_reportsPath() {
        const QString path = QStringLiteral(PRISCA_TEST_DATA_DIR "/demo_does_not_exist.csv");
        FileError error;
        QVERIFY(!readDemonstrationCsv(path, &error));
        QCOMPARE(error.path, path);
        QVERIFY(!error.message.isEmpty());
        QVERIFY(!readDemonstrationCsv(QStringLiteral(PRISCA_TEST_DATA_DIR), &error));
        QCOMPARE(error.path, QStringLiteral(PRISCA_TEST_DATA_DIR));
    }

    void read_fileErrorsCarryThePath() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("bad.csv"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(withField(8, 4, "oops"));
        file.close();
        FileError error;
        QVERIFY(!readDemonstrationCsv(path, &error));
        QCOMPARE(error.toString().left(path.size() + 6), path + QStringLiteral(":8:4: "));
    }

    // ---- the output is plain CSV --------------------------------------------------------------

    void output_isPlainCsvForPandasAndMatlab() {
        Demonstration demo = makeDemonstration(50);
        demo.metadata.insert(QStringLiteral("operator"), QStringLiteral("A, B"));
        const QByteArray text = formatDemonstrationCsv(demo);
        QVERIFY(text.startsWith("# prisca-demonstration 1\n"));
        QVERIFY(!text.contains('\r'));
        QVERIFY(text.endsWith('\n'));
        const QList<QByteArray> lines = text.left(text.size() - 1).split('\n');
        int header = 0;
        while (header < lines.size() && lines[header].startsWith('#')) {
            ++header;
        }
        QCOMPARE(lines.value(header), QByteArray("t,x,y,psi,vx,vy,r,throttle,steering"));
        QCOMPARE(lines.size() - header - 1, 50);
        for (int i = header; i < lines.size(); ++i) {
            const QByteArray& line = lines[i];
            QCOMPARE(line.count(','), 8);  // the same column count on every row
            QVERIFY2(!line.contains('"') && !line.contains('#') && !line.contains(' ') &&
                         !line.contains('\t'),
                     line.constData());
            if (i > header) {
                for (const QByteArray& field : line.split(',')) {
                    bool ok = false;
                    field.toDouble(&ok);  // C locale: '.' decimal point, no grouping
                    QVERIFY2(ok, field.constData());
                }
            }
        }
        QVERIFY(text.contains("# states: x[m], y[m], psi[rad], vx[m/s], vy[m/s], r[rad/s]\n"));
        QVERIFY(text.contains("# actions: throttle[1], steering[1]\n"));
        QVERIFY(text.contains("# operator: A, B\n"));
    }

    void fileError_toString_omitsZeros() {
        QCOMPARE((FileError{"a.csv", 3, 2, "bad"}).toString(), QStringLiteral("a.csv:3:2: bad"));
        QCOMPARE((FileError{"a.csv", 3, 0, "bad"}).toString(), QStringLiteral("a.csv:3: bad"));
        QCOMPARE((FileError{"a.csv", 0, 0, "bad"}).toString(), QStringLiteral("a.csv: bad"));
        QCOMPARE((FileError{"", 0, 0, "bad"}).toString(), QStringLiteral("bad"));
    }

    // ---- size -------------------------------------------------------------------------------

    // Exactness on a long file; its speed is measured in tests/benchmarks, not asserted here.
    void read_100000Rows_isExact() {
        const Demonstration demo = makeDemonstration(100000);
        const QByteArray text = formatDemonstrationCsv(demo);
        FileError error;
        const auto back = parseDemonstrationCsv(text, kSource, &error);
        QVERIFY2(back, qPrintable(error.toString()));
        QVERIFY(sameDemonstration(demo, *back));
    }
};

QTEST_GUILESS_MAIN(TestDemonstrationCsv)
#include "test_demonstration_csv.moc"
