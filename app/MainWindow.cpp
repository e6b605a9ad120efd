#include "app/MainWindow.h"

#include "app/ModalDialog.h"

#include "app/ArenaView.h"
#include "app/BundleChooser.h"
#include "app/ControllerPanel.h"
#include "app/EmergencyStop.h"
#include "app/EmergencyStopGuard.h"
#include "app/ExperimentsPanel.h"
#include "app/GamepadEmergencyButton.h"
#include "app/LabSession.h"
#include "app/LanguageMenu.h"
#include "app/LanguageSwitcher.h"
#include "app/LiveChartsPanel.h"
#include "app/MappingPanel.h"
#include "app/MessageLog.h"
#include "app/MessageLogPanel.h"
#include "app/ModelPanel.h"
#include "app/RecordPanel.h"
#include "app/ReplayDialog.h"
#include "app/RunPanel.h"
#include "app/RunThread.h"
#include "app/TaskPanel.h"
#include "app/rig/RigPanel.h"
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
#include <QTextBrowser>
#include <QTextEdit>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace prisca::app {

namespace {

// The product name is a proper noun and stays untranslated in every language.
const QString kProductName = QStringLiteral("PRISCA Lab");
const QSize kDefaultSize(1280, 800);  // px, used until the operator has sized the window
const QSize kFrameAllowance(16, 48);  // px, a window manager's borders and title bar
constexpr int kStatusMessageMs = 4000;
constexpr int kNoticeMs = 15000;  // what the operator must read, e.g. replaced parameters
constexpr int kMaxRecent = 8;
const char* const kRecentKey = "session/recent";
const char* const kLastSessionKey = "session/last";  // the session as it was at the last close
// The operator has dragged a separator between docks (then their sizes are theirs).
const char* const kOperatorSizedKey = "mainWindow/operatorSizedDocks";

QDockWidget* dock(QMainWindow* window, const QString& name, QWidget* panel, Qt::DockWidgetArea area,
                  bool scrolls = true) {
    auto* d = new QDockWidget(window);
    d->setObjectName(name);  // saveState() needs the name
    if (scrolls) {
        // Panels scroll rather than force the window taller than a laptop screen, or take the
        // height of every panel tabbed with them (a tab group is as tall as its tallest).
        auto* scroll = new QScrollArea(d);
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidget(panel);
        d->setWidget(scroll);
    } else {
        d->setWidget(panel);
    }
    window->addDockWidget(area, d);
    return d;
}

}  // namespace

MainWindow::MainWindow(LanguageSwitcher& languages, QWidget* parent)
    : QMainWindow(parent),
      languages_(languages),
      log_(new MessageLog(this)),
      session_(new LabSession(this)),
      run_(new RunThread(this)),
      emergency_(new EmergencyStop(this)),
      versionLabel_(new QLabel(this)) {
    setObjectName(QStringLiteral("mainWindow"));
    setWindowTitle(kProductName);
    MessageLog::captureQtMessages();  // the workers' messages (prisca.* categories) in the log
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    // The right-hand panels run the full height; the charts sit under the arena only.
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);

    const QSettings settings;
    QString plant = settings.value(QStringLiteral("task/plant")).toString();
    if (!sim::PlantCatalog::names().contains(plant)) {
        plant = QStringLiteral("slidecar");
    }
    session_->setPlant(plant);
    // The session as the operator left it (kept in the settings on close); a stale or damaged
    // copy is ignored, never an obstacle to starting.
    const QByteArray last = settings.value(QLatin1String(kLastSessionKey)).toByteArray();
    if (!last.isEmpty()) {
        QString ignored;
        session_->fromJson(last, tr("the last session"), &ignored);
    }

    createPanels();
    // The panels' first lines are their initial state, not news: the log starts with the
    // messages of before the restart instead.
    log_->clear();
    log_->append(session_->messages());
    experimentsPanel_->restoreKeptResult();  // the last experiment's result, shown again
    createMenus();
    createToolBar();
    for (QWidget* field : findChildren<QWidget*>()) {
        noWheelFocus(field);
    }
    qApp->installEventFilter(this);
    // Installed after the window's own filter, so it reads every key first.
    guard_ = new EmergencyStopGuard(
        this, emergencyButton_, [this] { return !workInProgress().isEmpty(); },
        [this](const QString& by) { emergency_->engage(by); }, this);
    gamepadStop_ = new GamepadEmergencyButton(this);
    connect(gamepadStop_, &GamepadEmergencyButton::pressed, emergency_, &EmergencyStop::engage);
    applyEmergencyInputs();
    createStatusBar();
    connect(&languages_, &LanguageSwitcher::languageChanged, this, &MainWindow::announceLanguage);
    connect(run_, &RunThread::progress, this,
            [this](const QString& text) { statusBar()->showMessage(text); });
    connect(run_, &RunThread::failed, this,
            [this](const QString& text) { warningBox(this, tr("Run"), text); });
    retranslateUi();
    if (!session_->notice().isEmpty()) {
        say(tr("Session"), session_->notice(), kNoticeMs);  // the last session's
    }
    showScene();

    if (!restoreGeometry(settings.value(QLatin1String(kGeometryKey)).toByteArray())) {
        // Inside the screen's available area with room for the title bar, centred: on a
        // 1280 x 800 screen the status bar is then on screen too.
        const QRect available = screen() ? screen()->availableGeometry() : QRect(0, 0, 1280, 800);
        resize(kDefaultSize.boundedTo(available.size() - kFrameAllowance));
        // Centred; on a screen narrower than the panels allow, from its left edge.
        move(available.left() + std::max(0, (available.width() - width()) / 2),
             available.top() + std::max(0, (available.height() - height()) / 2));
    }
    stateRestored_ = restoreState(settings.value(QLatin1String(kStateKey)).toByteArray());
    operatorSizedDocks_ = settings.value(QLatin1String(kOperatorSizedKey), false).toBool();
}

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    if (!stateRestored_ && !laidOut_) {
        laidOut_ = true;
        // Once the window has its size: the layout an operator left is kept; a first start
        // shares the space out by proportion instead of by the panels' size hints.
        QTimer::singleShot(0, this, &MainWindow::shareSpace);
    }
}

void MainWindow::resizeEvent(QResizeEvent* event) {
    QMainWindow::resizeEvent(event);
    // Until the operator sizes the panels (or a saved layout was restored), the space is shared
    // out again when the window changes size, e.g. when it is maximised.
    if (laidOut_ && !stateRestored_ && !operatorSizedDocks_) {
        QTimer::singleShot(0, this, &MainWindow::shareSpace);
    }
}

void MainWindow::shareSpace() {
    // The side panels as wide as their widest content needs (no sideways scrolling), about
    // a third of the window; the arena over the charts with the larger share of the height.
    int needed = 0;
    for (QDockWidget* d :
         {taskDock_, recordDock_, mappingDock_, modelDock_, controllerDock_, runDock_}) {
        if (auto* scroll = qobject_cast<QScrollArea*>(d->widget())) {
            needed = std::max(needed, scroll->widget()->minimumSizeHint().width() +
                                          scroll->verticalScrollBar()->sizeHint().width() + 8);
        }
    }
    const int side = std::clamp(width() * 3 / 10, needed, std::max(needed, width() / 2));
    resizeDocks({taskDock_, runDock_}, {side, side}, Qt::Horizontal);
    resizeDocks({chartsDock_}, {height() * 2 / 5}, Qt::Vertical);
    shareRightColumn();
}

void MainWindow::shareRightColumn() {
    // The tab shown on top of the right column gets the height it needs to show whole (the
    // Mapping panel's Fit B_v and fit table), at least two fifths; the Run panel the rest, never
    // less than its minimum (its settings and the newest result in view).
    QDockWidget* top = nullptr;
    for (QDockWidget* d : {taskDock_, recordDock_, mappingDock_, modelDock_, controllerDock_}) {
        // The tab on top: the only one of the group on screen.
        if (d->isVisible() && !d->isFloating() && !d->visibleRegion().isEmpty()) {
            top = d;
        }
    }
    if (!top || runDock_->isFloating() || !runDock_->isVisible()) {
        return;
    }
    const int column = top->height() + runDock_->height();
    int needed = column * 2 / 5;
    if (auto* scroll = qobject_cast<QScrollArea*>(top->widget())) {
        const int chrome = top->height() - scroll->viewport()->height();
        needed = std::max(needed, scroll->widget()->sizeHint().height() + std::max(chrome, 0));
    }
    // What the Run panel leaves (it keeps its minimum: its settings and the newest result);
    // a panel that cannot show whole anyway (the Controller's long list) scrolls in its share.
    const int separator = style()->pixelMetric(QStyle::PM_DockWidgetSeparatorExtent, nullptr, this);
    const int most = column - runDock_->minimumSizeHint().height() - separator;
    const int topHeight = needed <= column * 7 / 10
                              ? std::max(std::min(needed, most), column * 2 / 5)
                              : column * 2 / 5;
    // (The sizes are weights of what the area has, its tab bar and separator included: the top
    // is asked a little more, which the Run panel's minimum bounds.)
    const int slack = fontMetrics().height() * 2;
    resizeDocks({top, runDock_}, {topHeight + slack, std::max(1, column - topHeight - slack)},
                Qt::Vertical);
}

MainWindow::~MainWindow() {
    qApp->removeEventFilter(this);
}

namespace {
// A setting the wheel would change: a combo box or a spin box.
bool isSetting(const QObject* widget) {
    return qobject_cast<const QComboBox*>(widget) || qobject_cast<const QAbstractSpinBox*>(widget);
}
}  // namespace

void MainWindow::noWheelFocus(QWidget* field) {
    // Settings take the focus from a click or Tab, not from the wheel passing over them: the
    // wheel then scrolls the panel instead of changing what it passes (see eventFilter).
    if (isSetting(field) && field->focusPolicy() == Qt::WheelFocus) {
        field->setFocusPolicy(Qt::StrongFocus);
    }
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::MouseButtonPress && watched == this &&
        (cursor().shape() == Qt::SplitVCursor || cursor().shape() == Qt::SplitHCursor)) {
        // A press on the window itself, not on a panel: a separator between docks. From now on
        // the operator sizes the panels.
        if (!operatorSizedDocks_) {
            operatorSizedDocks_ = true;
            QSettings().setValue(QLatin1String(kOperatorSizedKey), true);
        }
        return false;
    }
    if (event->type() == QEvent::Polish) {
        noWheelFocus(qobject_cast<QWidget*>(watched));  // a setting made later (a dialog's)
        return false;
    }
    if (event->type() == QEvent::Wheel) {
        // The wheel over a setting the operator has not clicked into scrolls the panel around it
        // instead of changing the setting (a protocol or a gain changed by scrolling past it).
        auto* field = qobject_cast<QWidget*>(watched);
        if (isSetting(field) && !field->hasFocus()) {
            event->ignore();  // not the setting's: the application passes it on to the parents
            return true;
        }
        return false;
    }
    return false;
}

void MainWindow::createPanels() {
    arena_ = new ArenaView(this);
    setCentralWidget(arena_);
    taskPanel_ = new TaskPanel(*session_, this);
    controllerPanel_ = new ControllerPanel(*session_, this);
    runPanel_ = new RunPanel(*session_, *run_, *emergency_, this);
    recordPanel_ = new RecordPanel(*session_, *emergency_, this);
    mappingPanel_ = new MappingPanel(*session_, this);
    modelPanel_ = new ModelPanel(*session_, *emergency_, this);
    chartsPanel_ = new LiveChartsPanel(this);
    experimentsPanel_ = new ExperimentsPanel(*session_, *emergency_, this);
    rigPanel_ = new RigPanel(*session_, *emergency_, this);
    connect(rigPanel_, &RigPanel::replayRequested, this,
            [this](const QString& folder) { openReplay(folder); });
    taskDock_ = dock(this, QStringLiteral("taskDock"), taskPanel_, Qt::RightDockWidgetArea);
    recordDock_ = dock(this, QStringLiteral("recordDock"), recordPanel_, Qt::RightDockWidgetArea);
    mappingDock_ =
        dock(this, QStringLiteral("mappingDock"), mappingPanel_, Qt::RightDockWidgetArea);
    modelDock_ = dock(this, QStringLiteral("modelDock"), modelPanel_, Qt::RightDockWidgetArea);
    controllerDock_ =
        dock(this, QStringLiteral("controllerDock"), controllerPanel_, Qt::RightDockWidgetArea);
    // The run panel fits its dock without scrolling: its results table takes what is left.
    runDock_ = dock(this, QStringLiteral("runDock"), runPanel_, Qt::RightDockWidgetArea, false);
    // The charts fill what they get (they have no natural height to scroll to).
    chartsDock_ =
        dock(this, QStringLiteral("chartsDock"), chartsPanel_, Qt::BottomDockWidgetArea, false);
    // The experiments' table and figure shrink with the dock (the table scrolls its rows).
    experimentsDock_ = dock(this, QStringLiteral("experimentsDock"), experimentsPanel_,
                            Qt::BottomDockWidgetArea, false);
    tabifyDockWidget(chartsDock_, experimentsDock_);
    // The rig's pages scroll inside the panel; its buttons stay in view.
    rigDock_ = dock(this, QStringLiteral("rigDock"), rigPanel_, Qt::BottomDockWidgetArea, false);
    tabifyDockWidget(experimentsDock_, rigDock_);
    logPanel_ = new MessageLogPanel(*log_, this);
    logDock_ = dock(this, QStringLiteral("logDock"), logPanel_, Qt::BottomDockWidgetArea, false);
    tabifyDockWidget(rigDock_, logDock_);
    chartsDock_->raise();
    tabifyDockWidget(taskDock_, recordDock_);
    tabifyDockWidget(recordDock_, mappingDock_);
    tabifyDockWidget(mappingDock_, modelDock_);
    tabifyDockWidget(modelDock_, controllerDock_);
    taskDock_->raise();
    // The tab the operator brings up gets the room it needs (until they size the docks).
    for (QDockWidget* d : {taskDock_, recordDock_, mappingDock_, modelDock_, controllerDock_}) {
        connect(d, &QDockWidget::visibilityChanged, this, [this](bool visible) {
            if (visible && isVisible() && !operatorSizedDocks_) {
                QTimer::singleShot(0, this, &MainWindow::shareRightColumn);
            }
        });
    }

    connect(session_, &LabSession::demonstrationChanged, this, &MainWindow::showScene);
    connect(session_, &LabSession::plantChanged, this, &MainWindow::showScene);
    // Another method may have another theta: its chart follows (only then, so a parameter
    // changed between runs does not clear the charts).
    connect(session_, &LabSession::controllerChanged, this, [this] {
        if (chartsPanel_->parameterCount() != parameterCount()) {
            chartsPanel_->setPlant(session_->profile().info, parameterCount());
        }
    });
    connect(runPanel_, &RunPanel::runStarting, this, [this] {
        chartsPanel_->setCaption(
            tr("%1 on the %2; demonstration: %3")
                .arg(sim::MethodCatalog::get(session_->method()).label,
                     QCoreApplication::translate(
                         "PlantCatalog", sim::PlantCatalog::get(session_->plant()).displayName),
                     session_->demonstrationDescription()));
        arena_->clearTrails();
        chartsPanel_->clear();
    });
    connect(run_, &RunThread::samplesReady, arena_, &ArenaView::addSamples);
    connect(recordPanel_, &RecordPanel::recordingStarted, arena_, &ArenaView::clearTrails);
    connect(recordPanel_, &RecordPanel::samplesReady, arena_, &ArenaView::addSamples);
    // The rig's car where the camera sees it, in the arena too.
    connect(rigPanel_, &RigPanel::carTracked, arena_,
            [this](const Eigen::VectorXd& state) { arena_->showState(state, Eigen::VectorXd()); });
    connect(run_, &RunThread::samplesReady, chartsPanel_, &LiveChartsPanel::addSamples);
}

void MainWindow::showScene() {
    const sim::MethodTuning& profile = session_->profile();
    arena_->setScene(profile.info, session_->demonstration());
    chartsPanel_->setPlant(profile.info, parameterCount());
}

int MainWindow::parameterCount() const {
    // theta's shape is the method's: PRISCA may have features of its own (PGSD has the shared).
    const core::FeatureMap& features = session_->profile().featuresOf(session_->method());
    return features.featureCount() * features.channelCount();
}

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
            job = tr("Job: training before the run");
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

bool MainWindow::openSession(const QString& path) {
    QString error;
    if (!session_->open(path, &error)) {
        warningBox(this, tr("Open session"),
                   tr("The session could not be opened.\n\n%1").arg(error));
        return false;
    }
    sessionPath_ = path;
    rememberRecent(path);
    const QString file = QFileInfo(path).fileName();
    if (!session_->messages().isEmpty()) {
        logMessage(tr("Session"), MessageLevel::Info,
                   tr("The messages saved with %1 follow (%2 lines).")
                       .arg(file)
                       .arg(session_->messages().size()));
        log_->append(session_->messages());
    }
    const QString& notice = session_->notice();
    if (notice.isEmpty()) {
        say(tr("Session"), tr("Opened %1").arg(file), kStatusMessageMs);
    } else {
        say(tr("Session"), tr("Opened %1. %2").arg(file, notice), kNoticeMs);
    }
    return true;
}

bool MainWindow::saveSession(const QString& path) {
    QString error;
    session_->setMessages(log_->toJson());
    if (!session_->save(path, &error)) {
        warningBox(this, tr("Save session"), error);
        return false;
    }
    sessionPath_ = path;
    rememberRecent(path);
    say(tr("Session"), tr("Saved %1").arg(QFileInfo(path).fileName()), kStatusMessageMs);
    return true;
}

void MainWindow::say(const QString& source, const QString& text, int ms) {
    statusBar()->showMessage(text, ms);
    logMessage(source, MessageLevel::Info, text);
}

void MainWindow::rememberRecent(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(QLatin1String(kRecentKey)).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    while (recent.size() > kMaxRecent) {
        recent.removeLast();
    }
    settings.setValue(QLatin1String(kRecentKey), recent);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
    recentMenu_->clear();
    const QStringList recent = QSettings().value(QLatin1String(kRecentKey)).toStringList();
    for (const QString& path : recent) {
        QAction* action = recentMenu_->addAction(QFileInfo(path).fileName());
        action->setToolTip(path);
        connect(action, &QAction::triggered, this, [this, path] { openSession(path); });
    }
    recentMenu_->setEnabled(!recent.isEmpty());
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslateUi() {
    fileMenu_->setTitle(tr("&File"));
    openSessionAction_->setText(tr("&Open session..."));
    recentMenu_->setTitle(tr("Open &recent"));
    saveSessionAction_->setText(tr("&Save session as..."));
    quitAction_->setText(tr("&Quit"));
    replayAction_->setText(tr("&Replay a trial bundle..."));
    emergencyInputsAction_->setText(tr("E-STOP &inputs..."));
    emergencyInputsAction_->setStatusTip(
        tr("A foot switch's key and a gamepad button that are E-STOP too"));
    if (pendingQuit_) {
        showPendingQuit();
    }
    quitAction_->setStatusTip(tr("Close the window and leave PRISCA Lab"));
    runMenu_->setTitle(tr("&Run"));
    runToolBar_->setWindowTitle(tr("Run"));
    viewMenu_->setTitle(tr("&View"));
    taskDock_->setWindowTitle(tr("Task"));
    recordDock_->setWindowTitle(tr("Record"));
    mappingDock_->setWindowTitle(tr("Mapping"));
    modelDock_->setWindowTitle(tr("Model"));
    controllerDock_->setWindowTitle(tr("Controller"));
    runDock_->setWindowTitle(tr("Run"));
    chartsDock_->setWindowTitle(tr("Live charts"));
    experimentsDock_->setWindowTitle(tr("Experiments"));
    rigDock_->setWindowTitle(tr("Rig"));
    logDock_->setWindowTitle(tr("Messages"));
    helpMenu_->setTitle(tr("&Help"));
    aboutAction_->setText(tr("&About PRISCA Lab"));
    guideAction_->setText(tr("Operator &guide"));
    shortcutsAction_->setText(tr("&Keyboard shortcuts"));
    aboutAction_->setStatusTip(tr("Show the version and what PRISCA Lab does"));
    const QString version = QCoreApplication::applicationVersion();
    versionLabel_->setText(version.isEmpty() ? QString() : tr("Version %1").arg(version));
    if (jobStatus_) {
        updateStatusFields();
        showEmergencyState(emergency_->isLatched());
    }
}

QStringList MainWindow::workInProgress() const {
    QStringList work;
    const RunPhase phase = run_->phase();
    if (phase == RunPhase::Running || phase == RunPhase::Paused || phase == RunPhase::Training) {
        work << tr("a simulated run");
    }
    if (experimentsPanel_->isRunning()) {
        work << tr("an experiment (%1 of %2 done)")
                    .arg(experimentsPanel_->progressDone())
                    .arg(experimentsPanel_->progressTotal());
    }
    if (rigPanel_->isRunning()) {
        work << tr("a trial on the rig");
    }
    if (rigPanel_->measuringLatency()) {
        work << tr("a latency measurement on the rig");
    }
    if (rigPanel_->isDriving() || recordPanel_->isRecording()) {
        work << tr("a recording");
    }
    if (modelPanel_->isRunning()) {
        work << tr("an identification of the car's model");
    }
    return work;
}

QString MainWindow::keptFolder() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
        .filePath(QStringLiteral("kept"));
}

void MainWindow::stopWork(bool keep) {
    run_->stop();
    experimentsPanel_->cancel();  // what finished comes back as a partial result
    if (rigPanel_->isRunning()) {
        rigPanel_->stopTrial();  // failsafe; its bundle is written as it is
    }
    if (rigPanel_->isDriving()) {
        rigPanel_->stopDriving();  // the take is written and becomes the demonstration
    }
    if (recordPanel_->isRecording()) {
        recordPanel_->stopRecording();
    }
    modelPanel_->cancel();  // nothing of it is kept: the session keeps the model it had
    logMessage(tr("Quit"), MessageLevel::Info,
               keep ? tr("Quitting: the work under way is stopped and what is done kept.")
                    : tr("Quitting: the work under way is discarded."));
}

void MainWindow::quitWhenIdle() {
    if (quitPlan_ == QuitPlan::None || !workInProgress().isEmpty()) {
        return;
    }
    const QuitPlan plan = quitPlan_;
    quitPlan_ = QuitPlan::None;
    showPendingQuit();
    if (plan == QuitPlan::Keep || plan == QuitPlan::Finish) {
        // What finished, where the operator can find it after the restart.
        const QString stamp =
            QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"));
        QDir().mkpath(keptFolder());
        QString error;
        const std::shared_ptr<const core::RunLog> log = run_->lastRunLog();
        if (log && log->rows.rows() > 0) {
            const QString path =
                QDir(keptFolder()).filePath(QStringLiteral("run-%1.csv").arg(stamp));
            if (runPanel_->exportRunLog(path, &error)) {
                logMessage(tr("Quit"), MessageLevel::Info,
                           tr("The run's log was kept in %1").arg(path));
            } else {
                logMessage(tr("Quit"), MessageLevel::Error, error);
            }
        }
        if (!experimentsPanel_->tableText(core::TableFormat::Markdown).isEmpty()) {
            const QString path =
                QDir(keptFolder()).filePath(QStringLiteral("experiment-%1.md").arg(stamp));
            if (experimentsPanel_->exportTable(path, &error)) {
                logMessage(tr("Quit"), MessageLevel::Info,
                           tr("The experiment's table was kept in %1").arg(path));
            } else {
                logMessage(tr("Quit"), MessageLevel::Error, error);
            }
        }
    }
    quitConfirmed_ = true;
    close();
}

void MainWindow::closeEvent(QCloseEvent* event) {
    const QStringList work = workInProgress();
    if (!quitConfirmed_ && !work.isEmpty()) {
        QMessageBox box(QMessageBox::Question, tr("Quit PRISCA Lab"),
                        tr("Work is under way:\n\n%1\n\nWhat should happen to it?")
                            .arg(QStringLiteral("- ") + work.join(QStringLiteral("\n- "))),
                        QMessageBox::NoButton, this);
        box.setObjectName(QStringLiteral("quitQuestion"));
        box.setInformativeText(
            tr("Finish: quit once it is done. Keep: stop now, save what is done (the run's log, "
               "the experiment's table, the recording) and quit. Discard: stop now and quit."));
        QPushButton* finish = box.addButton(tr("Finish, then quit"), QMessageBox::AcceptRole);
        QPushButton* keep = box.addButton(tr("Keep what is done, quit"), QMessageBox::AcceptRole);
        QPushButton* discard = box.addButton(tr("Discard, quit"), QMessageBox::DestructiveRole);
        QPushButton* cancel = box.addButton(QMessageBox::Cancel);
        finish->setObjectName(QStringLiteral("quitFinish"));
        keep->setObjectName(QStringLiteral("quitKeep"));
        discard->setObjectName(QStringLiteral("quitDiscard"));
        cancel->setObjectName(QStringLiteral("quitCancel"));
        box.setDefaultButton(cancel);
        box.setEscapeButton(cancel);
        ModalDialog::exec(box);
        if (box.clickedButton() == finish && !workInProgress().isEmpty()) {
            quitPlan_ = QuitPlan::Finish;
            showPendingQuit();
            say(tr("Quit"), tr("PRISCA Lab quits once the work under way is done."), kNoticeMs);
            event->ignore();
            return;
        }
        if (box.clickedButton() == keep || box.clickedButton() == finish) {
            // (Finish with the work already done, E-STOP meanwhile say: what is done is kept.)
            quitPlan_ = QuitPlan::Keep;
            showPendingQuit();
            stopWork(true);
            event->ignore();
            QTimer::singleShot(0, this, &MainWindow::quitWhenIdle);  // may be idle already
            return;
        }
        if (box.clickedButton() != discard) {
            quitPlan_ = QuitPlan::None;
            event->ignore();
            return;
        }
        stopWork(false);
    }
    run_->stop();
    QSettings settings;
    session_->setMessages(log_->toJson());
    settings.setValue(QLatin1String(kLastSessionKey), session_->toJson());
    settings.setValue(QLatin1String(kGeometryKey), saveGeometry());
    settings.setValue(QLatin1String(kStateKey), saveState());
    QMainWindow::closeEvent(event);
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
    text->setMarkdown(QString::fromUtf8(file.readAll()));
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
                tr("E-STOP"), MessageLevel::Warning,
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
            logMessage(tr("E-STOP"), MessageLevel::Warning,
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
