// The Experiments panel driven offscreen: Table I in the background, exported and read back,
// cancelled Table I and learning curves keeping what finished, the last result shown again after
// a restart (and a damaged kept file refused, not shown).
#include "GuiTestSupport.h"
#include "app/MessageLog.h"
#include "app/workers/ExperimentArchive.h"

#include <cmath>

using namespace prisca::app;
using namespace prisca::test;

class TestGuiExperiments : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_experiments"); }
    void init() { resetGuiState(); }

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
        QCOMPARE(table->rowCount(),
                 12);  // every Table I row: PRISCA's two, LQR, PGSD, ILC, the limit
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

        // The spin boxes changed after the run do not change what the result says it is.
        const QString caption = panel->tableText(prisca::core::TableFormat::Markdown);
        w.find<QSpinBox>("experimentCount")->setValue(7);
        w.find<QSpinBox>("experimentSeed")->setValue(4242);
        QCOMPARE(panel->shownRecord().count, 3);
        QCOMPARE(panel->tableText(prisca::core::TableFormat::Markdown), caption);

        // A restart shows the same result again, figure included, and says it is the kept one.
        QStringList cells;
        for (int r = 0; r < table->rowCount(); ++r) {
            for (int c = 0; c < table->columnCount(); ++c) {
                cells << table->item(r, c)->text();
            }
        }
        QVERIFY(!panel->showsKeptResult());
        Window again;
        auto* restored = again.find<ExperimentsPanel>("experimentsPanel");
        QVERIFY(restored->showsKeptResult());
        auto* restoredTable = again.find<QTableWidget>("experimentTable");
        QStringList restoredCells;
        for (int r = 0; r < restoredTable->rowCount(); ++r) {
            for (int c = 0; c < restoredTable->columnCount(); ++c) {
                restoredCells << restoredTable->item(r, c)->text();
            }
        }
        QCOMPARE(restoredCells, cells);
        QCOMPARE(restored->tableText(prisca::core::TableFormat::Markdown), caption);
        QVERIFY(!again.find<QLabel>("experimentFigure")->pixmap().isNull());
        QVERIFY(again.find<QAbstractButton>("exportTable")->isEnabled());
        const QString status = again.find<QLabel>("experimentStatus")->text();
        QVERIFY2(status.contains(QLatin1String("shown again")), qPrintable(status));
    }

    void experiments_keptCurvesRoundTrip_andADamagedFileIsRefused() {
        QTemporaryDir dir;
        KeptExperiment kept;
        kept.record.curves = true;
        kept.record.plant = QStringLiteral("acrobot");
        kept.record.poseTarget = false;
        kept.record.count = 2;
        kept.record.seed = 9;
        kept.record.budget = 3200;
        kept.record.demonstration = QStringLiteral("a test");
        kept.record.finished = QDateTime(QDate(2026, 12, 3), QTime(6, 30));
        auto curves = std::make_shared<std::vector<prisca::sim::CurveSummary>>();
        prisca::sim::CurveSummary c;
        c.method = QStringLiteral("prisca");
        c.steps = {0, 1600, 3200};
        c.seconds = {0.0, 40.0, 80.0};
        c.band.mean = {1.0, 0.5, std::nan("")};
        c.band.lower = {0.9, 0.25, std::nan("")};
        c.band.upper = {1.1, 0.75, std::nan("")};
        c.band.standardDeviation = {0.1, 0.2, std::nan("")};
        c.band.count = {2, 2, 0};
        curves->push_back(c);
        kept.curves = curves;
        kept.curvesCancelled = true;
        const QString path = dir.filePath("last.dat");
        QString error;
        QVERIFY2(saveKeptExperiment(path, kept, &error), qPrintable(error));
        const auto back = loadKeptExperiment(path, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->record.plant, kept.record.plant);
        QCOMPARE(back->record.finished, kept.record.finished);
        QCOMPARE(back->record.budget, 3200LL);
        QVERIFY(back->curvesCancelled);
        QVERIFY(back->curves && !back->table1);
        QCOMPARE(back->curves->at(0).steps, c.steps);
        QCOMPARE(back->curves->at(0).band.mean[1], 0.5);
        QVERIFY(std::isnan(back->curves->at(0).band.mean[2]));
        QCOMPARE(back->curves->at(0).band.count, c.band.count);

        // Cut short, or not ours: refused with the file named, never half shown.
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray whole = file.readAll();
        file.close();
        for (const QByteArray& bad :
             {whole.left(whole.size() - 5), QByteArray("hello world"), whole + QByteArray("x")}) {
            QFile out(path);
            QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
            out.write(bad);
            out.close();
            error.clear();
            QVERIFY(!loadKeptExperiment(path, &error));
            QVERIFY2(error.contains(path), qPrintable(error));
        }

        // A pose no floor has (a flipped bit, NaN) is damage too, never drawn.
        KeptExperiment broken;
        broken.record.plant = QStringLiteral("slidecar");
        auto table = std::make_shared<prisca::sim::Table1Result>();
        table->lot = Eigen::Vector3d(std::nan(""), 0.0, 0.0);
        broken.table1 = table;
        QVERIFY2(saveKeptExperiment(path, broken, &error), qPrintable(error));
        QVERIFY(!loadKeptExperiment(path, &error));
        table->lot = Eigen::Vector3d(4.0, 1.0, 0.5);  // the same, plausible: read back
        QVERIFY2(saveKeptExperiment(path, broken, &error), qPrintable(error));
        QVERIFY2(loadKeptExperiment(path, &error), qPrintable(error));

        // The window with a damaged kept file starts empty and says why in its log.
        QVERIFY(QDir().mkpath(QFileInfo(keptExperimentPath()).absolutePath()));
        QFile damaged(keptExperimentPath());
        QVERIFY(damaged.open(QIODevice::WriteOnly | QIODevice::Truncate));
        damaged.write(whole.left(20));
        damaged.close();
        Window w;
        QVERIFY(!w.find<ExperimentsPanel>("experimentsPanel")->showsKeptResult());
        QCOMPARE(w.find<QTableWidget>("experimentTable")->rowCount(), 0);
        const auto& entries = w.window.messageLog().entries();
        QVERIFY(std::any_of(entries.begin(), entries.end(), [](const LogEntry& e) {
            return e.level == MessageLevel::Warning &&
                   e.text.contains(QLatin1String("could not be shown again"));
        }));
        QFile::remove(keptExperimentPath());
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
