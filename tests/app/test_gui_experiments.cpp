// The Experiments panel driven offscreen: Table I in the background, exported and read back,
// cancelled Table I and learning curves keeping what finished.
#include "GuiTestSupport.h"

using namespace prisca::app;
using namespace prisca::test;

class TestGuiExperiments : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_experiments"); }
    void init() { QSettings().clear(); }

    void experiments_table1InTheBackgroundThenExportedAndReadBack() {
        Window w;
        auto* panel = w.find<ExperimentsPanel>("experimentsPanel");
        w.find<QComboBox>("experimentKind")->setCurrentIndex(0);
        w.find<QSpinBox>("experimentCount")->setValue(3);
        QSignalSpy finished(panel, &ExperimentsPanel::finished);
        w.find<QAbstractButton>("startExperiment")->click();
        QVERIFY(panel->isRunning());
        QVERIFY(w.find<QAbstractButton>("cancelExperiment")->isEnabled());
        QVERIFY(finished.wait(kRunTimeoutMs));
        QVERIFY(!panel->isRunning());
        auto* table = w.find<QTableWidget>("experimentTable");
        QCOMPARE(table->rowCount(), 12);  // every Table I row: PRISCA's two, LQR, PGSD, ILC, the limit
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("OURS (PRISCA)"));
        QCOMPARE(table->item(0, 1)->text(), QStringLiteral("3"));  // N
        QVERIFY(table->item(0, 2)->text().contains(QStringLiteral("±")));
        QVERIFY(!w.find<QLabel>("experimentFigure")->pixmap().isNull());
        // The result names the demonstration it is about.
        QVERIFY2(
            panel->tableText(prisca::core::TableFormat::Markdown)
                .contains(QLatin1String("demonstration: the scripted operator (stick-180-left")),
            qPrintable(panel->tableText(prisca::core::TableFormat::Markdown).left(300)));

        QTemporaryDir dir;
        QString error;
        for (const char* name : {"t.md", "t.csv", "t.tex"}) {
            const QString path = dir.filePath(name);
            QVERIFY2(panel->exportTable(path, &error), qPrintable(error));
            QFile file(path);
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QString text = QString::fromUtf8(file.readAll());
            QVERIFY2(text.contains("PRISCA") && text.contains("PLAYBACK"), qPrintable(text));
        }
        QFile tex(dir.filePath("t.tex"));
        QVERIFY(tex.open(QIODevice::ReadOnly));
        QVERIFY(tex.readAll().contains("\\begin{tabular}"));
        const QString png = dir.filePath("fig7.png");
        QVERIFY2(panel->exportFigure(png, &error), qPrintable(error));
        QVERIFY(!QImage(png).isNull());
    }

    void experiments_cancelledTable1ShowsDashesNotNan() {
        Window w;
        auto* panel = w.find<ExperimentsPanel>("experimentsPanel");
        w.find<QComboBox>("experimentKind")->setCurrentIndex(0);
        w.find<QSpinBox>("experimentCount")->setValue(20);
        QSignalSpy finished(panel, &ExperimentsPanel::finished);
        w.find<QAbstractButton>("startExperiment")->click();
        w.find<QAbstractButton>("cancelExperiment")->click();  // the trials under way finish
        QVERIFY(finished.wait(kRunTimeoutMs));
        auto* table = w.find<QTableWidget>("experimentTable");
        QVERIFY(table->rowCount() > 0);
        int dashes = 0;
        for (int r = 0; r < table->rowCount(); ++r) {
            for (int c = 1; c < table->columnCount(); ++c) {
                const QString text = table->item(r, c)->text();
                QVERIFY2(!text.contains(QLatin1String("nan"), Qt::CaseInsensitive),
                         qPrintable(QStringLiteral("row %1 col %2: %3").arg(r).arg(c).arg(text)));
                dashes += text == QStringLiteral("—") ? 1 : 0;
            }
        }
        // Each row says how many trials it has; one short of the 20 asked is "(partial)", and
        // one trial gives no interval and no variance.
        for (int r = 0; r < table->rowCount(); ++r) {
            const int n = table->item(r, 1)->text().toInt();
            QVERIFY(n < 20);
            QVERIFY2(table->item(r, 0)->text().endsWith(QLatin1String("(partial)")),
                     qPrintable(table->item(r, 0)->text()));
            if (n == 1) {
                QVERIFY(!table->item(r, 2)->text().contains(QStringLiteral("±")));
                QCOMPARE(table->item(r, 3)->text(), QStringLiteral("—"));
            }
        }
        if (dashes == 0) {
            // On a loaded machine every method may have run a trial before the cancel took
            // effect: then there is no untouched row to look at.
            QSKIP("every method ran a trial before the cancel took effect");
        }
    }

    void experiments_cancelStopsTheCurvesAndKeepsWhatFinished() {
        Window w;
        w.find<QComboBox>("target")->setCurrentIndex(1);
        emit w.find<QComboBox>("target")->activated(1);  // the acrobot
        auto* panel = w.find<ExperimentsPanel>("experimentsPanel");
        w.find<QComboBox>("experimentKind")->setCurrentIndex(1);
        w.find<QSpinBox>("experimentCount")->setValue(20);
        w.find<QSpinBox>("experimentBudget")->setValue(2000000);  // far more than the test waits
        QSignalSpy finished(panel, &ExperimentsPanel::finished);
        w.find<QAbstractButton>("startExperiment")->click();
        QVERIFY(panel->isRunning());  // cancelled while it runs
        w.find<QAbstractButton>("cancelExperiment")->click();
        QVERIFY(finished.wait(kRunTimeoutMs));
        QVERIFY(!panel->isRunning());
        QVERIFY(panel->tableText(prisca::core::TableFormat::Markdown).contains("cancelled"));
        QCOMPARE(w.find<QTableWidget>("experimentTable")->rowCount(), 3);
    }
};

QTEST_MAIN(TestGuiExperiments)
#include "test_gui_experiments.moc"
