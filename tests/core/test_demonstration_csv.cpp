// Tests for the demonstration CSV reader and writer (core/DemonstrationCsv.h).

#include "core/DemonstrationCsv.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>

using prisca::core::checkDemonstrationForCsv;
using prisca::core::CsvReadOptions;
using prisca::core::Demonstration;
using prisca::core::FileError;
using prisca::core::formatDemonstrationCsv;
using prisca::core::parseDemonstrationCsv;
using prisca::core::readDemonstrationCsv;
using prisca::core::writeDemonstrationCsv;

namespace {

// The canonical good file; most bad inputs are made by editing one line of it.
const QByteArray kGood =
    "# prisca-demonstration 1\n"                                    // line 1
    "# plant: slidecar\n"                                           // line 2
    "# dt: 0.025\n"                                                 // line 3
    "# states: x[m], y[m], psi[rad], vx[m/s], vy[m/s], r[rad/s]\n"  // line 4
    "# actions: throttle[1], steering[1]\n"                         // line 5
    "t,x,y,psi,vx,vy,r,throttle,steering\n"                         // line 6
    "0,0,0,0,0,0,0,0.5,0\n"                                         // line 7
    "0.025,0.001,0,0,0.08,0,0,0.5,0\n"                              // line 8
    "0.05,0.004,0,0,0.16,0,0,0.5,0.1\n"                             // line 9
    "0.075,0.009,0,0,0.24,0,0,0.5,0.1\n";                           // line 10

const QString kSource = QStringLiteral("memory.csv");

// kGood with its 1-based line number `line` replaced; a null replacement removes the line.
QByteArray withLine(int line, const QByteArray& replacement, const QByteArray& text = kGood) {
    QList<QByteArray> lines = text.split('\n');
    if (replacement.isNull()) {
        lines.removeAt(line - 1);
    } else {
        lines[line - 1] = replacement;
    }
    return lines.join('\n');
}

// kGood with field `column` (1-based) of line `line` replaced.
QByteArray withField(int line, int column, const QByteArray& value) {
    QList<QByteArray> fields = kGood.split('\n').at(line - 1).split(',');
    fields[column - 1] = value;
    return withLine(line, fields.join(','));
}

// The error of a parse that must fail, or nullopt when it unexpectedly succeeded.
std::optional<FileError> errorOf(const QByteArray& text, const CsvReadOptions& options = {}) {
    FileError error;
    if (parseDemonstrationCsv(text, kSource, &error, options)) {
        return std::nullopt;
    }
    return error;
}

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool sameBits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    if (a.rows() != b.rows() || a.cols() != b.cols()) {
        return false;
    }
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
        for (Eigen::Index j = 0; j < a.cols(); ++j) {
            if (!sameBits(a(i, j), b(i, j))) {
                return false;
            }
        }
    }
    return true;
}

bool sameDemonstration(const Demonstration& a, const Demonstration& b) {
    return a.plant == b.plant && sameBits(a.dt, b.dt) && a.stateNames == b.stateNames &&
           a.stateUnits == b.stateUnits && a.actionNames == b.actionNames &&
           a.actionUnits == b.actionUnits && a.metadata == b.metadata &&
           sameBits(Eigen::MatrixXd(a.time), Eigen::MatrixXd(b.time)) &&
           sameBits(a.states, b.states) && sameBits(a.actions, b.actions);
}

// A slide-car demonstration of T samples at dt = 0.025 s with smooth, non-round values.
Demonstration makeDemonstration(int samples) {
    Demonstration demo;
    demo.plant = QStringLiteral("slidecar");
    demo.dt = 0.025;
    demo.stateNames = QStringList{"x", "y", "psi", "vx", "vy", "r"};
    demo.stateUnits = QStringList{"m", "m", "rad", "m/s", "m/s", "rad/s"};
    demo.actionNames = QStringList{"throttle", "steering"};
    demo.actionUnits = QStringList{"1", "1"};
    demo.time.resize(samples);
    demo.states.resize(samples, 6);
    demo.actions.resize(samples, 2);
    for (int k = 0; k < samples; ++k) {
        const double t = k * demo.dt;
        demo.time[k] = t;
        for (int c = 0; c < 6; ++c) {
            demo.states(k, c) = std::sin(0.7 * t + c) * (c + 1) / 3.0;
        }
        demo.actions(k, 0) = 0.5 + 0.1 * std::cos(t);
        demo.actions(k, 1) = std::sin(2.0 * t) / 7.0;
    }
    return demo;
}

int lineCount(const QByteArray& text) {
    return int(text.count('\n')) + 1;
}

}  // namespace

class TestDemonstrationCsv : public QObject {
    Q_OBJECT

  private:
    // Fails the current test unless parsing `text` fails at `line`:`column` with a message
    // mentioning every string in `mentions`.
    void expectError(const QByteArray& text, int line, int column, const QStringList& mentions,
                     const CsvReadOptions& options = {}) {
        const std::optional<FileError> error = errorOf(text, options);
        QVERIFY2(error, "the bad input was accepted");
        QCOMPARE(error->path, kSource);
        QVERIFY2(!error->message.isEmpty(), "empty error message");
        QVERIFY2(!error->message.contains(QLatin1Char('\n')), qPrintable(error->message));
        QCOMPARE(error->line, line);
        QCOMPARE(error->column, column);
        for (const QString& mention : mentions) {
            QVERIFY2(error->message.contains(mention),
                     qPrintable(QStringLiteral("'%1' not in: %2").arg(mention, error->message)));
        }
    }

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
