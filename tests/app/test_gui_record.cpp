// The Record and Mapping panels driven offscreen through their real widgets: a demonstration
// recorded by keyboard, E-STOP ending a recording, B~ edited and B_v fitted.
#include "GuiTestSupport.h"

using namespace prisca::app;
using namespace prisca::test;

class TestGuiRecord : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_record"); }
    void init() { resetGuiState(); }

    void record_drivingWithTheKeyboardMakesTheDemonstration() {
        Window w;
        auto* panel = w.find<RecordPanel>("recordPanel");
        w.find<QSpinBox>("countdown")->setValue(0);
        const auto scripted = w.window.session().demonstration();
        w.find<QAbstractButton>("recordButton")->click();
        QVERIFY(panel->isRecording());
        // Full throttle by ramp (2 per second), then a left turn, then hands off.
        QTest::keyPress(&w.window, Qt::Key_Up);
        QTRY_VERIFY(panel->input()[0] > 0.99);
        // The operator sees the time and what is commanded, and the brakeless car's warning.
        QTRY_VERIFY2(
            w.find<QLabel>("recordStatus")->text().contains(QLatin1String("throttle 1.00")),
            qPrintable(w.find<QLabel>("recordStatus")->text()));
        QVERIFY(w.find<QLabel>("recordStatus")->text().contains(QLatin1String("no brakes")));
        // Full throttle for 0.6 s of the recording's own time (not the wall clock's), counted
        // from the first samples that arrive now.
        double throttleFrom = -1.0, recorded = -1.0;
        const QMetaObject::Connection seen = QObject::connect(
            panel, &RecordPanel::samplesReady, panel,
            [&](const QVector<prisca::app::LiveSample>& samples) {
                if (!samples.isEmpty()) {
                    throttleFrom = throttleFrom < 0.0 ? samples.front().time : throttleFrom;
                    recorded = samples.back().time;
                }
            });
        QTRY_VERIFY_WITH_TIMEOUT(throttleFrom >= 0.0 && recorded >= throttleFrom + 0.6, 30000);
        QObject::disconnect(seen);
        QTest::keyPress(&w.window, Qt::Key_A);
        QTRY_VERIFY(panel->input()[1] > 0.5);
        QTest::keyRelease(&w.window, Qt::Key_A);
        QTest::keyRelease(&w.window, Qt::Key_Up);
        QTRY_VERIFY(panel->input().isZero());
        w.find<QAbstractButton>("stopRecordingButton")->click();
        QTRY_VERIFY(!panel->isRecording());
        QTRY_VERIFY(w.window.session().demonstration() != scripted);

        const auto demo = w.window.session().demonstration();
        const QString stream = w.window.session().demonstrationSource();
        QVERIFY2(stream.contains("recordings"), qPrintable(stream));
        QVERIFY2(demo->length() >= 40, qPrintable(QString::number(demo->length())));
        QVERIFY(demo->actions.col(0).maxCoeff() > 0.99);  // full throttle was recorded
        QVERIFY(demo->actions.col(1).maxCoeff() > 0.5);   // so was the left steer
        QVERIFY(demo->states.col(0).maxCoeff() > 0.3);    // and the car drove forward
        QVERIFY(demo->states.col(1).maxCoeff() > 0.0);    // and turned left
        // The stream on disk is a complete demonstration file of the same samples.
        prisca::core::FileError error;
        const auto onDisk = prisca::core::readDemonstrationCsv(stream, &error);
        QVERIFY2(onDisk, qPrintable(error.toString()));
        QCOMPARE(onDisk->length(), demo->length());
        QVERIFY(onDisk->states == demo->states);
        QVERIFY(onDisk->actions == demo->actions);
        // The fit follows the new demonstration.
        QCOMPARE(w.window.session().fit().samples > 0, true);

        // Discard: the scripted demonstration is back and the recording is gone.
        w.find<QAbstractButton>("discardRecordingButton")->click();
        QCOMPARE(w.window.session().demonstration(), scripted);
        QVERIFY(!QFile::exists(stream));
    }

    void record_emergencyStopEndsTheRecording() {
        Window w;
        auto* panel = w.find<RecordPanel>("recordPanel");
        w.find<QSpinBox>("countdown")->setValue(0);
        const auto before = w.window.session().demonstration();
        w.find<QAbstractButton>("recordButton")->click();
        QVERIFY(panel->isRecording());
        QTest::keyPress(&w.window, Qt::Key_Up);
        QTRY_VERIFY(panel->input()[0] > 0.5);
        QTest::keyClick(&w.window, Qt::Key_Space);
        QTRY_VERIFY(!panel->isRecording());
        QTest::keyRelease(&w.window, Qt::Key_Up);
        QVERIFY(panel->input().isZero());
        // The take E-STOP cut short is kept on disk but not made the demonstration.
        QTRY_VERIFY(w.find<QLabel>("recordStatus")->text().contains(QLatin1String("E-STOP")));
        QCOMPARE(w.window.session().demonstration(), before);
    }

    void mapping_editAndFitShowsValuesAndSignConflicts() {
        Window w;
        auto* panel = w.find<MappingPanel>("mappingPanel");
        auto* result = w.find<QTableWidget>("fitResult");
        auto* signs = w.find<QTableWidget>("signs");
        const double steeringToPsi = w.window.session().fit().b(1, 2);
        QVERIFY(steeringToPsi > 0.0);
        QCOMPARE(result->item(1, 2)->text(), QString::number(steeringToPsi, 'g', 2));
        // R² row under the two controls.
        QCOMPARE(result->verticalHeaderItem(2)->text(), QStringLiteral("R²"));
        // Clicking cycles 0 -> +1 -> -1; "steering turns right" contradicts the demonstration.
        QCOMPARE(signs->item(1, 2)->text(), QStringLiteral("+1"));
        signs->setCurrentCell(1, 2);
        emit signs->cellClicked(1, 2);
        QCOMPARE(signs->item(1, 2)->text(), QStringLiteral("−1"));
        w.find<QAbstractButton>("fitButton")->click();
        QCOMPARE(w.window.session().profile().mapping.signs(1, 2), -1);
        QCOMPARE(w.window.session().fit().b(1, 2), 0.0);  // B_v >= 0 keeps B~'s sign: set to 0
        QCOMPARE(result->item(1, 2)->text(), QStringLiteral("·"));
        auto* warnings = w.find<QLabel>("fitWarnings");
        QVERIFY(warnings->isVisible());
        bool named = false;
        for (const QString& line : warnings->text().split(QLatin1Char('\n'))) {
            named |= line.contains("steering") && line.contains("psi");
        }
        QVERIFY2(named, qPrintable(warnings->text()));
        // Back to +1 through the panel's setter and the fit returns.
        panel->setSign(1, 2, 1);
        panel->fit();
        QCOMPARE(w.window.session().fit().b(1, 2), steeringToPsi);
    }
};

QTEST_MAIN(TestGuiRecord)
#include "test_gui_record.moc"
