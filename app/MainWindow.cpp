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
    log_->captureQtMessages();  // the workers' messages (prisca.* categories) in the log
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
    const core::FeatureMap& features =
        sim::MethodCatalog::featuresOf(session_->profile(), session_->method());
    return features.featureCount() * features.channelCount();
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
        logMessage(this, tr("Session"), MessageLevel::Info,
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
    logMessage(this, source, MessageLevel::Info, text);
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

}  // namespace prisca::app
