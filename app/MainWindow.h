#pragma once

#include <QMainWindow>

class QAction;
class QLabel;
class QMenu;

namespace prisca::app {

class LanguageMenu;
class LanguageSwitcher;
class WelcomePanel;

/// The application window: menus, status bar and the central panel. It only arranges panels;
/// each panel is its own class. Geometry and dock state are restored from QSettings on
/// construction and saved when the window closes.
class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    /// QSettings keys for the remembered window geometry and toolbar/dock state.
    static constexpr const char* kGeometryKey = "mainWindow/geometry";
    static constexpr const char* kStateKey = "mainWindow/state";

    /// `languages` must outlive the window.
    explicit MainWindow(LanguageSwitcher& languages, QWidget* parent = nullptr);

  protected:
    void changeEvent(QEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

  private:
    void createMenus();
    void retranslateUi();
    void showAbout();
    void announceLanguage(const QString& code);

    LanguageSwitcher& languages_;
    WelcomePanel* welcomePanel_;
    QMenu* fileMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    LanguageMenu* languageMenu_ = nullptr;
    QMenu* helpMenu_ = nullptr;
    QAction* quitAction_ = nullptr;
    QAction* aboutAction_ = nullptr;
    QLabel* versionLabel_;
};

}  // namespace prisca::app
