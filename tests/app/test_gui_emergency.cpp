// E-STOP over everything the window shows, one latch over every job, and the quit that keeps the
// right run: driven offscreen with the keys and clicks an operator would use.
#include "GuiTestSupport.h"
#include "app/input/GamepadEmergencyButton.h"
#include "app/panels/ReplayDialog.h"
#include "app/widgets/BundleChooser.h"

#include <QKeySequenceEdit>
#include <QMenu>
#include <QMenuBar>
#include <QProgressBar>
#include <QSlider>
#include <QTextBrowser>

#include <SDL.h>

using namespace prisca::test;

namespace {

// Runs `trigger` (which opens a dialog and returns when it closes, as ModalDialog::exec does),
// and `body` on the dialog once it is shown, from inside the dialog's own event loop. The dialog
// is closed afterwards if `body` left it open. False if no `T` was shown.
template <class T>
bool withDialog(QObject* context, const std::function<void()>& trigger,
                const std::function<void(T*)>& body) {
    bool seen = false;
    QTimer poll;
    poll.setInterval(20);
    QObject::connect(&poll, &QTimer::timeout, context, [&] {
        auto* dialog = qobject_cast<T*>(ModalDialog::top());
        if (seen || !dialog || !dialog->isVisible()) {
            return;
        }
        seen = true;
        poll.stop();
        body(dialog);
        if (dialog->isVisible()) {
            dialog->reject();
        }
    });
    poll.start();
    trigger();
    poll.stop();
    return seen;
}

// A simulated run in real time that lasts long enough for what follows.
void startLongRun(Window& w) {
    w.setSpeedIndex(0);
    w.find<QSpinBox>("trials")->setValue(50);
    w.find<RunPanel>("runPanel")->startRun();
    QTRY_COMPARE_WITH_TIMEOUT(w.window.run().phase(), RunPhase::Running, kRunTimeoutMs);
}

void resetEmergencyStop(Window& w) {
    w.find<QAbstractButton>("resetEmergencyButton")->click();
    QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
    QVERIFY(!w.window.emergencyStop().isLatched());
}

}  // namespace

class TestGuiEmergency : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_emergency"); }
    void init() { resetGuiState(); }

    void spaceInTheSaveDialog_stopsTheRunAndTheDialogStays() {
        Window w;
        startLongRun(w);
        const auto saveSession = [&] {
            w.activate();  // the offscreen platform does not hand it back when a dialog closes
            QTest::keyClick(&w.window, Qt::Key_S, Qt::ControlModifier);
        };
        // Ctrl+S opens the save dialog over the running window; Space in it, with the focus in
        // its file name field, is E-STOP.
        bool stayed = false;
        QVERIFY(withDialog<QFileDialog>(&w.window, saveSession, [&](QFileDialog* dialog) {
            auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
            QVERIFY(name);
            QTRY_VERIFY(name->hasFocus());  // a text field: with nothing running it takes spaces
            QTest::keyClick(name, Qt::Key_Space);
            QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
            QVERIFY(w.window.emergencyStop().isLatched());
            QVERIFY(!name->text().contains(QLatin1Char(' ')));
            stayed = dialog->isVisible();  // the operator's dialog is not taken from them
        }));
        QVERIFY(stayed);
        resetEmergencyStop(w);
        // Esc in it is E-STOP too while something runs (with nothing running it closes it).
        startLongRun(w);
        stayed = false;
        QVERIFY(withDialog<QFileDialog>(&w.window, saveSession, [&](QFileDialog* dialog) {
            QTest::keyClick(dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit")),
                            Qt::Key_Escape);
            QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
            stayed = dialog->isVisible();
        }));
        QVERIFY(stayed);
    }

    void redButton_takesAClickWithADialogOpen_andTheDialogKeepsTheRestOfTheWindow() {
        Window w;
        startLongRun(w);
        bool stayed = false;
        QVERIFY(withDialog<QFileDialog>(
            &w.window, [&] { QTest::keyClick(&w.window, Qt::Key_S, Qt::ControlModifier); },
            [&](QFileDialog* dialog) {
                // While the dialog is open the rest of the window takes no input: F6 (Pause) and
                // a click on Stop do nothing...
                auto* stop = w.find<QAbstractButton>("stopButton");
                QTest::mouseClick(w.window.windowHandle(), Qt::LeftButton, Qt::NoModifier,
                                  stop->mapTo(&w.window, stop->rect().center()));
                QTest::keyClick(&w.window, Qt::Key_F6);
                QCoreApplication::processEvents();
                QCOMPARE(w.window.run().phase(), RunPhase::Running);
                // ... but the red button does, and the dialog does not cover it.
                auto* button = w.find<QAbstractButton>("emergencyStopButton");
                const QRect red(button->mapToGlobal(QPoint(0, 0)), button->size());
                const QRect frame = dialog->frameGeometry();
                QVERIFY2(!frame.intersects(red),
                         qPrintable(QStringLiteral("dialog %1,%2 %3x%4 over the button at %5,%6")
                                        .arg(frame.x())
                                        .arg(frame.y())
                                        .arg(frame.width())
                                        .arg(frame.height())
                                        .arg(red.x())
                                        .arg(red.y())));
                // A click as the platform delivers it (through the window, where Qt's own
                // modality would drop it), not straight to the widget.
                QVERIFY(QGuiApplication::modalWindow() == nullptr);
                QTest::mouseClick(w.window.windowHandle(), Qt::LeftButton, Qt::NoModifier,
                                  button->mapTo(&w.window, button->rect().center()));
                QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
                stayed = dialog->isVisible();
            }));
        QVERIFY(stayed);
    }

    void emergencyStop_winsOverTheShortcutSheetTheQuitQuestionAndAMessage() {
        Window w;
        startLongRun(w);
        bool stayed = false;
        QVERIFY(withDialog<QMessageBox>(
            &w.window, [&] { w.find<QAction>("shortcutsAction")->trigger(); },
            [&](QMessageBox* sheet) {
                QCOMPARE(sheet->objectName(), QStringLiteral("shortcutSheet"));
                QTest::keyClick(sheet, Qt::Key_Space);  // this closed the sheet; the run went on
                QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
                stayed = sheet->isVisible();
            }));
        QVERIFY(stayed);
        resetEmergencyStop(w);

        // The quit question: Space pressed its Cancel once.
        startLongRun(w);
        stayed = false;
        QVERIFY(withDialog<QMessageBox>(
            &w.window, [&] { w.window.close(); },
            [&](QMessageBox* question) {
                QCOMPARE(question->objectName(), QStringLiteral("quitQuestion"));
                QTest::keyClick(question->focusWidget() ? question->focusWidget() : question,
                                Qt::Key_Space);
                QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
                stayed = question->isVisible();
                question->findChild<QAbstractButton*>(QStringLiteral("quitCancel"))->click();
            }));
        QVERIFY(stayed);
        QVERIFY(w.window.isVisible());
    }

    void emergencyStop_winsOverAnOpenMenuTheGuideAndTheReplay() {
        Window w;
        startLongRun(w);
        // An open menu: Space is E-STOP, and a click on the red button too (not just a close).
        QMenu* runMenu = w.window.menuBar()->findChild<QMenu*>(QStringLiteral("runMenu"));
        QVERIFY(runMenu);
        runMenu->popup(w.window.mapToGlobal(QPoint(40, 40)));
        QTRY_VERIFY(QApplication::activePopupWidget() == runMenu);
        QTest::keyClick(runMenu, Qt::Key_Space);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        QTRY_VERIFY(QApplication::activePopupWidget() == nullptr);
        resetEmergencyStop(w);

        startLongRun(w);
        auto* speed = w.find<QComboBox>("speed");
        speed->showPopup();
        QTRY_VERIFY(QApplication::activePopupWidget() != nullptr);
        auto* button = w.find<QAbstractButton>("emergencyStopButton");
        QTest::mouseClick(QApplication::activePopupWidget(), Qt::LeftButton, Qt::NoModifier,
                          QApplication::activePopupWidget()->mapFromGlobal(
                              button->mapToGlobal(button->rect().center())));
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        resetEmergencyStop(w);

        // The operator guide (F1): Space in it is E-STOP, and it does not cover the red button.
        startLongRun(w);
        w.find<QAction>("guideAction")->trigger();
        QDialog* guide = nullptr;
        QTRY_VERIFY((guide = w.window.findChild<QDialog*>(QStringLiteral("operatorGuide"))) &&
                    guide->isVisible());
        const QRect red(button->mapToGlobal(QPoint(0, 0)), button->size());
        QVERIFY(!guide->frameGeometry().intersects(red));
        QTest::keyClick(guide->findChild<QTextBrowser*>(QStringLiteral("guideText")),
                        Qt::Key_Space);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        QVERIFY(guide->isVisible());
        guide->close();
    }

    // A method that plans through a model identifies it when the run starts (seconds): that is
    // work under way, so Space in an open menu is E-STOP then too, and no trial starts after it.
    void emergencyStop_winsWhileTheRunIdentifiesItsModel() {
        Window w;
        w.setSpeedIndex(0);
        auto* method = w.find<QComboBox>("method");
        method->setCurrentIndex(method->findData(QStringLiteral("mpc")));
        emit method->activated(method->currentIndex());
        QCOMPARE(w.window.session().method(), QStringLiteral("mpc"));
        w.find<QSpinBox>("trials")->setValue(3);
        const RunWorker* worker = w.window.run().worker();
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(w.window.run().phase(), RunPhase::Training, kRunTimeoutMs);
        QVERIFY(!w.window.workInProgress().isEmpty());
        QMenu* runMenu = w.window.menuBar()->findChild<QMenu*>(QStringLiteral("runMenu"));
        QVERIFY(runMenu);
        runMenu->popup(w.window.mapToGlobal(QPoint(40, 40)));
        QTRY_VERIFY(QApplication::activePopupWidget() == runMenu);
        QTest::keyClick(runMenu, Qt::Key_Space);
        QVERIFY(w.window.emergencyStop().isLatched());
        QTRY_VERIFY(QApplication::activePopupWidget() == nullptr);
        // E-STOP cuts the identification short.
        QTRY_COMPARE_WITH_TIMEOUT(w.window.run().phase(), RunPhase::EmergencyStopped,
                                  kRunTimeoutMs);
        QCOMPARE(worker->stepsTaken(), 0);
        resetEmergencyStop(w);
    }

    void emergencyStop_winsOverTheReplayWindow() {
        Window w;
        // A finished simulated trial leaves a bundle (the trials are kept as bundles).
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(1);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(w.results()->rowCount(), 1, kRunTimeoutMs);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        const QString trials =
            QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
                .filePath(QStringLiteral("trials"));
        std::vector<BundleEntry> bundles;
        QTRY_VERIFY((bundles = BundleChooser::scan({trials})).size() >= 1);
        ReplayDialog* replay = w.window.openReplay(bundles.front().folder);
        QVERIFY(replay);
        startLongRun(w);
        auto* slider = replay->findChild<QSlider*>(QStringLiteral("replaySlider"));
        QTest::keyClick(slider, Qt::Key_Space);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        QVERIFY(replay->isVisible());
        replay->close();
    }

    void aDialogsOwnPopups_takeTheKeys() {
        // A popup a dialog opens may have no parent (the file dialog's name completer is such a
        // window): the keys it takes must reach it, though it is no child of the dialog the
        // other windows are kept from. (Before, the completer ate the path being typed.)
        Window w;
        bool picked = false;
        QVERIFY(withDialog<QFileDialog>(
            &w.window,
            [&] {
                w.activate();
                QTest::keyClick(&w.window, Qt::Key_O, Qt::ControlModifier);
            },
            [&](QFileDialog* dialog) {
                QMenu list;  // no parent, a popup of its own
                QAction* first = list.addAction(QStringLiteral("/tmp/alpha.json"));
                list.addAction(QStringLiteral("/tmp/beta.json"));
                QObject::connect(first, &QAction::triggered, [&] { picked = true; });
                list.popup(dialog->mapToGlobal(QPoint(40, 40)));
                QTRY_VERIFY(QApplication::activePopupWidget() == &list);
                QTest::keyClick(&list, Qt::Key_Down);
                QTest::keyClick(&list, Qt::Key_Return);
            }));
        QVERIFY(picked);
    }

    void nothingRunning_spaceAndEscAreTheDialogsOwn() {
        Window w;
        bool closedByEsc = false;
        QVERIFY(withDialog<QMessageBox>(
            &w.window, [&] { w.find<QAction>("shortcutsAction")->trigger(); },
            [&](QMessageBox* sheet) {
                QTest::keyClick(sheet, Qt::Key_Escape);  // closes it; nothing to stop
                closedByEsc = !sheet->isVisible();
            }));
        QVERIFY(closedByEsc);
        QVERIFY(!w.window.emergencyStop().isLatched());
    }

    void latch_coversExperimentsAndRecordings_andNothingStartsWhileLatched() {
        Window w;
        auto* experiments = w.find<ExperimentsPanel>("experimentsPanel");
        w.find<QComboBox>("experimentKind")->setCurrentIndex(0);
        w.find<QSpinBox>("experimentCount")->setValue(200);
        experiments->start();
        QVERIFY(experiments->isRunning());
        QTRY_VERIFY_WITH_TIMEOUT(experiments->progressDone() >= 1, 120000);
        QTest::keyClick(&w.window, Qt::Key_Space);
        QVERIFY(w.window.emergencyStop().isLatched());
        // The experiment stops with what finished, marked partial.
        QTRY_VERIFY_WITH_TIMEOUT(!experiments->isRunning(), 120000);
        const QString md = experiments->tableText(prisca::core::TableFormat::Markdown);
        QVERIFY2(md.contains(QLatin1String("(partial:")), qPrintable(md));
        auto* status = w.find<QLabel>("experimentStatus");
        QVERIFY2(status->text().contains(QLatin1String("E-STOP")), qPrintable(status->text()));
        auto* bar = w.find<QProgressBar>("experimentProgress");
        QVERIFY2(bar->text().contains(QLatin1String("Cancelled")), qPrintable(bar->text()));
        // While latched nothing starts: the run, a recording, an experiment, a rig trial.
        QVERIFY(!w.find<QAbstractButton>("runButton")->isEnabled());
        QVERIFY(!w.find<QAbstractButton>("startExperiment")->isEnabled());
        QVERIFY(!w.find<QAbstractButton>("recordButton")->isEnabled());
        QVERIFY(!w.find<QAbstractButton>("runOnRig")->isEnabled());
        experiments->start();  // called directly: refused all the same
        QVERIFY(!experiments->isRunning());
        QVERIFY(status->text().contains(QLatin1String("Reset E-STOP")));
        auto* rig = w.find<RigPanel>("rigPanel");
        QVERIFY(!rig->runTrial());
        auto* rigInfo = w.find<QLabel>("rigTrialInfo");
        QVERIFY2(rigInfo->text().contains(QLatin1String("Reset E-STOP")),
                 qPrintable(rigInfo->text()));
        w.find<RecordPanel>("recordPanel")->startCountdown();
        QVERIFY(!w.find<RecordPanel>("recordPanel")->isRecording());
        QVERIFY(w.window.workInProgress().isEmpty());
        w.find<QAbstractButton>("resetEmergencyButton")->click();
        QVERIFY(!w.window.emergencyStop().isLatched());
        // What the Rig panel said of the latch is gone with it.
        QVERIFY2(!rigInfo->text().contains(QLatin1String("latched")) &&
                     rigInfo->text().contains(QLatin1String("E-STOP is reset")),
                 qPrintable(rigInfo->text()));
        QVERIFY(w.find<QAbstractButton>("startExperiment")->isEnabled());
        QVERIFY(w.find<QAbstractButton>("recordButton")->isEnabled());
        QVERIFY(w.find<QAbstractButton>("runOnRig")->isEnabled());
        QTRY_VERIFY(w.find<QAbstractButton>("runButton")->isEnabled());
    }

    void latch_endsARecording_andItsTakeIsKept() {
        Window w;
        auto* record = w.find<RecordPanel>("recordPanel");
        w.find<QSpinBox>("countdown")->setValue(0);
        record->startCountdown();
        QVERIFY(record->isRecording());
        QTest::qWait(300);  // a little driving
        w.find<QAbstractButton>("emergencyStopButton")->click();
        QTRY_VERIFY(!record->isRecording());
        auto* status = w.find<QLabel>("recordStatus");
        QTRY_VERIFY2(status->text().contains(QLatin1String("E-STOP ended the recording")),
                     qPrintable(status->text()));
        // The take is on disk in the recordings folder.
        const QStringList takes =
            QDir(RecordPanel::recordingsFolder()).entryList({QStringLiteral("*.csv")}, QDir::Files);
        QVERIFY(!takes.isEmpty());
    }

    void aTrialCutByEmergencyStop_leavesARowThatSaysSo() {
        Window w;
        w.setSpeedIndex(0);
        w.find<QSpinBox>("trials")->setValue(3);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_VERIFY_WITH_TIMEOUT(w.window.run().worker()->stepsTaken() > 20, kRunTimeoutMs);
        QTest::keyClick(&w.window, Qt::Key_Escape);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        QTRY_COMPARE(w.results()->rowCount(), 1);
        QCOMPARE(w.results()->item(0, 0)->text(), QStringLiteral("1 (E-STOP)"));
    }

    void footSwitchKey_isEmergencyStopAnywhere() {
        QSettings().setValue(QLatin1String(MainWindow::kEmergencyKeysKey),
                             QStringList{QStringLiteral("F13")});
        Window w;
        QCOMPARE(w.window.emergencyStopGuard().extraKeys().size(), 1);
        // With nothing running, in a dialog (where Space and Esc are the dialog's own).
        QVERIFY(withDialog<QMessageBox>(
            &w.window, [&] { w.find<QAction>("shortcutsAction")->trigger(); },
            [&](QMessageBox* sheet) {
                QVERIFY2(sheet->text().contains(QLatin1String("F13")), qPrintable(sheet->text()));
                QTest::keyClick(sheet, Qt::Key_F13);
            }));
        QVERIFY(w.window.emergencyStop().isLatched());
        QCOMPARE(w.window.emergencyStop().pressedBy(), QStringLiteral("F13"));
        resetEmergencyStop(w);
        // In a text field too (a foot switch's key is never typed).
        auto* filter = w.find<QLineEdit>("cameraPath");
        filter->setEnabled(true);
        filter->setFocus();
        QTest::keyClick(filter, Qt::Key_F13);
        QVERIFY(w.window.emergencyStop().isLatched());
    }

    void footSwitchKey_isSetInTheInputsDialog() {
        Window w;
        QVERIFY(withDialog<QDialog>(
            &w.window, [&] { w.find<QAction>("emergencyInputsAction")->trigger(); },
            [&](QDialog* dialog) {
                QCOMPARE(dialog->objectName(), QStringLiteral("emergencyInputs"));
                auto* key = dialog->findChild<QKeySequenceEdit*>(QStringLiteral("footSwitchKey"));
                key->setFocus();
                QTest::keyClick(key, Qt::Key_Pause);
                QTRY_VERIFY(!key->keySequence().isEmpty());
                auto* pad = dialog->findChild<QComboBox*>(QStringLiteral("gamepadButton"));
                pad->setCurrentIndex(pad->findData(QStringLiteral("back")));
                dialog->accept();
            }));
        QCOMPARE(QSettings().value(QLatin1String(MainWindow::kEmergencyKeysKey)).toStringList(),
                 QStringList{QStringLiteral("Pause")});
        QCOMPARE(w.window.gamepadEmergencyButton().buttons(), QStringList{QStringLiteral("back")});
        QTest::keyClick(&w.window, Qt::Key_Pause);
        QVERIFY(w.window.emergencyStop().isLatched());
    }

    void gamepadButton_isEmergencyStopWithADialogOpen() {
        SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
        if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0) {
            QSKIP("SDL's game controller subsystem is not available here");
        }
        // A virtual pad of the common layout, as SDL would show a real one.
        SDL_VirtualJoystickDesc desc;
        SDL_zero(desc);
        desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
        desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
        desc.naxes = SDL_CONTROLLER_AXIS_MAX;
        desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
        desc.name = "PRISCA test pad";
        const int index = SDL_JoystickAttachVirtualEx(&desc);
        QVERIFY2(index >= 0, SDL_GetError());
        SDL_Joystick* joystick = SDL_JoystickOpen(index);
        QVERIFY(joystick);
        {
            Window w;  // its pad button: "b" by default
            QCOMPARE(w.window.gamepadEmergencyButton().buttons(), QStringList{QStringLiteral("b")});
            QTRY_VERIFY_WITH_TIMEOUT(w.window.gamepadEmergencyButton().padFound(), 5000);
            startLongRun(w);
            QVERIFY(withDialog<QFileDialog>(
                &w.window, [&] { QTest::keyClick(&w.window, Qt::Key_S, Qt::ControlModifier); },
                [&](QFileDialog*) {
                    SDL_JoystickSetVirtualButton(joystick, SDL_CONTROLLER_BUTTON_B, 1);
                    QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
                    SDL_JoystickSetVirtualButton(joystick, SDL_CONTROLLER_BUTTON_B, 0);
                }));
            QVERIFY(w.window.emergencyStop().pressedBy().contains(QLatin1String("gamepad")));
        }
        SDL_JoystickClose(joystick);
        SDL_JoystickDetachVirtual(index);
        SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
    }

    void finishThenQuit_keepsTheRunThatJustFinished() {
        QDir(MainWindow::keptFolder()).removeRecursively();
        Window w;
        w.setSpeedIndex(2);  // as fast as possible
        w.find<QSpinBox>("trials")->setValue(1);
        // A first run, seed 3, to its end.
        w.find<QSpinBox>("seed")->setValue(3);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(w.results()->rowCount(), 1, kRunTimeoutMs);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        // A second, seed 4, in real time, and quit asking to finish it first.
        w.setSpeedIndex(0);
        w.find<QSpinBox>("seed")->setValue(4);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(w.window.run().phase(), RunPhase::Running, kRunTimeoutMs);
        const QString asked =
            answerQuitQuestion(&w.window, "quitFinish", [&] { w.window.close(); });
        QVERIFY(!asked.isEmpty());
        // The pending quit stays in view.
        auto* pending = w.find<QWidget>("pendingQuit");
        QVERIFY(pending->isVisible());
        w.setSpeedIndex(2);  // finish it sooner
        QTRY_VERIFY_WITH_TIMEOUT(!w.window.isVisible(), kRunTimeoutMs);
        const QStringList kept =
            QDir(MainWindow::keptFolder()).entryList({QStringLiteral("run-*.csv")}, QDir::Files);
        QCOMPARE(kept.size(), 1);
        QFile log(QDir(MainWindow::keptFolder()).filePath(kept.first()));
        QVERIFY(log.open(QIODevice::ReadOnly));
        const QByteArray text = log.readAll();
        QVERIFY2(text.contains("# seed: 4"), text.left(600).constData());
    }

    void pendingQuit_canBeCalledOff() {
        Window w;
        startLongRun(w);
        answerQuitQuestion(&w.window, "quitFinish", [&] { w.window.close(); });
        auto* pending = w.find<QWidget>("pendingQuit");
        QVERIFY(pending->isVisible());
        // Messages come and go in the status bar; the pending quit stays.
        w.window.statusBar()->showMessage(QStringLiteral("something else"));
        QVERIFY(pending->isVisible());
        w.find<QAbstractButton>("cancelQuit")->click();
        QVERIFY(!pending->isVisible());
        w.find<QAbstractButton>("stopButton")->click();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        QCoreApplication::processEvents();
        QVERIFY(w.window.isVisible());  // the run ended and the window stayed
    }
};

QTEST_MAIN(TestGuiEmergency)
#include "test_gui_emergency.moc"
