// The Model panel driven offscreen: the slide-car identified from the demonstration in the
// background (a short budget), its table, the replay drawn beside the recorded path, the model
// saved with the session and opened again, mpc's model set; Cancel and E-STOP keeping no model;
// the model dropped when the demonstration changes; plants identification does not know.
#include "GuiTestSupport.h"
#include "app/panels/ModelPanel.h"
#include "sim/planning/Identification.h"

#include <QProgressBar>

using namespace prisca::app;
using namespace prisca::test;

namespace {

// Generous: the suite passes while other work keeps both cores busy, and under AddressSanitizer.
constexpr int kIdentifyTimeoutMs = 240000;

// A search of a few hundred model runs: seconds, not the minute `prisca-cli identify` takes.
prisca::sim::IdentificationSettings quickSettings() {
    prisca::sim::IdentificationSettings quick;
    quick.restarts = 0;
    quick.evaluationsPerStart = 60;
    quick.passes = 1;
    return quick;
}

}  // namespace

class TestGuiModel : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_model"); }
    void init() { resetGuiState(); }

    void identify_fillsTheTableDrawsTheReplayAndIsSavedWithTheSession() {
        QTemporaryDir dir;
        const QString path = dir.filePath("session.json");
        Window w;
        LabSession& session = w.window.session();
        auto* panel = w.find<ModelPanel>("modelPanel");
        QVERIFY(panel);
        panel->setIdentificationSettings(quickSettings());
        QVERIFY(!session.identifiedModel());
        QVERIFY(!session.profile().mpcModel);
        // Before a model: the recorded path alone.
        QCOMPARE(panel->figure().panels.front().lines.size(), size_t(1));

        QSignalSpy finished(panel, &ModelPanel::finished);
        w.find<QAbstractButton>("identifyButton")->click();
        QVERIFY(panel->isRunning());
        QVERIFY(!w.find<QAbstractButton>("identifyButton")->isEnabled());
        QVERIFY(w.find<QAbstractButton>("cancelIdentify")->isEnabled());
        // A job of the window: quitting asks about it, Space and Esc are E-STOP meanwhile.
        QVERIFY(w.window.workInProgress().join(' ').contains("identification"));
        QVERIFY(finished.wait(kIdentifyTimeoutMs));
        QVERIFY(!panel->isRunning());

        const auto model = session.identifiedModel();
        QVERIFY2(model, qPrintable(w.find<QLabel>("modelStatus")->text()));
        QVERIFY(model->ok());
        QVERIFY2(w.find<QLabel>("modelStatus")->text().startsWith("Identified in"),
                 qPrintable(w.find<QLabel>("modelStatus")->text()));
        QVERIFY(w.find<QLabel>("modelSummary")->text().contains("mpc plans through this model"));
        // mpc plans through it: the profile every run copies holds its parameters.
        QVERIFY(session.profile().mpcModel);
        QCOMPARE(session.profile().mpcModel->values, model->parameters.values);
        QCOMPARE(session.task().profile.mpcModel->values, model->parameters.values);

        // The table: one row per fitted parameter, value, unit, deviation and verdict.
        auto* table = w.find<QTableWidget>("modelParameters");
        int fitted = 0;
        for (const auto& p : model->table) {
            fitted += p.fitted ? 1 : 0;
        }
        QVERIFY(fitted > 5);
        QCOMPARE(table->rowCount(), fitted);
        QCOMPARE(table->columnCount(), 5);
        bool someIdentified = false;
        for (int r = 0; r < table->rowCount(); ++r) {
            QVERIFY(!table->item(r, 0)->text().isEmpty());
            bool number = false;
            table->item(r, 1)->text().toDouble(&number);
            QVERIFY2(number, qPrintable(table->item(r, 1)->text()));
            someIdentified = someIdentified || table->item(r, 4)->text() == "identified";
            if (table->item(r, 4)->text() == "identified") {
                QVERIFY2(table->item(r, 3)->text().startsWith("±"),
                         qPrintable(table->item(r, 3)->text()));
            }
        }
        QVERIFY(someIdentified);
        QVERIFY(w.find<QLabel>("modelHeld")->text().contains("mass"));  // measured, not fitted

        // The figure: the recorded path and the model's replay, one point per sample each.
        const auto& lines = panel->figure().panels.front().lines;
        QCOMPARE(lines.size(), size_t(2));
        const auto samples = static_cast<size_t>(session.demonstration()->length());
        QCOMPARE(lines[0].points.size(), samples);
        QCOMPARE(lines[1].points.size(), samples);
        QCOMPARE(lines[1].points.front(), lines[0].points.front());  // from the same start
        QTRY_VERIFY(!w.find<QLabel>("modelFigure")->pixmap().isNull());

        // Saved with the session, and back when it is opened.
        QVERIFY(w.window.saveSession(path));
        LabSession opened;
        QString error;
        QVERIFY2(opened.open(path, &error), qPrintable(error));
        QVERIFY(opened.notice().isEmpty());
        QVERIFY(opened.identifiedModel());
        QCOMPARE(opened.identifiedModel()->parameters.values, model->parameters.values);
        QCOMPARE(opened.identifiedModel()->positionRms, model->positionRms);
        QCOMPARE(opened.identifiedModel()->table.size(), model->table.size());
        for (size_t i = 0; i < model->table.size(); ++i) {
            QCOMPARE(opened.identifiedModel()->table[i].identified, model->table[i].identified);
            QCOMPARE(opened.identifiedModel()->table[i].fitted, model->table[i].fitted);
        }
        QVERIFY(opened.profile().mpcModel);
        QCOMPARE(opened.profile().mpcModel->values, model->parameters.values);
        // The saved model is a plant file `run --model` reads.
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject saved = QJsonDocument::fromJson(file.readAll()).object();
        const QByteArray plantFile =
            QJsonDocument(saved.value("model").toObject().value("file").toObject()).toJson();
        const auto asPlantFile =
            prisca::sim::parsePlantParameters(plantFile, "model", "slidecar", &error);
        QVERIFY2(asPlantFile, qPrintable(error));
        QCOMPARE(asPlantFile->values, model->parameters.values);

        // A window opened on that session shows the model again.
        QVERIFY(w.window.openSession(path));
        QCOMPARE(table->rowCount(), fitted);

        // Resetting the controller's parameters keeps the model mpc plans through.
        w.find<QAbstractButton>("controllerPreset")->click();
        QVERIFY(session.profile().mpcModel);

        // Another demonstration: the model is of the old one, and the operator is told.
        session.setScriptedDemonstration(session.scriptedStyle(), session.scriptedSeed() + 1);
        QVERIFY(!session.identifiedModel());
        QVERIFY(!session.profile().mpcModel);
        QVERIFY2(
            w.find<QLabel>("modelStatus")->text().contains("cleared: the demonstration changed"),
            qPrintable(w.find<QLabel>("modelStatus")->text()));
        QVERIFY(!table->isVisible());
        QCOMPARE(panel->figure().panels.front().lines.size(), size_t(1));
    }

    void cancel_keepsNoModelAndSaysCancelled() {
        Window w;
        auto* panel = w.find<ModelPanel>("modelPanel");
        // The default budget (`prisca-cli identify`'s): cancelled long before it would end.
        QSignalSpy finished(panel, &ModelPanel::finished);
        w.find<QAbstractButton>("identifyButton")->click();
        QTRY_VERIFY_WITH_TIMEOUT(panel->progressDone() > 0, kIdentifyTimeoutMs);
        QVERIFY(w.find<QProgressBar>("identifyProgress")->maximum() > 0);
        w.find<QAbstractButton>("cancelIdentify")->click();
        QVERIFY(finished.wait(kIdentifyTimeoutMs));
        QVERIFY(!panel->isRunning());
        QVERIFY(!w.window.session().identifiedModel());
        QVERIFY(!w.window.session().profile().mpcModel);
        const QString status = w.find<QLabel>("modelStatus")->text();
        QVERIFY2(status.startsWith("Cancelled after") && status.contains("No model was kept"),
                 qPrintable(status));
        QVERIFY(w.find<QAbstractButton>("identifyButton")->isEnabled());
        QVERIFY(w.window.workInProgress().isEmpty());
    }

    void emergencyStop_cancelsTheIdentificationAndNoneStartsWhileLatched() {
        Window w;
        auto* panel = w.find<ModelPanel>("modelPanel");
        QSignalSpy finished(panel, &ModelPanel::finished);
        w.find<QAbstractButton>("identifyButton")->click();
        QVERIFY(panel->isRunning());
        // Space is E-STOP while a job runs, the identification included.
        QTest::keyClick(&w.window, Qt::Key_Space);
        QVERIFY(w.window.emergencyStop().isLatched());
        QVERIFY(finished.wait(kIdentifyTimeoutMs));
        QVERIFY(!w.window.session().identifiedModel());
        const QString status = w.find<QLabel>("modelStatus")->text();
        QVERIFY2(status.startsWith("Stopped by E-STOP"), qPrintable(status));
        QVERIFY(!w.find<QAbstractButton>("identifyButton")->isEnabled());
        panel->identify();  // refused while latched
        QVERIFY(!panel->isRunning());
        w.window.emergencyStop().reset();
        QVERIFY(w.find<QAbstractButton>("identifyButton")->isEnabled());
    }

    void otherPlants_sayTheyCannotBeIdentified() {
        Window w;
        w.window.session().setPlant(QStringLiteral("acrobot"));
        QVERIFY(!w.find<QAbstractButton>("identifyButton")->isEnabled());
        const QString summary = w.find<QLabel>("modelSummary")->text();
        QVERIFY2(summary.startsWith("Only the slide-car can be identified"), qPrintable(summary));
        w.find<ModelPanel>("modelPanel")->identify();
        QVERIFY(!w.find<ModelPanel>("modelPanel")->isRunning());
    }

    void sessions_withoutOrWithAnUnreadableModelStillOpen() {
        LabSession session;
        session.setPlant(QStringLiteral("slidecar"));
        QJsonObject root = QJsonDocument::fromJson(session.toJson()).object();
        QVERIFY(!root.contains("model"));
        LabSession opened;
        QString error;
        QVERIFY2(opened.fromJson(QJsonDocument(root).toJson(), "old", &error), qPrintable(error));
        QVERIFY(!opened.identifiedModel());
        QVERIFY(opened.notice().isEmpty());
        // A damaged model is left out, the operator told; the rest of the session opens.
        root.insert("model", QJsonObject{{"samples", 3}, {"file", QJsonObject{{"plant", 7}}}});
        QVERIFY2(opened.fromJson(QJsonDocument(root).toJson(), "damaged", &error),
                 qPrintable(error));
        QVERIFY(!opened.identifiedModel());
        QVERIFY2(opened.notice().contains("Model step"), qPrintable(opened.notice()));
    }
};

QTEST_MAIN(TestGuiModel)
#include "test_gui_model.moc"
