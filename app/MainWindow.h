#pragma once

#include <QMainWindow>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QPushButton;
class QTimer;
class QToolBar;

namespace prisca::app {

class ArenaView;
class ControllerPanel;
class EmergencyStop;
class EmergencyStopGuard;
class GamepadEmergencyButton;
class LabSession;
class LanguageMenu;
class LanguageSwitcher;
class ExperimentsPanel;
class LiveChartsPanel;
class MappingPanel;
class ModelPanel;
class MessageLog;
class MessageLogPanel;
class RecordPanel;
class RigPanel;
class RunThread;
class RunPanel;
class TaskPanel;

/// The application window: it arranges the panels (arena in the middle; task, controller and
/// run panels on the right; live charts below), owns the session and the run thread's handle,
/// and holds the menus. Each panel is its own class and talks to the session or the run
/// directly. Geometry and dock layout are restored from QSettings and saved on close.
class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    /// Where the window keeps what it saves by itself (a run's log, an experiment's table) when
    /// the operator quits and keeps what is done.
    static QString keptFolder();
    /// Opens a trial bundle in a replay window; a bad one gets a message box. The window, or
    /// null.
    class ReplayDialog* openReplay(const QString& folder);
    /// QSettings keys for the remembered window geometry and toolbar/dock state.
    static constexpr const char* kGeometryKey = "mainWindow/geometry";
    static constexpr const char* kStateKey = "mainWindow/state";

    /// `languages` must outlive the window. Opens on the target last used (the simulated
    /// slide-car the first time), ready to run.
    explicit MainWindow(LanguageSwitcher& languages, QWidget* parent = nullptr);
    ~MainWindow() override;

    LabSession& session() { return *session_; }
    MessageLog& messageLog() { return *log_; }
    RunThread& run() { return *run_; }
    /// The one E-STOP latch every job of the window follows.
    EmergencyStop& emergencyStop() { return *emergency_; }
    /// The keys and buttons that press it.
    EmergencyStopGuard& emergencyStopGuard() { return *guard_; }
    GamepadEmergencyButton& gamepadEmergencyButton() { return *gamepadStop_; }
    /// What would be lost or cut short by quitting now, one line each (empty: nothing).
    QStringList workInProgress() const;
    /// QSettings keys of E-STOP's extra inputs: a foot switch's keys (a list of key names as
    /// QKeySequence writes them, e.g. "F13", "Pause") and gamepad buttons (SDL's names).
    static constexpr const char* kEmergencyKeysKey = "estop/keys";
    static constexpr const char* kEmergencyPadKey = "estop/gamepadButtons";

    /// Opens a session file; a bad file gets a message box and changes nothing.
    bool openSession(const QString& path);
    /// Saves the session; a failure gets a message box.
    bool saveSession(const QString& path);

  protected:
    void changeEvent(QEvent* event) override;
    /// The wheel over a setting not clicked into scrolls its panel; a press on a separator means
    /// the operator sizes the docks. (E-STOP's keys: EmergencyStopGuard.)
    bool eventFilter(QObject* watched, QEvent* event) override;
    static void noWheelFocus(QWidget* field);
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

  private:
    void createPanels();
    void createMenus();
    void createToolBar();
    void shareSpace();
    /// The right column's height between the tab on top (what it needs to show whole, at least
    /// two fifths) and the Run panel (never less than its minimum).
    void shareRightColumn();
    void retranslateUi();
    void createStatusBar();
    /// Stops every job; with `keep`, what finished is saved (the run's log, the experiment's
    /// table) before the window closes.
    void stopWork(bool keep);
    /// Closes the window once a quit the operator asked for has nothing left to wait for.
    void quitWhenIdle();
    /// The status bar's job and E-STOP fields from the state now.
    void updateStatusFields();
    /// E-STOP's button and status field follow the latch.
    void showEmergencyState(bool latched);
    /// Run > E-STOP inputs...: the foot switch's key and the gamepad's button.
    void editEmergencyInputs();
    void applyEmergencyInputs();
    /// The quit the operator asked for, waiting for the work: shown until it happens or is
    /// cancelled.
    void showPendingQuit();
    void showAbout();
    /// Help > Keyboard shortcuts: every shortcut of the window, from the actions themselves.
    void showShortcuts();
    /// Help > Operator guide: docs/operator-guide.md, as built into the application.
    void showGuide();
    void announceLanguage(const QString& code);
    void showScene();
    /// Entries of theta for the session's method (what the theta chart plots).
    int parameterCount() const;
    void rememberRecent(const QString& path);
    void updateRecentMenu();

    /// A line in the status bar for `ms` (0: until replaced), and in the message log.
    void say(const QString& source, const QString& text, int ms);

    LanguageSwitcher& languages_;
    MessageLog* log_;  ///< first: the panels' first messages go to it
    LabSession* session_;
    RunThread* run_;
    EmergencyStop* emergency_;
    EmergencyStopGuard* guard_ = nullptr;
    GamepadEmergencyButton* gamepadStop_ = nullptr;
    ArenaView* arena_ = nullptr;
    TaskPanel* taskPanel_ = nullptr;
    ControllerPanel* controllerPanel_ = nullptr;
    RunPanel* runPanel_ = nullptr;
    RecordPanel* recordPanel_ = nullptr;
    MappingPanel* mappingPanel_ = nullptr;
    ModelPanel* modelPanel_ = nullptr;
    LiveChartsPanel* chartsPanel_ = nullptr;
    ExperimentsPanel* experimentsPanel_ = nullptr;
    RigPanel* rigPanel_ = nullptr;
    MessageLogPanel* logPanel_ = nullptr;
    QDockWidget* logDock_ = nullptr;
    QDockWidget* taskDock_ = nullptr;
    QDockWidget* controllerDock_ = nullptr;
    QDockWidget* runDock_ = nullptr;
    QDockWidget* recordDock_ = nullptr;
    QDockWidget* mappingDock_ = nullptr;
    QDockWidget* modelDock_ = nullptr;
    QDockWidget* chartsDock_ = nullptr;
    QDockWidget* experimentsDock_ = nullptr;
    QDockWidget* rigDock_ = nullptr;
    QMenu* fileMenu_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QMenu* runMenu_ = nullptr;
    LanguageMenu* languageMenu_ = nullptr;
    QMenu* helpMenu_ = nullptr;
    QAction* openSessionAction_ = nullptr;
    QAction* saveSessionAction_ = nullptr;
    QAction* quitAction_ = nullptr;
    QAction* replayAction_ = nullptr;
    QAction* emergencyInputsAction_ = nullptr;
    QToolBar* runToolBar_ = nullptr;
    bool stateRestored_ = false;  ///< the operator's own dock layout was restored
    bool laidOut_ = false;
    bool operatorSizedDocks_ = false;  ///< the operator dragged a separator: keep their sizes
    QPushButton* emergencyButton_ = nullptr;
    QAction* aboutAction_ = nullptr;
    QAction* shortcutsAction_ = nullptr;
    QAction* guideAction_ = nullptr;
    QLabel* versionLabel_;
    QLabel* jobStatus_ = nullptr;
    QLabel* linkStatus_ = nullptr;
    QLabel* cameraStatus_ = nullptr;
    QLabel* emergencyStatus_ = nullptr;
    QTimer* statusTimer_ = nullptr;
    bool emergencyShownLatched_ = false;
    enum class QuitPlan { None, Finish, Keep };
    QuitPlan quitPlan_ = QuitPlan::None;
    QWidget* pendingQuit_ = nullptr;  ///< in the status bar while a quit waits
    QLabel* pendingQuitText_ = nullptr;
    class QPushButton* cancelQuit_ = nullptr;
    bool quitConfirmed_ = false;  ///< the operator answered; close without asking again
    QString sessionPath_;
};

}  // namespace prisca::app
