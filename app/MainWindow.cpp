#include "app/MainWindow.h"

#include "app/LanguageMenu.h"
#include "app/LanguageSwitcher.h"
#include "app/WelcomePanel.h"

#include <QAction>
#include <QCloseEvent>
#include <QCoreApplication>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace prisca::app {

namespace {

// The product name is a proper noun and stays untranslated in every language.
const QString kProductName = QStringLiteral("PRISCA Lab");
const QSize kDefaultSize(1024, 700);  // px, used until the operator has sized the window
constexpr int kStatusMessageMs = 4000;

}  // namespace

MainWindow::MainWindow(LanguageSwitcher& languages, QWidget* parent)
    : QMainWindow(parent),
      languages_(languages),
      welcomePanel_(new WelcomePanel(this)),
      versionLabel_(new QLabel(this)) {
    setObjectName(QStringLiteral("mainWindow"));
    setWindowTitle(kProductName);
    setCentralWidget(welcomePanel_);
    createMenus();
    statusBar()->addPermanentWidget(versionLabel_);
    connect(&languages_, &LanguageSwitcher::languageChanged, this, &MainWindow::announceLanguage);
    retranslateUi();

    const QSettings settings;
    if (!restoreGeometry(settings.value(QLatin1String(kGeometryKey)).toByteArray())) {
        resize(kDefaultSize);
    }
    restoreState(settings.value(QLatin1String(kStateKey)).toByteArray());
}

void MainWindow::createMenus() {
    fileMenu_ = menuBar()->addMenu(QString());
    fileMenu_->setObjectName(QStringLiteral("fileMenu"));
    quitAction_ = fileMenu_->addAction(QString());
    quitAction_->setObjectName(QStringLiteral("quitAction"));
    // Ctrl+Q on every platform, not the platform's Quit key (which is empty on Windows).
    quitAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));
    quitAction_->setMenuRole(QAction::QuitRole);
    // Closing the window (not QCoreApplication::quit) so closeEvent saves the geometry.
    connect(quitAction_, &QAction::triggered, this, &QWidget::close);

    viewMenu_ = menuBar()->addMenu(QString());
    viewMenu_->setObjectName(QStringLiteral("viewMenu"));
    languageMenu_ = new LanguageMenu(languages_, viewMenu_);
    viewMenu_->addMenu(languageMenu_);

    helpMenu_ = menuBar()->addMenu(QString());
    helpMenu_->setObjectName(QStringLiteral("helpMenu"));
    aboutAction_ = helpMenu_->addAction(QString());
    aboutAction_->setObjectName(QStringLiteral("aboutAction"));
    aboutAction_->setMenuRole(QAction::AboutRole);
    connect(aboutAction_, &QAction::triggered, this, &MainWindow::showAbout);
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslateUi() {
    fileMenu_->setTitle(tr("&File"));
    quitAction_->setText(tr("&Quit"));
    quitAction_->setStatusTip(tr("Close the window and leave PRISCA Lab"));
    viewMenu_->setTitle(tr("&View"));
    helpMenu_->setTitle(tr("&Help"));
    aboutAction_->setText(tr("&About PRISCA Lab"));
    aboutAction_->setStatusTip(tr("Show the version and what PRISCA Lab does"));
    const QString version = QCoreApplication::applicationVersion();
    versionLabel_->setText(version.isEmpty() ? QString() : tr("Version %1").arg(version));
}

void MainWindow::closeEvent(QCloseEvent* event) {
    QSettings settings;
    settings.setValue(QLatin1String(kGeometryKey), saveGeometry());
    settings.setValue(QLatin1String(kStateKey), saveState());
    QMainWindow::closeEvent(event);
}

void MainWindow::announceLanguage(const QString& code) {
    for (const UiLanguage& language : LanguageSwitcher::availableLanguages()) {
        if (language.code == code) {
            statusBar()->showMessage(tr("Interface language: %1").arg(language.nativeName),
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
    QMessageBox::about(this, tr("About PRISCA Lab"), text);
}

}  // namespace prisca::app
