// Table I formatting: the numbers in each format against hand-computed statistics.
#include "core/Table1Report.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <limits>

using namespace prisca::core;

class TestTable1Report : public QObject {
    Q_OBJECT
  private:
    // Position errors {3, 5, 7} cm: MAE 5, sample std 2, variance 4.
    // Orientation errors {-10, 20, 30} deg: |e| = {10, 20, 30}: MAE 20, std 10, variance 100.
    static std::vector<Table1Row> rows() {
        return {{"prisca", summarizeErrors({3, 5, 7}), summarizeErrors({-10, 20, 30}), 0.6815,
                 "OURS (PRISCA)"},
                {"pd-h-lsd", summarizeErrors({1, 1}), summarizeErrors({4, 4}), 2512.4, "PD+H+LSD"}};
    }

  private slots:
    void markdown_showsMaeStdAndVarianceWithTheirUnits() {
        const QString md = formatTable1(rows(), TableFormat::Markdown, "caption here");
        QVERIFY(md.startsWith("caption here\n"));
        QVERIFY2(md.contains(
                     "| OURS (PRISCA) | 3 | 5.00 ± 2.00 | 4.00 | 20.00 ± 10.00 | 100.00 | 0.681 |"),
                 qPrintable(md));
        QVERIFY(md.contains("| PD+H+LSD | 2 | 1.00 ± 0.00 | 0.00 | 4.00 ± 0.00 | 0.00 | 2512 |"));
        QVERIFY(md.contains("[cm²]") && md.contains("[deg]"));
    }

    void csv_carriesFullPrecisionOneRowPerMethod() {
        const QString csv = formatTable1(rows(), TableFormat::Csv, "c");
        const QStringList lines = csv.trimmed().split('\n');
        QCOMPARE(lines.size(), 3);
        QCOMPARE(
            lines[1],
            QStringLiteral("prisca,OURS (PRISCA),3,5,2,4,20,10,100,0.68149999999999999,3,false"));
        QCOMPARE(lines[0].split(',').size(), lines[1].split(',').size());
    }

    void latex_isATabularWithEscapedCaption() {
        const QString tex = formatTable1(rows(), TableFormat::Latex, "50% of trials_x");
        QVERIFY(tex.contains("\\begin{tabular}") && tex.contains("\\end{table}"));
        QVERIFY(tex.contains("50\\% of trials\\_x"));
        QVERIFY2(tex.contains(
                     "OURS (PRISCA) & 3 & $5.00 \\pm 2.00$ & 4.00 & $20.00 \\pm 10.00$ & 100.00 & "
                     "0.681 \\\\"),
                 qPrintable(tex));
    }

    void json_parsesAndHoldsTheSummaries() {
        const QJsonObject root =
            QJsonDocument::fromJson(formatTable1(rows(), TableFormat::Json, "c").toUtf8()).object();
        const QJsonArray array = root.value("rows").toArray();
        QCOMPARE(array.size(), 2);
        const QJsonObject position = array[0].toObject().value("positionCm").toObject();
        QCOMPARE(position.value("meanAbsoluteError").toDouble(), 5.0);
        QCOMPARE(position.value("standardDeviation").toDouble(), 2.0);
        QCOMPARE(position.value("variance").toDouble(), 4.0);
        QCOMPARE(
            array[0].toObject().value("orientationDeg").toObject().value("variance").toDouble(),
            100.0);
        QCOMPARE(array[1].toObject().value("label").toString(), QStringLiteral("PD+H+LSD"));
        QCOMPARE(array[1].toObject().value("cpuMicrosecondsPerStep").toDouble(), 2512.4);
    }

    void partialRow_isMarkedInEveryFormatWithNoSpreadFromOneTrial() {
        // A cancelled batch: one trial of the twenty asked for.
        std::vector<Table1Row> one = {{"pd-h", summarizeErrors({274.93}), summarizeErrors({12.5}),
                                       std::numeric_limits<double>::quiet_NaN(), "PD+H"}};
        one[0].plannedTrials = 20;
        QVERIFY(one[0].partial());
        const QString md = formatTable1(one, TableFormat::Markdown, "c");
        QVERIFY2(md.contains("| PD+H (partial: 1 of 20 trials) | 1 | 274.93 | n/a | 12.50 | n/a |"),
                 qPrintable(md));
        QVERIFY(!md.trimmed().split('\n').last().contains(QStringLiteral("±")));  // the row
        const QString tex = formatTable1(one, TableFormat::Latex, "c");
        QVERIFY2(
            tex.contains("PD+H (partial: 1 of 20 trials) & 1 & $274.93$ & n/a & $12.50$ & n/a"),
            qPrintable(tex));
        QVERIFY(!tex.contains(QStringLiteral("\\pm")));
        const QStringList csv = formatTable1(one, TableFormat::Csv, "c").trimmed().split('\n');
        QVERIFY(csv[0].endsWith(QStringLiteral(",trials_planned,partial")));
        QCOMPARE(csv[1], QStringLiteral("pd-h,PD+H,1,274.93000000000001,,,12.5,,,,20,true"));
        const QJsonObject row =
            QJsonDocument::fromJson(formatTable1(one, TableFormat::Json, "c").toUtf8())
                .object()
                .value("rows")
                .toArray()[0]
                .toObject();
        QCOMPARE(row.value("partial").toBool(), true);
        QCOMPARE(row.value("trials").toInt(), 1);
        QCOMPARE(row.value("plannedTrials").toInt(), 20);
        QVERIFY(row.value("positionCm").toObject().value("standardDeviation").isNull());
        QVERIFY(row.value("positionCm").toObject().value("variance").isNull());
        // The full batch of the same method is not partial.
        one[0].plannedTrials = 1;
        QVERIFY(!one[0].partial());
        QVERIFY(!formatTable1(one, TableFormat::Markdown, "c").contains("partial"));
    }

    void emptyRow_showsNotAvailableRatherThanNan() {
        const std::vector<Table1Row> none = {{"pd", summarizeErrors({}), summarizeErrors({}),
                                              std::numeric_limits<double>::quiet_NaN(), "PD"}};
        const QString md = formatTable1(none, TableFormat::Markdown, "c");
        QVERIFY2(md.contains("| PD | 0 | n/a | n/a | n/a | n/a |"), qPrintable(md));
        QVERIFY(md.trimmed().endsWith("| n/a |"));  // CPU time not measured
        QVERIFY(!md.contains("nan"));
        QVERIFY(QJsonDocument::fromJson(formatTable1(none, TableFormat::Json, "c").toUtf8())
                    .isObject());
    }

    void formats_parseByName() {
        QCOMPARE(parseTableFormat("md"), std::optional<TableFormat>(TableFormat::Markdown));
        QCOMPARE(parseTableFormat("latex"), std::optional<TableFormat>(TableFormat::Latex));
        QVERIFY(!parseTableFormat("html"));
    }
};

QTEST_APPLESS_MAIN(TestTable1Report)
#include "test_table1_report.moc"
