// The main window driven offscreen: title, menus, run-time language switch, remembered settings,
// clean close.
#include "app/LabSession.h"
#include "app/LanguageSwitcher.h"
#include "app/MainWindow.h"
#include "app/widgets/ModalDialog.h"
#include "app/workers/ExperimentArchive.h"

#include <QtTest/qtestspontaneevent.h>
#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QWheelEvent>
#include <QtTest>

using prisca::app::LanguageSwitcher;
using prisca::app::MainWindow;

namespace {

const QString kChineseFileMenu = QStringLiteral("檔案(&F)");

QMenu* menu(const QWidget& window, const char* name) {
    return window.findChild<QMenu*>(QLatin1String(name));
}

QAction* action(const QWidget& window, const QString& name) {
    return window.findChild<QAction*>(name);
}

QStringList menuBarTitles(const QMainWindow& window) {
    QStringList titles;
    for (const QAction* entry : window.menuBar()->actions()) {
        titles << entry->text();
    }
    return titles;
}

}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase();
    void init();

    void construct_showsTitleMenusStatusBarAndPanels();
    void languageMenu_switchesFileMenuToChineseAndBack();
    void languageChoice_isRememberedForTheNextStart();
    void geometry_isRememberedForTheNextStart();
    void aboutAction_showsWhatTheAppIs();
    void quitShortcut_closesWindowAndEndsTheEventLoopWithZero();
    void wheel_overAnUnfocusedSettingScrollsAndLeavesIt();
};

void TestMainWindow::initTestCase() {
    // Test mode keeps the operator's real settings out of reach.
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("PRISCA Lab Tests"));
    QCoreApplication::setApplicationName(QStringLiteral("test_main_window"));
    QCoreApplication::setApplicationVersion(QStringLiteral("9.8.7"));
    // The harness outlives the window; closing it must not end the test's event processing.
    QApplication::setQuitOnLastWindowClosed(false);
}

void TestMainWindow::init() {
    QSettings().clear();
    QFile::remove(prisca::app::keptExperimentPath());  // no experiment kept from another test
    // Any warning is a failure, except the offscreen platform's note on size hints.
    QTest::failOnWarning(QRegularExpression(
        QStringLiteral("^(?!This plugin does not support propagateSizeHints\\(\\)$)")));
}

void TestMainWindow::construct_showsTitleMenusStatusBarAndPanels() {
    LanguageSwitcher languages;
    languages.restoreLanguage();
    QVERIFY(languages.setLanguage(QStringLiteral("en")));
    MainWindow window(languages);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));

    QCOMPARE(window.windowTitle(), QStringLiteral("PRISCA Lab"));
    QCOMPARE(menuBarTitles(window),
             (QStringList{QStringLiteral("&File"), QStringLiteral("&Run"), QStringLiteral("&View"),
                          QStringLiteral("&Help")}));

    QAction* quit = action(window, QStringLiteral("quitAction"));
    QVERIFY(quit);
    QCOMPARE(quit->shortcut(), QKeySequence(QStringLiteral("Ctrl+Q")));
    QVERIFY(menu(window, "fileMenu")->actions().contains(quit));

    QMenu* language = menu(window, "languageMenu");
    QVERIFY(language);
    QCOMPARE(language->title(), QStringLiteral("&Language"));
    QVERIFY(menu(window, "viewMenu")->actions().contains(language->menuAction()));
    QCOMPARE(language->actions().size(), 2);
    QCOMPARE(language->actions().at(0)->text(), QStringLiteral("English"));
    QCOMPARE(language->actions().at(1)->text(), QStringLiteral("繁體中文 (香港)"));
    QVERIFY(language->actions().at(0)->isChecked());
    QVERIFY(!language->actions().at(1)->isChecked());

    QAction* about = action(window, QStringLiteral("aboutAction"));
    QVERIFY(about);
    QCOMPARE(about->text(), QStringLiteral("&About PRISCA Lab"));
    QVERIFY(menu(window, "helpMenu")->actions().contains(about));

    QStatusBar* status = window.findChild<QStatusBar*>();
    QVERIFY(status);
    QVERIFY(status->isVisible());
    QVERIFY(status->findChild<QLabel*>(QStringLiteral("versionLabel")));
    QCOMPARE(status->findChild<QLabel*>(QStringLiteral("versionLabel"))->text(),
             QStringLiteral("Version 9.8.7"));

    // Ready to go on the simulated slide-car: the arena in the middle, panels around it.
    QWidget* central = window.centralWidget();
    QVERIFY(central);
    QCOMPARE(central->objectName(), QStringLiteral("arenaView"));
    for (const char* name : {"taskPanel", "controllerPanel", "runPanel", "liveChartsPanel"}) {
        QVERIFY2(window.findChild<QWidget*>(QLatin1String(name)), name);
    }
    QCOMPARE(window.session().plant(), QStringLiteral("slidecar"));
    auto* run = window.findChild<QAbstractButton*>(QStringLiteral("runButton"));
    QVERIFY(run);
    QVERIFY(run->isEnabled());
}

void TestMainWindow::languageMenu_switchesFileMenuToChineseAndBack() {
    LanguageSwitcher languages;
    MainWindow window(languages);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QMenu* file = menu(window, "fileMenu");
    QAbstractButton* heading = window.findChild<QAbstractButton*>(QStringLiteral("runButton"));
    QVERIFY(heading);
    const QString englishHeading = heading->text();
    QCOMPARE(file->title(), QStringLiteral("&File"));

    QAction* chinese = action(window, QStringLiteral("languageAction_zh_HK"));
    QVERIFY(chinese);
    chinese->trigger();
    QTRY_COMPARE(file->title(), kChineseFileMenu);
    QCOMPARE(languages.currentLanguage(), QStringLiteral("zh_HK"));
    QVERIFY(chinese->isChecked());
    QCOMPARE(menu(window, "languageMenu")->title(), QStringLiteral("語言(&L)"));
    QVERIFY(heading->text() != englishHeading);
    QCOMPARE(QSettings().value(QLatin1String(LanguageSwitcher::kSettingsKey)).toString(),
             QStringLiteral("zh_HK"));
    // The language names themselves never change, so anyone can find their own.
    QCOMPARE(action(window, QStringLiteral("languageAction_en"))->text(),
             QStringLiteral("English"));

    action(window, QStringLiteral("languageAction_en"))->trigger();
    QTRY_COMPARE(file->title(), QStringLiteral("&File"));
    QCOMPARE(heading->text(), englishHeading);
    QVERIFY(!chinese->isChecked());
    QCOMPARE(QSettings().value(QLatin1String(LanguageSwitcher::kSettingsKey)).toString(),
             QStringLiteral("en"));
}

void TestMainWindow::languageChoice_isRememberedForTheNextStart() {
    {
        LanguageSwitcher languages;
        QVERIFY(languages.setLanguage(QStringLiteral("zh_HK")));
    }
    LanguageSwitcher languages;
    languages.restoreLanguage();
    QCOMPARE(languages.currentLanguage(), QStringLiteral("zh_HK"));
    // Restored before the window exists, so it is Chinese from the first paint.
    MainWindow window(languages);
    QCOMPARE(menu(window, "fileMenu")->title(), kChineseFileMenu);
    QVERIFY(action(window, QStringLiteral("languageAction_zh_HK"))->isChecked());
}

void TestMainWindow::geometry_isRememberedForTheNextStart() {
    LanguageSwitcher languages;
    {
        MainWindow window(languages);
        window.resize(1200, 780);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.close());
    }
    QVERIFY(QSettings().contains(QLatin1String(MainWindow::kGeometryKey)));
    MainWindow window(languages);
    QCOMPARE(window.size(), QSize(1200, 780));
}

void TestMainWindow::aboutAction_showsWhatTheAppIs() {
    LanguageSwitcher languages;
    MainWindow window(languages);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));

    QString title;
    QString text;
    // The box is modal: read and dismiss it from a timer while trigger() waits in its loop.
    QTimer poll;
    connect(&poll, &QTimer::timeout, this, [&] {
        if (auto* box = qobject_cast<QMessageBox*>(prisca::app::ModalDialog::top())) {
            title = box->windowTitle();
            text = box->text();
            box->accept();
        }
    });
    poll.start(20);
    action(window, QStringLiteral("aboutAction"))->trigger();
    poll.stop();

    QCOMPARE(title, QStringLiteral("About PRISCA Lab"));
    QVERIFY2(text.contains(QStringLiteral("PRISCA Lab 9.8.7")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("one demonstrated manoeuvre")), qPrintable(text));
}

void TestMainWindow::quitShortcut_closesWindowAndEndsTheEventLoopWithZero() {
    // As in main(): the last window closing is what ends QApplication::exec().
    QApplication::setQuitOnLastWindowClosed(true);
    LanguageSwitcher languages;
    MainWindow window(languages);
    window.show();
    QVERIFY(QTest::qWaitForWindowActive(&window));

    QTimer::singleShot(0, &window,
                       [&window] { QTest::keyClick(&window, Qt::Key_Q, Qt::ControlModifier); });
    // A window that ignored Ctrl+Q would otherwise hang the test.
    QTimer guard;
    guard.setSingleShot(true);
    connect(&guard, &QTimer::timeout, this, [] { QCoreApplication::exit(99); });
    guard.start(10000);
    const int exitCode = QApplication::exec();
    guard.stop();
    QApplication::setQuitOnLastWindowClosed(false);

    QCOMPARE(exitCode, 0);
    QVERIFY(!window.isVisible());
    QVERIFY(QSettings().contains(QLatin1String(MainWindow::kGeometryKey)));
    QVERIFY(QSettings().contains(QLatin1String(MainWindow::kStateKey)));
}

void TestMainWindow::wheel_overAnUnfocusedSettingScrollsAndLeavesIt() {
    LanguageSwitcher languages;
    MainWindow window(languages);
    window.resize(1280, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* protocol = window.findChild<QComboBox*>(QStringLiteral("linkProtocol"));
    QVERIFY(protocol);
    // The rig panel shown (its dock raised, its Link page open) in the active window, as an
    // operator has it.
    for (QWidget* w = protocol; w; w = w->parentWidget()) {
        if (auto* dock = qobject_cast<QDockWidget*>(w)) {
            dock->raise();
        }
        if (auto* tabs = qobject_cast<QTabWidget*>(w)) {
            tabs->setCurrentIndex(1);
        }
    }
    QTRY_VERIFY(protocol->isVisible());
    QApplication::setActiveWindow(&window);
    QTRY_VERIFY(window.isActiveWindow());
    const int before = protocol->currentIndex();
    auto wheel = [&](int steps) {
        // From the window system, as a real wheel: to the window at the setting's position;
        // the window finds the widget there, the application gives focus by policy, delivers
        // the event and propagates it.
        const QPointF at =
            protocol->mapTo(&window, QPointF(protocol->width() / 2.0, protocol->height() / 2.0));
        QWheelEvent event(at, window.mapToGlobal(at), QPoint(), QPoint(0, -120 * steps),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QSpontaneKeyEvent::setSpontaneous(&event);
        QVERIFY(window.childAt(at.toPoint()) == protocol);
        qApp->notify(window.windowHandle(), &event);  // as delivered: sendEvent would unmark it
    };
    // The wheel passing over a setting does not give it the focus (a click or Tab does).
    for (const QWidget* field : window.findChildren<QComboBox*>()) {
        QVERIFY2(field->focusPolicy() == Qt::StrongFocus, qPrintable(field->objectName()));
    }
    for (const QWidget* field : window.findChildren<QAbstractSpinBox*>()) {
        QVERIFY2(field->focusPolicy() == Qt::StrongFocus, qPrintable(field->objectName()));
    }
    QVERIFY(protocol->focusPolicy() == Qt::StrongFocus);
    // Not clicked into: the setting stays; the wheel scrolls the panel around it.
    QScrollArea* panel = nullptr;
    for (QWidget* w = protocol; w && !panel; w = w->parentWidget()) {
        panel = qobject_cast<QScrollArea*>(w);
    }
    QVERIFY(panel);
    panel->verticalScrollBar()->setValue(0);
    // The rig's Link page scrolls in a short window (its buttons stay above the pages).
    for (int height = 800; height >= 500 && panel->verticalScrollBar()->maximum() == 0;
         height -= 50) {
        window.resize(1280, height);
        QCoreApplication::processEvents();  // the new layout
    }
    QVERIFY(panel->verticalScrollBar()->maximum() > 0);
    panel->verticalScrollBar()->setValue(0);
    QCoreApplication::processEvents();
    QVERIFY(!protocol->hasFocus());
    wheel(1);
    QCOMPARE(protocol->currentIndex(), before);
    QVERIFY(panel->verticalScrollBar()->value() > 0);
    panel->verticalScrollBar()->setValue(0);
    QCoreApplication::processEvents();
    // Clicked into (focused): the wheel changes it, as everywhere else.
    protocol->setFocus();
    QTRY_VERIFY(protocol->hasFocus());
    wheel(1);
    QVERIFY(protocol->currentIndex() != before);
}

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
