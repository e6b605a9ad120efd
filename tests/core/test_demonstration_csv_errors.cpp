// Tests for the demonstration CSV reader on bad input (core/DemonstrationCsv.h): the magic
// line, the declarations, the header, the data rows, and never a crash.

#include "DemonstrationCsvTestSupport.h"

class TestDemonstrationCsvErrors : public QObject {
    Q_OBJECT

  private slots:
    // ---- the magic line and the declarations ------------------------------------------------

    void missingMagic_reportsLine1() {
        expectError(withLine(1, "# plant-log 1"), 1, 0, {"prisca-demonstration 1"});
        expectError(withLine(1, QByteArray()), 1, 0, {"'# plant: slidecar'"});
        expectError("t,x\n0,1\n", 1, 0, {"prisca-demonstration 1"});
    }

    void unsupportedVersion_reportsVersion() {
        expectError(withLine(1, "# prisca-demonstration 2"), 1, 0, {"version", "'2'"});
        expectError(withLine(1, "# prisca-demonstration"), 1, 0, {"version"});
    }

    void emptyFile_reportsLine1() {
        expectError(QByteArray(), 1, 0, {"empty"});
        expectError("\xEF\xBB\xBF", 1, 0, {"empty"});
    }

    void missingStatesLine_reportsHeaderLine() {
        // Without line 4 the header row moves up to line 5.
        expectError(withLine(4, QByteArray()), 5, 0, {"# states:"});
    }

    void missingActionsLine_reportsHeaderLine() {
        expectError(withLine(5, QByteArray()), 5, 0, {"# actions:"});
    }

    void duplicateDeclaration_reportsBothLines() {
        expectError(withLine(5, "# dt: 0.05\n# actions: throttle[1], steering[1]"), 5, 0,
                    {"dt", "line 3"});
    }

    void malformedStateEntry_reportsEntryNumber_data() {
        QTest::addColumn<QByteArray>("states");
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("mention");
        QTest::newRow("unclosed bracket") << QByteArray("# states: x[m], y[m, psi") << 2 << "y[m";
        QTest::newRow("text after unit") << QByteArray("# states: x[m]z, y") << 1 << "x[m]z";
        QTest::newRow("stray bracket") << QByteArray("# states: x, y]") << 2 << "y]";
        QTest::newRow("empty entry") << QByteArray("# states: x[m], , y") << 2 << "empty";
        QTest::newRow("no name") << QByteArray("# states: x, [m]") << 2 << "[m]";
        QTest::newRow("duplicate") << QByteArray("# states: x, y, x[cm]") << 3 << "'x'";
        QTest::newRow("time name") << QByteArray("# states: x, t[s]") << 2 << "time column";
        QTest::newRow("quote") << QByteArray("# states: x, \"y\"") << 2 << "\"";
        QTest::newRow("hash") << QByteArray("# states: x, y#2") << 2 << "'#'";
    }

    void malformedStateEntry_reportsEntryNumber() {
        QFETCH(QByteArray, states);
        QFETCH(int, column);
        QFETCH(QString, mention);
        expectError(withLine(4, states), 4, column, {QStringLiteral("state entry"), mention});
    }

    void actionNameRepeatingAState_reported() {
        expectError(withLine(5, "# actions: throttle[1], vx"), 5, 2, {"'vx'", "action entry 2"});
    }

    void badDt_rejected_data() {
        QTest::addColumn<QByteArray>("value");
        QTest::addColumn<QString>("mention");
        QTest::newRow("zero") << QByteArray("0") << "from 0.0001 to 10 s";
        QTest::newRow("negative") << QByteArray("-0.025") << "from 0.0001 to 10 s";
        QTest::newRow("tiny") << QByteArray("1e-300") << "from 0.0001 to 10 s";
        QTest::newRow("an hour") << QByteArray("3600") << "from 0.0001 to 10 s";
        QTest::newRow("text") << QByteArray("fast") << "'fast'";
        QTest::newRow("with unit") << QByteArray("0.025 s") << "'0.025 s'";
        QTest::newRow("empty") << QByteArray("") << "no value";
        QTest::newRow("nan") << QByteArray("nan") << "finite";
        QTest::newRow("infinite") << QByteArray("inf") << "finite";
        QTest::newRow("overflow") << QByteArray("1e999") << "finite";
    }

    void badDt_rejected() {
        QFETCH(QByteArray, value);
        QFETCH(QString, mention);
        expectError(withLine(3, "# dt: " + value), 3, 0, {QStringLiteral("dt"), mention});
    }

    // ---- the header row ---------------------------------------------------------------------

    void missingHeader_reportsLineAfterMetadata() {
        const QByteArray onlyMetadata = kGood.left(kGood.indexOf("t,x"));
        expectError(onlyMetadata + "\n\n", 6, 0, {"header", "t,x,y,psi"});
    }

    void dataWithoutHeader_reportsMissingHeader() {
        expectError(withLine(6, QByteArray()), 6, 1, {"header", "'0'"});
    }

    void headerMismatch_reportsLineAndColumn() {
        expectError(withLine(6, "t,x,y,yaw,vx,vy,r,throttle,steering"), 6, 4,
                    {"'yaw'", "'psi'", "states"});
        expectError(withLine(6, "t,x,y,psi,vx,vy,r,throttle,steer"), 6, 9,
                    {"'steer'", "'steering'", "actions"});
        expectError(withLine(6, "time,x,y,psi,vx,vy,r,throttle,steering"), 6, 1, {"'time'", "'t'"});
        expectError(withLine(6, "t,x[m],y,psi,vx,vy,r,throttle,steering"), 6, 2, {"'x[m]'"});
    }

    void headerColumnCount_reportsMissingOrExtraColumn() {
        expectError(withLine(6, "t,x,y,psi,vx,vy,r,throttle"), 6, 9, {"'steering'", "missing"});
        expectError(withLine(6, "t,x,y,psi,vx,vy,r,throttle,steering,brake"), 6, 10,
                    {"column 10", "10 columns"});
    }

    // ---- data rows --------------------------------------------------------------------------

    void wrongFieldCount_reportsExpectedAndGot_data() {
        QTest::addColumn<QByteArray>("row");
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("got");
        QTest::newRow("one short") << QByteArray("0.05,0.004,0,0,0.16,0,0,0.5") << 9 << "got 8";
        QTest::newRow("one long") << QByteArray("0.05,0.004,0,0,0.16,0,0,0.5,0,7") << 10
                                  << "got 10";
        QTest::newRow("trailing comma")
            << QByteArray("0.05,0.004,0,0,0.16,0,0,0.5,0.1,") << 10 << "got 10";
        QTest::newRow("semicolons")
            << QByteArray("0.05;0.004;0;0;0.16;0;0;0.5;0.1") << 2 << "got 1";
    }

    void wrongFieldCount_reportsExpectedAndGot() {
        QFETCH(QByteArray, row);
        QFETCH(int, column);
        QFETCH(QString, got);
        expectError(withLine(9, row), 9, column, {QStringLiteral("expected 9"), got});
    }

    void nonNumericValue_quotesTextAndNamesColumn_data() {
        QTest::addColumn<QByteArray>("value");
        QTest::newRow("word") << QByteArray("abc");
        QTest::newRow("two points") << QByteArray("1.2.3");
        QTest::newRow("bare exponent") << QByteArray("1e");
        QTest::newRow("hex") << QByteArray("0x10");
        QTest::newRow("quoted") << QByteArray("\"0.16\"");
        QTest::newRow("decimal comma fragment") << QByteArray("0 16");
        QTest::newRow("double sign") << QByteArray("+-1");
    }

    void nonNumericValue_quotesTextAndNamesColumn() {
        QFETCH(QByteArray, value);
        expectError(withField(9, 5, value), 9, 5,
                    {QStringLiteral("'%1'").arg(QString::fromUtf8(value)), "'vx'", "not a number"});
    }

    void emptyValue_namesColumn() {
        expectError(withField(8, 8, " "), 8, 8, {"'throttle'", "empty"});
    }

    void nonFiniteValue_rejected_data() {
        QTest::addColumn<QByteArray>("value");
        QTest::addColumn<QString>("mention");
        QTest::newRow("nan") << QByteArray("nan") << "not finite";
        QTest::newRow("NaN") << QByteArray("NaN") << "not finite";
        QTest::newRow("inf") << QByteArray("inf") << "not finite";
        QTest::newRow("-inf") << QByteArray("-inf") << "not finite";
        QTest::newRow("Infinity") << QByteArray("Infinity") << "not finite";
        QTest::newRow("overflow") << QByteArray("1e999") << "range";
        QTest::newRow("underflow") << QByteArray("1e-999") << "range";
    }

    void nonFiniteValue_rejected() {
        QFETCH(QByteArray, value);
        QFETCH(QString, mention);
        expectError(withField(10, 3, value), 10, 3,
                    {QStringLiteral("'%1'").arg(QString::fromUtf8(value)), "'y'", mention});
    }

    void valueBeyondTheFormatsBound_rejected_data() {
        QTest::addColumn<int>("column");
        QTest::addColumn<QByteArray>("value");
        QTest::addColumn<QString>("name");
        QTest::newRow("state 1e300") << 3 << QByteArray("1e300") << "'y'";
        QTest::newRow("state -1e7") << 3 << QByteArray("-1e7") << "'y'";
        QTest::newRow("action 2e6") << 8 << QByteArray("2e6") << "'throttle'";
        QTest::newRow("time 1e12") << 1 << QByteArray("1e12") << "'t'";
    }

    void valueBeyondTheFormatsBound_rejected() {
        QFETCH(int, column);
        QFETCH(QByteArray, value);
        QFETCH(QString, name);
        expectError(withField(10, column, value), 10, column,
                    {QStringLiteral("'%1'").arg(QString::fromUtf8(value)), name, "beyond"});
    }

    void inferredDtOutsideItsRange_rejected() {
        // No '# dt:' line and rows 1e-6 s apart: the median step is no sampling period.
        QByteArray text = "# prisca-demonstration 1\n# states: x [m]\n# actions: u\nt,x,u\n";
        for (int k = 0; k < 5; ++k) {
            text += QByteArray::number(k * 1e-6) + ",0,0\n";
        }
        const std::optional<FileError> error = errorOf(text, {});
        QVERIFY2(error, "accepted");
        QVERIFY2(error->message.contains("median time step"), qPrintable(error->message));
    }

    void timeNotIncreasing_reportsLine_data() {
        QTest::addColumn<QByteArray>("time");
        QTest::newRow("repeated") << QByteArray("0.025");
        QTest::newRow("decreasing") << QByteArray("0.01");
    }

    void timeNotIncreasing_reportsLine() {
        QFETCH(QByteArray, time);
        expectError(withField(9, 1, time), 9, 1, {"strictly increase", "line 8", "'t'"});
    }

    void unevenTimeStep_beyondTolerance_reportsLine() {
        // 0.05 -> 0.08 is a step of 0.03 s, 20% over dt.
        expectError(withField(10, 1, "0.08"), 10, 1, {"0.03", "0.025", "line 9", "5%"});
    }

    void unevenTimeStep_withinTolerance_accepted() {
        // 0.05 -> 0.076 is 4% over dt: accepted by the default 5%, and kept as written.
        FileError error;
        const auto demo = parseDemonstrationCsv(withField(10, 1, "0.076"), kSource, &error);
        QVERIFY2(demo, qPrintable(error.toString()));
        QCOMPARE(demo->time[3], 0.076);
    }

    void dtTolerance_optionIsHonoured() {
        CsvReadOptions strict;
        strict.dtTolerance = 0.01;
        expectError(withField(10, 1, "0.076"), 10, 1, {"1%"}, strict);
        CsvReadOptions loose;
        loose.dtTolerance = std::numeric_limits<double>::infinity();
        QVERIFY(parseDemonstrationCsv(withField(10, 1, "0.5"), kSource, nullptr, loose));
        // A missing row (a doubled step) is always uneven at the default tolerance.
        expectError(withLine(9, QByteArray()), 9, 1, {"0.05", "line 8"});
    }

    void noDataRows_reported() {
        const QByteArray headerOnly = kGood.left(kGood.indexOf("0,0,0"));
        expectError(headerOnly, 7, 0, {"no data rows"});
        expectError(headerOnly + "\n\n# only a comment\n", 7, 0, {"no data rows"});
    }

    void missingDt_inferredFromMedianStep() {
        // Steps 0.02, 0.0205, 0.02, 0.0205, 0.02: median 0.02, every step within 5% of it.
        const QByteArray text =
            "# prisca-demonstration 1\n# states: x\n# actions: u\nt,x,u\n"
            "0,0,0\n0.02,1,0\n0.0405,2,0\n0.0605,3,0\n0.081,4,0\n0.101,5,0\n";
        FileError error;
        const auto demo = parseDemonstrationCsv(text, kSource, &error);
        QVERIFY2(demo, qPrintable(error.toString()));
        QCOMPARE(demo->length(), 6);
        QVERIFY2(std::abs(demo->dt - 0.02) < 1e-12, qPrintable(QString::number(demo->dt, 'g', 17)));
        QCOMPARE(demo->plant, QString());
        // With an even number of steps the median is the mean of the middle two.
        const auto even =
            parseDemonstrationCsv(text.left(text.lastIndexOf("0.101")), kSource, &error);
        QVERIFY2(even, qPrintable(error.toString()));
        QVERIFY2(std::abs(even->dt - 0.02025) < 1e-12,
                 qPrintable(QString::number(even->dt, 'g', 17)));
    }

    void missingDt_unevenStepsStillRejected() {
        // Without line 3 the rows move up one line; the 0.05 -> 0.08 step is now on line 9.
        expectError(withLine(3, QByteArray(), withField(10, 1, "0.08")), 9, 1,
                    {"median", "line 8"});
    }

    void missingDt_singleRow_reported() {
        const QByteArray oneRow = withLine(3, QByteArray(), kGood.left(kGood.indexOf("0.025,")));
        expectError(oneRow, 6, 1, {"dt"});
    }

    // ---- never crash ------------------------------------------------------------------------

    void garbledInput_neverCrashesAndAlwaysExplains() {
        std::mt19937 random(4242);
        static const char kAlphabet[] = "0123456789.,-+eE#[]:\n\r \t\"naif\xEF\xBB\xBF\xFF";
        const QByteArray alphabet(kAlphabet, sizeof kAlphabet - 1);
        int failures = 0;
        for (int trial = 0; trial < 4000; ++trial) {
            QByteArray text = trial % 10 == 0 ? QByteArray() : kGood;
            const int edits = 1 + int(random() % 6);
            for (int e = 0; e < edits; ++e) {
                const int at = text.isEmpty() ? 0 : int(random() % text.size());
                const char c = alphabet[int(random() % alphabet.size())];
                switch (random() % 3) {
                    case 0:
                        text.insert(at, c);
                        break;
                    case 1:
                        text.remove(at, 1 + int(random() % 12));
                        break;
                    default:
                        if (!text.isEmpty()) {
                            text[at] = c;
                        }
                }
            }
            FileError error;
            const auto demo = parseDemonstrationCsv(text, kSource, &error);
            if (demo) {
                QCOMPARE(demo->validate(), QString());
                continue;
            }
            ++failures;
            QVERIFY2(!error.message.isEmpty(), text.constData());
            QVERIFY(error.line >= 0 && error.line <= lineCount(text) + 1);
            QVERIFY(error.column >= 0);
            QCOMPARE(error.path, kSource);
        }
        QVERIFY(failures > 1000);  // the edits really do break files
    }
};

QTEST_GUILESS_MAIN(TestDemonstrationCsvErrors)
#include "test_demonstration_csv_errors.moc"
