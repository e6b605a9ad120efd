// MainWindow: the tool bar, the status bar, the menus, Help's windows and the E-STOP inputs.
#include "app/MainWindow.h"
#include "app/MainWindow_p.h"

#include "app/widgets/ModalDialog.h"

#include "app/EmergencyStop.h"
#include "app/EmergencyStopGuard.h"
#include "app/LabSession.h"
#include "app/LanguageMenu.h"
#include "app/LanguageSwitcher.h"
#include "app/MessageLog.h"
#include "app/input/GamepadEmergencyButton.h"
#include "app/panels/ControllerPanel.h"
#include "app/panels/ExperimentsPanel.h"
#include "app/panels/LiveChartsPanel.h"
#include "app/panels/MappingPanel.h"
#include "app/panels/MessageLogPanel.h"
#include "app/panels/ModelPanel.h"
#include "app/panels/RecordPanel.h"
#include "app/panels/ReplayDialog.h"
#include "app/panels/RunPanel.h"
#include "app/panels/TaskPanel.h"
#include "app/rig/RigPanel.h"
#include "app/widgets/ArenaView.h"
#include "app/widgets/BundleChooser.h"
#include "app/workers/RunThread.h"
#include "core/RunLogCsv.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QCoreApplication>
#include <QDateTime>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QImage>
#include <QKeyEvent>
#include <QKeySequenceEdit>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QShowEvent>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextEdit>
#include <QTextImageFormat>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace prisca::app {

void MainWindow::createToolBar() {
    // Always visible, above every dock: run controls and the E-STOP no dock layout can cover.
    runToolBar_ = addToolBar(QString());
    runToolBar_->setObjectName(QStringLiteral("runToolBar"));
    runToolBar_->setMovable(false);
    runToolBar_->setFloatable(false);
    runToolBar_->toggleViewAction()->setVisible(false);  // cannot be hidden by mistake
    runToolBar_->setToolButtonStyle(Qt::ToolButtonTextOnly);
    runToolBar_->addActions(runPanel_->runActions());
    const QStringList names = {QStringLiteral("runButton"), QStringLiteral("pauseButton"),
                               QStringLiteral("stopButton"), QStringLiteral("resetButton")};
    for (int i = 0; i < names.size(); ++i) {
        runToolBar_->widgetForAction(runPanel_->runActions()[i])->setObjectName(names[i]);
    }
    auto* spacer = new QWidget(runToolBar_);
    spacer->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    runToolBar_->addWidget(spacer);
    auto* resetEmergency = new QToolButton(runToolBar_);
    resetEmergency->setObjectName(QStringLiteral("resetEmergencyButton"));
    resetEmergency->setDefaultAction(runPanel_->resetEmergencyAction());
    runToolBar_->addWidget(resetEmergency);
    emergencyButton_ = new QPushButton(runToolBar_);
    emergencyButton_->setObjectName(QStringLiteral("emergencyStopButton"));
    emergencyButton_->setFocusPolicy(Qt::NoFocus);
    emergencyButton_->setMinimumSize(240, 40);
    // On press, not release: the fastest the operator can ask. No dialog of ours covers it or
    // blocks it (ModalDialog, EmergencyStopGuard).
    connect(emergencyButton_, &QPushButton::pressed, emergency_,
            [this] { emergency_->engage(tr("the E-STOP button")); });
    ModalDialog::keepClearOf(emergencyButton_);
    runToolBar_->addWidget(emergencyButton_);
    const auto showEmergencyText = [this] {
        emergencyButton_->setText(emergencyShownLatched_ ? tr("E-STOP LATCHED")
                                                         : runPanel_->emergencyAction()->text());
        emergencyButton_->setToolTip(runPanel_->emergencyAction()->toolTip());
    };
    connect(runPanel_->emergencyAction(), &QAction::changed, this, showEmergencyText);
    showEmergencyText();
}

void MainWindow::createStatusBar() {
    // Always at the window's foot: what runs, the link, the camera, E-STOP. Each field is a
    // label of its own so a passing message never hides them.
    const auto field = [this](const char* name) {
        auto* label = new QLabel(this);
        label->setObjectName(QLatin1String(name));
        label->setContentsMargins(6, 0, 6, 0);
        label->setTextFormat(Qt::PlainText);
        statusBar()->addPermanentWidget(label);
        return label;
    };
    jobStatus_ = field("jobStatus");
    linkStatus_ = field("linkStatusField");
    cameraStatus_ = field("cameraStatusField");
    emergencyStatus_ = field("emergencyStatus");
    versionLabel_->setObjectName(QStringLiteral("versionLabel"));
    statusBar()->addPermanentWidget(versionLabel_);
    const auto alarm = [](QLabel* label, bool on) {
        label->setStyleSheet(on ? QStringLiteral("color: #b00020; font-weight: bold;") : QString());
    };
    connect(rigPanel_, &RigPanel::statusSummary, this,
            [this, alarm](const QString& link, bool linkAlarm, const QString& camera,
                          bool cameraAlarm) {
                linkStatus_->setText(link);
                alarm(linkStatus_, linkAlarm);
                cameraStatus_->setText(camera);
                alarm(cameraStatus_, cameraAlarm);
            });
    rigPanel_->emitStatus();
    // The job's progress changes without a signal of its own in every panel: a glance a few
    // times a second is enough for a status bar.
    statusTimer_ = new QTimer(this);
    statusTimer_->setInterval(250);
    connect(statusTimer_, &QTimer::timeout, this, &MainWindow::updateStatusFields);
    statusTimer_->start();
    connect(run_, &RunThread::phaseChanged, this, &MainWindow::updateStatusFields);
    connect(emergency_, &EmergencyStop::latchChanged, this, &MainWindow::showEmergencyState);
    showEmergencyState(emergency_->isLatched());
    // A quit that waits for the work says so until it happens, and can be called off.
    pendingQuit_ = new QWidget(this);
    pendingQuit_->setObjectName(QStringLiteral("pendingQuit"));
    auto* pendingLayout = new QHBoxLayout(pendingQuit_);
    pendingLayout->setContentsMargins(6, 0, 6, 0);
    pendingQuitText_ = new QLabel(pendingQuit_);
    pendingQuitText_->setStyleSheet(QStringLiteral("color: #9a5600; font-weight: bold;"));
    cancelQuit_ = new QPushButton(pendingQuit_);
    cancelQuit_->setObjectName(QStringLiteral("cancelQuit"));
    pendingLayout->addWidget(pendingQuitText_);
    pendingLayout->addWidget(cancelQuit_);
    statusBar()->insertPermanentWidget(0, pendingQuit_);
    pendingQuit_->hide();
    connect(cancelQuit_, &QPushButton::clicked, this, [this] {
        quitPlan_ = QuitPlan::None;
        showPendingQuit();
        say(tr("Quit"), tr("The quit was called off; the work goes on."), kStatusMessageMs);
    });
}

void MainWindow::showPendingQuit() {
    pendingQuit_->setVisible(quitPlan_ != QuitPlan::None);
    pendingQuitText_->setText(quitPlan_ == QuitPlan::Finish
                                  ? tr("Quits when the work under way is done")
                                  : tr("Quits once the work has stopped"));
    cancelQuit_->setText(tr("Don't quit"));
    cancelQuit_->setEnabled(quitPlan_ == QuitPlan::Finish);
}

void MainWindow::updateStatusFields() {
    QString job;
    switch (run_->phase()) {
        case RunPhase::Training:
            job = tr("Job: preparing the run (training, or identifying the model)");
            break;
        case RunPhase::Running:
            job = tr("Job: simulated run");
            break;
        case RunPhase::Paused:
            job = tr("Job: simulated run, PAUSED");
            break;
        case RunPhase::Idle:
        case RunPhase::EmergencyStopped:
            break;
    }
    if (job.isEmpty() && experimentsPanel_->isRunning()) {
        job = experimentsPanel_->progressTotal() > 0 ? tr("Job: experiment, %1 of %2")
                                                           .arg(experimentsPanel_->progressDone())
                                                           .arg(experimentsPanel_->progressTotal())
                                                     : tr("Job: experiment, starting");
    }
    if (job.isEmpty() && rigPanel_->isRunning()) {
        job = tr("Job: rig trial");
    }
    if (job.isEmpty() && modelPanel_->isRunning()) {
        job = modelPanel_->progressTotal() > 0
                  ? tr("Job: identifying the model, %1 %")
                        .arg(100 * modelPanel_->progressDone() / modelPanel_->progressTotal())
                  : tr("Job: identifying the model");
    }
    if (job.isEmpty() && rigPanel_->measuringLatency()) {
        job = tr("Job: measuring latency");
    }
    if (job.isEmpty() && (rigPanel_->isDriving() || recordPanel_->isRecording())) {
        job = tr("Job: recording");
    }
    if (job.isEmpty()) {
        job = tr("Job: none");
    }
    jobStatus_->setText(job);
    jobStatus_->setStyleSheet(run_->phase() == RunPhase::Paused
                                  ? QStringLiteral("color: #9a5600; font-weight: bold;")
                                  : QString());
    quitWhenIdle();
}

void MainWindow::showEmergencyState(bool latched) {
    emergencyStatus_->setText(latched ? tr("E-STOP LATCHED") : tr("E-STOP ready"));
    emergencyStatus_->setStyleSheet(
        latched ? QStringLiteral("color: white; background: #b00020; font-weight: bold;")
                : QString());
    const QString text = latched ? tr("E-STOP LATCHED") : runPanel_->emergencyAction()->text();
    if (emergencyButton_->text() != text) {
        emergencyButton_->setText(text);
    }
    if (latched == emergencyShownLatched_ && !emergencyButton_->styleSheet().isEmpty()) {
        return;
    }
    emergencyShownLatched_ = latched;
    // Latched, the button is pressed in: dark, sunken, and says so; Reset is next to it.
    emergencyButton_->setStyleSheet(
        latched
            ? QStringLiteral("QPushButton { background: #5c0000; color: #ffd7d7; font-weight: bold;"
                             " font-size: 18px; border: 3px inset #2a0000; border-radius: 6px;"
                             " padding: 2px 16px; }")
            : QStringLiteral("QPushButton { background: #c62828; color: white; font-weight: bold;"
                             " font-size: 18px; border: 3px solid #7f0000; border-radius: 6px;"
                             " padding: 2px 16px; }"
                             "QPushButton:pressed { background: #8e0000; }"));
}

void MainWindow::createMenus() {
    fileMenu_ = menuBar()->addMenu(QString());
    fileMenu_->setObjectName(QStringLiteral("fileMenu"));
    openSessionAction_ = fileMenu_->addAction(QString());
    openSessionAction_->setObjectName(QStringLiteral("openSessionAction"));
    openSessionAction_->setShortcut(QKeySequence::Open);
    connect(openSessionAction_, &QAction::triggered, this, [this] {
        const QString path = ModalDialog::openFileName(
            this, tr("Open session"), QFileInfo(sessionPath_).absolutePath(),
            tr("PRISCA Lab sessions (*.json);;All files (*)"));
        if (!path.isEmpty()) {
            openSession(path);
        }
    });
    recentMenu_ = fileMenu_->addMenu(QString());
    recentMenu_->setObjectName(QStringLiteral("recentMenu"));
    saveSessionAction_ = fileMenu_->addAction(QString());
    saveSessionAction_->setObjectName(QStringLiteral("saveSessionAction"));
    saveSessionAction_->setShortcut(QKeySequence::Save);
    connect(saveSessionAction_, &QAction::triggered, this, [this] {
        QString path = ModalDialog::saveFileName(this, tr("Save session"), sessionPath_,
                                                 tr("PRISCA Lab sessions (*.json)"));
        if (!path.isEmpty()) {
            if (QFileInfo(path).suffix().isEmpty()) {
                path += QStringLiteral(".json");
            }
            saveSession(path);
        }
    });
    replayAction_ = fileMenu_->addAction(QString());
    replayAction_->setObjectName(QStringLiteral("replayAction"));
    replayAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R));
    connect(replayAction_, &QAction::triggered, this, [this] {
        // The rig's bundles and the simulation's (both in the trials folder unless the rig's
        // were sent elsewhere), newest first, apart.
        const QString trials =
            QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
                .filePath(QStringLiteral("trials"));
        BundleChooser chooser(
            {rigPanel_->bundleParent().isEmpty() ? trials : rigPanel_->bundleParent(), trials},
            this);
        if (ModalDialog::exec(chooser) == QDialog::Accepted && !chooser.chosen().isEmpty()) {
            openReplay(chooser.chosen());
        }
    });
    fileMenu_->addSeparator();
    quitAction_ = fileMenu_->addAction(QString());
    quitAction_->setObjectName(QStringLiteral("quitAction"));
    // Ctrl+Q on every platform, not the platform's Quit key (which is empty on Windows).
    quitAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));
    quitAction_->setMenuRole(QAction::QuitRole);
    // Closing the window (not QCoreApplication::quit) so closeEvent saves the geometry.
    connect(quitAction_, &QAction::triggered, this, &QWidget::close);
    updateRecentMenu();

    runMenu_ = menuBar()->addMenu(QString());
    runMenu_->setObjectName(QStringLiteral("runMenu"));
    runMenu_->addActions(runPanel_->runActions());
    runMenu_->addSeparator();
    runMenu_->addAction(runPanel_->emergencyAction());
    runMenu_->addAction(runPanel_->resetEmergencyAction());
    emergencyInputsAction_ = runMenu_->addAction(QString());
    emergencyInputsAction_->setObjectName(QStringLiteral("emergencyInputsAction"));
    connect(emergencyInputsAction_, &QAction::triggered, this, &MainWindow::editEmergencyInputs);
    // The shortcuts work whatever is shown: the actions belong to the window itself.
    addActions(runPanel_->runActions());
    connect(runPanel_->resetEmergencyAction(), &QAction::triggered, this,
            [this] { say(tr("E-STOP"), tr("E-STOP reset"), kNoticeMs); });

    viewMenu_ = menuBar()->addMenu(QString());
    viewMenu_->setObjectName(QStringLiteral("viewMenu"));
    for (QDockWidget* d : {taskDock_, recordDock_, mappingDock_, modelDock_, controllerDock_,
                           runDock_, chartsDock_, experimentsDock_, rigDock_, logDock_}) {
        viewMenu_->addAction(d->toggleViewAction());
    }
    viewMenu_->addSeparator();
    languageMenu_ = new LanguageMenu(languages_, viewMenu_);
    viewMenu_->addMenu(languageMenu_);

    helpMenu_ = menuBar()->addMenu(QString());
    helpMenu_->setObjectName(QStringLiteral("helpMenu"));
    guideAction_ = helpMenu_->addAction(QString());
    guideAction_->setObjectName(QStringLiteral("guideAction"));
    guideAction_->setShortcut(QKeySequence::HelpContents);  // F1
    connect(guideAction_, &QAction::triggered, this, &MainWindow::showGuide);
    shortcutsAction_ = helpMenu_->addAction(QString());
    shortcutsAction_->setObjectName(QStringLiteral("shortcutsAction"));
    shortcutsAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Slash));
    connect(shortcutsAction_, &QAction::triggered, this, &MainWindow::showShortcuts);
    addActions({guideAction_, shortcutsAction_});
    helpMenu_->addSeparator();
    aboutAction_ = helpMenu_->addAction(QString());
    aboutAction_->setObjectName(QStringLiteral("aboutAction"));
    aboutAction_->setMenuRole(QAction::AboutRole);
    connect(aboutAction_, &QAction::triggered, this, &MainWindow::showAbout);
}

void MainWindow::announceLanguage(const QString& code) {
    for (const UiLanguage& language : LanguageSwitcher::availableLanguages()) {
        if (language.code == code) {
            say(tr("Language"), tr("Interface language: %1").arg(language.nativeName),
                kStatusMessageMs);
        }
    }
}

void MainWindow::showAbout() {
    // Each sentence is translated on its own so translators never see the markup.
    const QString version = QCoreApplication::applicationVersion();
    const QString text =
        QStringLiteral("<h3>%1 %2</h3><p>%3</p><p>%4</p><p>%5</p>")
            .arg(kProductName, version.toHtmlEscaped(),
                 tr("Teaches a robot to repeat one demonstrated manoeuvre precisely.")
                     .toHtmlEscaped(),
                 tr("PRISCA (Policy Reasoning In State-and-Cost Adaptation) learns online from a "
                    "single demonstration and a coarse sign model of the dynamics, such as "
                    "\"steer left to turn left\".")
                     .toHtmlEscaped(),
                 tr("Built with Qt %1, running on Qt %2.")
                     .arg(QStringLiteral(QT_VERSION_STR), QString::fromLatin1(qVersion()))
                     .toHtmlEscaped());
    ModalDialog::about(this, tr("About PRISCA Lab"), text);
}

void MainWindow::showShortcuts() {
    QList<QPair<QString, QString>> rows;
    const auto add = [&rows](QAction* action) {
        if (action && !action->shortcut().isEmpty()) {
            QString name = action->text();
            name.remove(QLatin1Char('&'));
            name.remove(
                QRegularExpression(QStringLiteral("\\s*\\([^)]*\\)$")));  // "(F5)" shown beside
            rows.append({action->shortcut().toString(QKeySequence::NativeText), name});
        }
    };
    for (QAction* action : runPanel_->runActions()) {
        add(action);
    }
    rows.append({tr("Space or Esc"),
                 tr("E-STOP, in every window while something runs (a dialog, a menu, the guide "
                    "and the replay too; Shift+Space types a space then). With nothing running, "
                    "in the main window: Space types a space in a text field, Esc first closes "
                    "an open list")});
    for (const QKeySequence& key : guard_->extraKeys()) {
        rows.append({key.toString(QKeySequence::NativeText), tr("E-STOP (the foot switch's key)")});
    }
    for (const QString& button : gamepadStop_->buttons()) {
        rows.append({tr("Gamepad button %1").arg(button), tr("E-STOP")});
    }
    for (QAction* action : {openSessionAction_, saveSessionAction_, replayAction_, quitAction_,
                            guideAction_, shortcutsAction_}) {
        add(action);
    }
    rows.append({tr("Arrow keys or W A S D"),
                 tr("Drive while recording: throttle up/down, steer left/right")});
    rows.append({QKeySequence(QKeySequence::Copy).toString(QKeySequence::NativeText),
                 tr("Copy the selected lines of the message log")});
    QString html = QStringLiteral("<table cellspacing='0' cellpadding='4'>");
    for (const auto& [keys, what] : rows) {
        html += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                    .arg(keys.toHtmlEscaped(), what.toHtmlEscaped());
    }
    html += QStringLiteral("</table>");
    QMessageBox box(QMessageBox::NoIcon, tr("Keyboard shortcuts"), html, QMessageBox::Close, this);
    box.setObjectName(QStringLiteral("shortcutSheet"));
    box.setTextFormat(Qt::RichText);
    ModalDialog::exec(box);
}

namespace {

// Pictures wider than `room` [px] shown at that width, in proportion.
void fitPictures(QTextDocument& document, int room) {
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            if (!fragment.isValid() || !fragment.charFormat().isImageFormat()) {
                continue;
            }
            QTextImageFormat picture = fragment.charFormat().toImageFormat();
            const QImage image(QStringLiteral(":/docs/") + picture.name());
            if (image.isNull() || image.width() <= room) {
                continue;
            }
            picture.setWidth(room);
            picture.setHeight(static_cast<double>(image.height()) * room / image.width());
            QTextCursor cursor(&document);
            cursor.setPosition(fragment.position());
            cursor.setPosition(fragment.position() + fragment.length(), QTextCursor::KeepAnchor);
            cursor.setCharFormat(picture);
        }
    }
}

}  // namespace

void MainWindow::showGuide() {
    QFile file(QStringLiteral(":/docs/operator-guide.md"));
    if (!file.open(QIODevice::ReadOnly)) {
        warningBox(this, tr("Operator guide"),
                   tr("The operator guide is not built into this copy."));
        return;
    }
    auto* dialog = new QDialog(this);
    dialog->setObjectName(QStringLiteral("operatorGuide"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Operator guide"));
    auto* text = new QTextBrowser(dialog);
    text->setObjectName(QStringLiteral("guideText"));
    text->setOpenExternalLinks(true);
    text->setSearchPaths({QStringLiteral(":/docs")});  // its pictures, built in with it
    text->setMarkdown(QString::fromUtf8(file.readAll()));
    fitPictures(*text->document(), std::min(900, width() * 3 / 4) - 60);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(text);
    layout->addWidget(buttons);
    dialog->resize(std::min(900, width() * 3 / 4), std::min(700, height() * 9 / 10));
    dialog->show();
    ModalDialog::placeClear(dialog);  // never over the E-STOP button
}

ReplayDialog* MainWindow::openReplay(const QString& folder) {
    QString error;
    auto bundle = rig::TrialBundle::load(folder, &error);
    if (!bundle) {
        warningBox(this, tr("Replay a trial bundle"), error);
        return nullptr;
    }
    auto* dialog = new ReplayDialog(std::move(*bundle), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    ModalDialog::placeClear(dialog);  // inside the screen, never over the E-STOP button
    return dialog;
}

void MainWindow::applyEmergencyInputs() {
    const QSettings settings;
    QList<QKeySequence> keys;
    for (const QString& name : settings.value(QLatin1String(kEmergencyKeysKey)).toStringList()) {
        const QKeySequence key = QKeySequence::fromString(name, QKeySequence::PortableText);
        if (key.isEmpty()) {
            logMessage(
                this, tr("E-STOP"), MessageLevel::Warning,
                tr("The E-STOP key \"%1\" in the settings is no key; it is left out.").arg(name));
        } else {
            keys << key;
        }
    }
    guard_->setExtraKeys(keys);
    // The red button of the common pad layout, unless the operator chose otherwise.
    const QStringList buttons =
        settings.value(QLatin1String(kEmergencyPadKey), QStringList{QStringLiteral("b")})
            .toStringList();
    for (const QString& name : buttons) {
        if (!GamepadEmergencyButton::knownButton(name)) {
            logMessage(this, tr("E-STOP"), MessageLevel::Warning,
                       tr("The gamepad button \"%1\" in the settings is no button SDL knows; it is "
                          "left out.")
                           .arg(name));
        }
    }
    gamepadStop_->setButtons(buttons);
}

void MainWindow::editEmergencyInputs() {
    QDialog dialog(this);
    dialog.setObjectName(QStringLiteral("emergencyInputs"));
    dialog.setWindowTitle(tr("E-STOP inputs"));
    auto* intro = new QLabel(
        tr("Space, Esc and the red button are always E-STOP. A USB foot switch can be set to "
           "send a key (F13, Pause, ...): press that key here. A gamepad's button is E-STOP too, "
           "whatever the window shows."),
        &dialog);
    intro->setWordWrap(true);
    auto* key = new QKeySequenceEdit(&dialog);
    key->setObjectName(QStringLiteral("footSwitchKey"));
    if (!guard_->extraKeys().isEmpty()) {
        key->setKeySequence(guard_->extraKeys().first());
    }
    auto* clearKey = new QPushButton(tr("No key"), &dialog);
    connect(clearKey, &QPushButton::clicked, key, &QKeySequenceEdit::clear);
    auto* keyRow = new QHBoxLayout;
    keyRow->addWidget(key, 1);
    keyRow->addWidget(clearKey);
    auto* pad = new QComboBox(&dialog);
    pad->setObjectName(QStringLiteral("gamepadButton"));
    pad->addItem(tr("None"), QString());
    const QList<QPair<QString, QString>> buttons = {
        {QStringLiteral("b"), tr("B (the red one on most pads)")},
        {QStringLiteral("a"), tr("A")},
        {QStringLiteral("x"), tr("X")},
        {QStringLiteral("y"), tr("Y")},
        {QStringLiteral("back"), tr("Back / Select")},
        {QStringLiteral("start"), tr("Start")},
        {QStringLiteral("leftshoulder"), tr("Left shoulder")},
        {QStringLiteral("rightshoulder"), tr("Right shoulder")},
        {QStringLiteral("paddle1"), tr("Paddle 1")},
    };
    for (const auto& [name, label] : buttons) {
        pad->addItem(label, name);
    }
    pad->setCurrentIndex(std::max(0, pad->findData(gamepadStop_->buttons().value(0))));
    auto* padState = new QLabel(gamepadStop_->padFound() ? tr("A gamepad is connected.")
                                                         : tr("No gamepad is connected now."),
                                &dialog);
    auto* form = new QFormLayout;
    form->addRow(tr("Foot switch key:"), keyRow);
    form->addRow(tr("Gamepad button:"), pad);
    form->addRow(QString(), padState);
    auto* answer = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    connect(answer, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(answer, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    auto* layout = new QVBoxLayout(&dialog);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(answer);
    dialog.resize(520, dialog.sizeHint().height());
    if (ModalDialog::exec(dialog) != QDialog::Accepted) {
        return;
    }
    QSettings settings;
    const QKeySequence chosen =
        key->keySequence().isEmpty() ? QKeySequence() : QKeySequence(key->keySequence()[0]);
    settings.setValue(QLatin1String(kEmergencyKeysKey),
                      chosen.isEmpty() ? QStringList()
                                       : QStringList{chosen.toString(QKeySequence::PortableText)});
    const QString button = pad->currentData().toString();
    settings.setValue(QLatin1String(kEmergencyPadKey),
                      button.isEmpty() ? QStringList() : QStringList{button});
    applyEmergencyInputs();
    say(tr("E-STOP"),
        tr("E-STOP inputs: Space, Esc, the red button%1%2")
            .arg(chosen.isEmpty()
                     ? QString()
                     : tr(", the key %1").arg(chosen.toString(QKeySequence::NativeText)),
                 button.isEmpty() ? QString() : tr(", gamepad button %1").arg(button)),
        kStatusMessageMs);
}

}  // namespace prisca::app
