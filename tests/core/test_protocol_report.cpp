// The evaluation protocol's aggregation over (style x seed set) cells, against numbers worked
// out by hand, and its formats.
#include "core/ProtocolReport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace prisca::core;

namespace {

constexpr double kT975dof1 = 12.706204736174707;  // Student t quantiles, 97.5%
constexpr double kT975dof3 = 3.182446305284263;

// A cell's row as the experiment labels it: PRISCA's Table I label, the oracle as the limit.
Table1Row row(const char* method, double position, double orientation, double cpu) {
    const QString id = QString::fromLatin1(method);
    const bool limit = id == QLatin1String("oracle");
    const QString label = id == QLatin1String("prisca") ? QStringLiteral("OURS (PRISCA)")
                          : limit                       ? QStringLiteral("LIMIT (oracle)")
                                                        : id.toUpper();
    return {id, summarizeErrors({position}), summarizeErrors({orientation}), cpu, label, limit};
}

// PRISCA's cells: position 2, 4 (style A, sets 1, 2) and 6, 8 (style B); orientation ten times.
// The oracle's: position 1 and orientation 2 everywhere.
ProtocolSummary example() {
    std::vector<std::vector<ProtocolCell>> cells(2);
    const double p[] = {2, 4, 6, 8};
    int i = 0;
    for (const char* style : {"A", "B"}) {
        for (std::uint64_t set : {1, 2}) {
            cells[0].push_back({style, set, row("prisca", p[i], 10 * p[i], 1.0 + i)});
            cells[1].push_back({style, set, row("oracle", 1.0, 2.0, 5000.0)});
            ++i;
        }
    }
    return summarizeProtocol({"prisca", "oracle"}, {"A", "B"}, {1, 2}, cells);
}

bool near(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b));
}

}  // namespace

class TestProtocolReport : public QObject {
    Q_OBJECT
  private slots:
    void meanInterval_isStudentTOverTheUnits() {
        // {2, 4, 6, 8}: mean 5, s^2 = 20/3, half width t(3) s / 2.
        const MeanInterval m = meanInterval({2, 4, 6, 8});
        const double half = kT975dof3 * std::sqrt(20.0 / 3.0) / 2.0;
        QCOMPARE(m.count, 4);
        QVERIFY(near(m.mean, 5.0));
        QVERIFY(near(m.lower, 5.0 - half));
        QVERIFY(near(m.upper, 5.0 + half));
        // One unit: no spread to estimate, the interval is the mean. None: NaN. NaN skipped.
        const MeanInterval one = meanInterval({3.0, std::nan("")});
        QCOMPARE(one.count, 1);
        QCOMPARE(one.lower, 3.0);
        QCOMPARE(one.upper, 3.0);
        QVERIFY(std::isnan(meanInterval({}).mean));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, meanInterval({1, 2}, 1.0));
    }

    void summarize_averagesCellsAndBreaksDownPerStyle() {
        const ProtocolSummary s = example();
        QCOMPARE(s.oracleRow(), 1);
        const ProtocolRow& prisca = s.rows[0];
        QCOMPARE(prisca.method, QStringLiteral("prisca"));
        QCOMPARE(prisca.trials, 4);
        QVERIFY(near(prisca.position.mean, 5.0));
        QVERIFY(near(prisca.orientation.mean, 50.0));
        QVERIFY(near(prisca.position.upper - prisca.position.mean,
                     kT975dof3 * std::sqrt(20.0 / 3.0) / 2.0));
        QVERIFY(near(prisca.cpuMicrosecondsPerStep, 2.5));  // mean of 1, 2, 3, 4
        // Style A: {2, 4}: mean 3, s = sqrt 2, half width t(1) sqrt(2) / sqrt(2).
        QVERIFY(near(prisca.stylePosition[0].mean, 3.0));
        QVERIFY(near(prisca.stylePosition[0].upper, 3.0 + kT975dof1));
        QVERIFY(near(prisca.stylePosition[1].mean, 7.0));
        QVERIFY(near(prisca.styleOrientation[1].mean, 70.0));
        QCOMPARE(s.rows[1].position.lower, 1.0);  // no spread
    }

    void summarize_perDayMeanMedianAndWorstCell() {
        // PRISCA's day 1: A 2, B 6; day 2: A 4, B 8. A hard day shows as one.
        const ProtocolSummary s = example();
        const ProtocolRow& prisca = s.rows[0];
        QCOMPARE(prisca.spread.cells, 4);
        QVERIFY(near(prisca.spread.median, 5.0));  // of 2, 4, 6, 8
        QVERIFY(near(prisca.spread.worst, 8.0));
        QCOMPARE(prisca.spread.worstCell, QStringLiteral("B on day 2"));
        QCOMPARE(prisca.days.size(), size_t(2));
        QCOMPARE(prisca.days[0].seedSet, std::uint64_t(1));
        QVERIFY(near(prisca.days[0].position.mean, 4.0));
        QVERIFY(near(prisca.days[0].position.median, 4.0));
        QVERIFY(near(prisca.days[0].position.worst, 6.0));
        QCOMPARE(prisca.days[0].position.worstCell, QStringLiteral("B on day 1"));
        QVERIFY(near(prisca.days[1].position.mean, 6.0));
        QVERIFY(near(prisca.days[1].position.worst, 8.0));
        // An odd count's median is its middle cell.
        std::vector<std::vector<ProtocolCell>> cells(1);
        for (std::uint64_t set : {1, 2, 3}) {
            cells[0].push_back({"A", set, row("pd", set == 2 ? 30.0 : 1.0 * set, 1.0, 1.0)});
        }
        const ProtocolSummary odd = summarizeProtocol({"pd"}, {"A"}, {1, 2, 3}, cells);
        QVERIFY(near(odd.rows[0].spread.median, 3.0));  // of 1, 3, 30
        QCOMPARE(odd.rows[0].spread.worstCell, QStringLiteral("A on day 2"));
        QCOMPARE(odd.rows[0].days[2].position.cells, 1);
        // A cell of a seed set the summary does not list is refused.
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 summarizeProtocol({"pd"}, {"A"}, {1, 3}, cells));
    }

    void planner_isReadCellByCellAgainstTheBestLaw() {
        // mpc plans through a model; pd and ilc are the laws; the oracle is neither.
        //            A/1  A/2  B/1  B/2
        // mpc         1    9    2    3     mean 3.75
        // pd          2    5   10    4     mean 5.25
        // ilc         4    4    1    8     mean 4.25: the best law over all
        // best law    2    4    1    4     mpc's ratios 0.5, 2.25, 2, 0.75: two over 1.5x
        const QStringList methods{"mpc", "pd", "ilc", "oracle"};
        const double values[3][4] = {{1, 9, 2, 3}, {2, 5, 10, 4}, {4, 4, 1, 8}};
        std::vector<std::vector<ProtocolCell>> cells(4);
        int i = 0;
        for (const char* style : {"A", "B"}) {
            for (std::uint64_t set : {1, 2}) {
                for (int m = 0; m < 3; ++m) {
                    Table1Row r = row(qPrintable(methods[m]), values[m][i], 1.0, 1.0);
                    r.plansThroughModel = m == 0;
                    cells[static_cast<size_t>(m)].push_back({style, set, r});
                }
                cells[3].push_back({style, set, row("oracle", 0.1, 0.1, 1.0)});
                ++i;
            }
        }
        // The laws' cells in another order: cells are matched by name, not by place.
        std::reverse(cells[1].begin(), cells[1].end());
        const ProtocolSummary s = summarizeProtocol(methods, {"A", "B"}, {1, 2}, cells);
        const LawComparison& all = s.rows[0].againstLaws;
        QCOMPARE(all.cells, 4);
        QCOMPARE(all.bestLaw, QStringLiteral("ILC"));
        QVERIFY(near(all.bestLawMean, 4.25));
        QVERIFY(near(all.ratioOfMeans, 3.75 / 4.25));
        QCOMPARE(all.cellsOver, 2);
        QVERIFY(near(all.worstRatio, 2.25));
        QCOMPARE(all.worstRatioCell, QStringLiteral("A on day 2"));
        // Day 1: mpc 1, 2 (mean 1.5); pd 2, 10 (6); ilc 4, 1 (2.5); B/1 is 2x its best law.
        const LawComparison& day1 = s.rows[0].days[0].againstLaws;
        QCOMPARE(day1.cells, 2);
        QCOMPARE(day1.bestLaw, QStringLiteral("ILC"));
        QVERIFY(near(day1.ratioOfMeans, 0.6));
        QCOMPARE(day1.cellsOver, 1);
        QVERIFY(near(day1.worstRatio, 2.0));
        QCOMPARE(day1.worstRatioCell, QStringLiteral("B on day 1"));
        // Day 2: mpc 9, 3 (6); pd 5, 4 (4.5): the best law that day is another.
        const LawComparison& day2 = s.rows[0].days[1].againstLaws;
        QCOMPARE(day2.bestLaw, QStringLiteral("PD"));
        QVERIFY(near(day2.ratioOfMeans, 6.0 / 4.5));
        // Laws and the limit are not compared.
        QCOMPARE(s.rows[1].againstLaws.cells, 0);
        QCOMPARE(s.rows[3].againstLaws.cells, 0);

        const QString md = formatProtocol(s, TableFormat::Markdown, "c");
        QVERIFY2(md.contains("| MPC | 0.88x ILC; 2 of 4 cells over 1.5x; worst 2.25x (A on day 2) "
                             "| 0.60x ILC; 1 of 2 cells over 1.5x; worst 2.00x (B on day 1) |"),
                 qPrintable(md));
        const QJsonArray rows =
            QJsonDocument::fromJson(formatProtocol(s, TableFormat::Json, "c").toUtf8())
                .object()
                .value("rows")
                .toArray();
        const QJsonObject against = rows[0].toObject().value("againstLaws").toObject();
        QCOMPARE(against.value("cellsOver").toInt(), 2);
        QCOMPARE(against.value("tolerance").toDouble(), 1.5);
        QCOMPARE(against.value("worstRatio").toDouble(), 2.25);
        QCOMPARE(rows[0]
                     .toObject()
                     .value("days")
                     .toArray()[1]
                     .toObject()
                     .value("againstLaws")
                     .toObject()
                     .value("bestLaw")
                     .toString(),
                 QStringLiteral("PD"));
        QVERIFY(!rows[1].toObject().contains("againstLaws"));

        // Without a law among the rows there is nothing to read the planner against.
        std::vector<std::vector<ProtocolCell>> alone{cells[0], cells[3]};
        const ProtocolSummary noLaw =
            summarizeProtocol({"mpc", "oracle"}, {"A", "B"}, {1, 2}, alone);
        QCOMPARE(noLaw.rows[0].againstLaws.cells, 0);
        QVERIFY(!formatProtocol(noLaw, TableFormat::Markdown, "c").contains("Planners against"));
    }

    void aVariantsCell_isNamedWithItsDemonstration() {
        std::vector<std::vector<ProtocolCell>> cells(1);
        cells[0].push_back({"x11", 4, row("pd", 3.0, 1.0, 1.0), "fast"});
        cells[0].push_back({"x11", 4, row("pd", 1.0, 1.0, 1.0), "blip"});
        const ProtocolSummary s = summarizeProtocol({"pd"}, {"x11"}, {4}, cells);
        QCOMPARE(s.rows[0].spread.worstCell, QStringLiteral("x11 fast on day 4"));
    }

    void markdown_showsIntervalsTheGapToTheLimitAndEveryStyle() {
        const QString md = formatProtocol(example(), TableFormat::Markdown, "caption");
        QVERIFY(md.startsWith("caption\n"));
        const double half = kT975dof3 * std::sqrt(20.0 / 3.0) / 2.0;
        const QString expected = QStringLiteral("| OURS (PRISCA) | 4 | 4 | 5.00 [%1, %2] | 5.0x | ")
                                     .arg(5.0 - half, 0, 'f', 2)
                                     .arg(5.0 + half, 0, 'f', 2);
        QVERIFY2(md.contains(expected), qPrintable(md));
        QVERIFY2(md.contains("| 25.0x | 2.5 |"), qPrintable(md));  // 50 deg / 2 deg; CPU
        QVERIFY(md.contains("| LIMIT (oracle) | 4 | 4 | 1.00 [1.00, 1.00] | 1.0x |"));
        QVERIFY(md.contains("| method | A | B |"));
        QVERIFY2(md.contains("\nPer style, position MAE"), qPrintable(md));
        QVERIFY2(md.contains("| OURS (PRISCA) | 3.00 / 30.00 | 7.00 / 70.00 |"), qPrintable(md));
        QVERIFY2(md.contains("| method | all | 1 | 2 |"), qPrintable(md));
        QVERIFY2(md.contains("| OURS (PRISCA) | 5.00 / 5.00 / 8.00 (B on day 2) | 4.00 / 4.00 / "
                             "6.00 (B on day 1) | 6.00 / 6.00 / 8.00 (B on day 2) |"),
                 qPrintable(md));
    }

    void markdown_namesABreakdownByVariantSo() {
        ProtocolSummary s = example();
        s.byVariant = true;
        const QString md = formatProtocol(s, TableFormat::Markdown, "c");
        QVERIFY2(md.contains("\nPer variant, position MAE") && !md.contains("Per style"),
                 qPrintable(md));
    }

    void csv_hasOneLinePerMethodAndScope() {
        const QStringList lines =
            formatProtocol(example(), TableFormat::Csv, "c").trimmed().split('\n');
        QCOMPARE(lines.size(), 1 + 2 * 5);  // header, (all, A, B, day 1, day 2) x 2 methods
        QVERIFY(lines[0].startsWith("scope,method,label,cells,position_mae_cm"));
        QVERIFY2(lines[1].startsWith("all,prisca,OURS (PRISCA),4,5,"), qPrintable(lines[1]));
        QVERIFY2(lines[3].startsWith("A,prisca,OURS (PRISCA),2,3,"), qPrintable(lines[3]));
        QVERIFY2(lines[1].endsWith(",5,8,B on day 2"), qPrintable(lines[1]));
        QVERIFY2(lines[9].startsWith("day 2,prisca,OURS (PRISCA),2,6,"), qPrintable(lines[9]));
        QVERIFY2(lines[9].endsWith(",6,8,B on day 2"), qPrintable(lines[9]));
        for (const QString& line : lines)
            QCOMPARE(line.count(','), lines[0].count(','));
    }

    void json_keepsTheTableIKeys() {
        const QJsonObject root =
            QJsonDocument::fromJson(formatProtocol(example(), TableFormat::Json, "c").toUtf8())
                .object();
        const QJsonArray rows = root.value("rows").toArray();
        QCOMPARE(rows.size(), 2);
        const QJsonObject prisca = rows[0].toObject();
        QCOMPARE(prisca.value("method").toString(), QStringLiteral("prisca"));
        QCOMPARE(prisca.value("positionCm").toObject().value("meanAbsoluteError").toDouble(), 5.0);
        QCOMPARE(prisca.value("orientationDeg").toObject().value("meanAbsoluteError").toDouble(),
                 50.0);
        QCOMPARE(prisca.value("positionTimesLimit").toDouble(), 5.0);
        const QJsonArray styles = prisca.value("styles").toArray();
        QCOMPARE(styles.size(), 2);
        QCOMPARE(styles[1].toObject().value("style").toString(), QStringLiteral("B"));
        QCOMPARE(styles[1]
                     .toObject()
                     .value("positionCm")
                     .toObject()
                     .value("meanAbsoluteError")
                     .toDouble(),
                 7.0);
        QCOMPARE(root.value("seedSets").toArray().size(), 2);
        QCOMPARE(prisca.value("cellSpread").toObject().value("worstCm").toDouble(), 8.0);
        const QJsonObject day2 = prisca.value("days").toArray().at(1).toObject();
        QCOMPARE(day2.value("seedSet").toDouble(), 2.0);
        QCOMPARE(day2.value("meanCm").toDouble(), 6.0);
        QCOMPARE(day2.value("medianCm").toDouble(), 6.0);
        QCOMPARE(day2.value("worstCell").toString(), QStringLiteral("B on day 2"));
    }

    void latex_escapesAndListsEveryStyle() {
        const QString tex = formatProtocol(example(), TableFormat::Latex, "95% of cell_x");
        QVERIFY(tex.contains("95\\% of cell\\_x"));
        QVERIFY(tex.contains("Method & A & B"));
        QVERIFY2(tex.contains("OURS (PRISCA) & 3.00 / 30.00 & 7.00 / 70.00 \\\\"), qPrintable(tex));
    }

    void aZeroLimit_givesNoRatio() {
        std::vector<std::vector<ProtocolCell>> cells(2);
        cells[0].push_back({"A", 1, row("pd", 3.0, 4.0, 1.0)});
        cells[1].push_back({"A", 1, row("oracle", 0.001, 0.0, 1.0)});
        const ProtocolSummary s = summarizeProtocol({"pd", "oracle"}, {"A"}, {1}, cells);
        QVERIFY(formatProtocol(s, TableFormat::Markdown, "c")
                    .contains("| PD | 1 | 1 | 3.00 | n/a | 4.00 | n/a |"));
        const QJsonObject root =
            QJsonDocument::fromJson(formatProtocol(s, TableFormat::Json, "c").toUtf8()).object();
        QVERIFY(root.value("rows").toArray()[0].toObject().value("positionTimesLimit").isNull());
    }

    void withoutOracle_theGapIsNotAvailable() {
        std::vector<std::vector<ProtocolCell>> cells(1);
        cells[0].push_back({"A", 1, row("pd", 3.0, 4.0, 1.0)});
        const ProtocolSummary s = summarizeProtocol({"pd"}, {"A"}, {1}, cells);
        QCOMPARE(s.oracleRow(), -1);
        const QString md = formatProtocol(s, TableFormat::Markdown, "c");
        QVERIFY(md.contains("| PD | 1 | 1 | 3.00 | n/a | 4.00 | n/a |"));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 summarizeProtocol({"pd", "ilc"}, {"A"}, {1}, cells));
    }
};

QTEST_APPLESS_MAIN(TestProtocolReport)
#include "test_protocol_report.moc"
