// What the window's offscreen tests share: the window at 1280x800, modal dialogs answered as an
// operator would, and the virtual rig started through the Rig panel.
#pragma once

#include "app/EmergencyStop.h"
#include "app/EmergencyStopGuard.h"
#include "app/LabSession.h"
#include "app/LanguageSwitcher.h"
#include "app/MainWindow.h"
#include "app/panels/ControllerPanel.h"
#include "app/panels/ExperimentsPanel.h"
#include "app/panels/LiveChartsPanel.h"
#include "app/panels/MappingPanel.h"
#include "app/panels/RecordPanel.h"
#include "app/panels/RunPanel.h"
#include "app/panels/TaskPanel.h"
#include "app/plot/ChartDecimation.h"
#include "app/rig/RigPanel.h"
#include "app/widgets/ModalDialog.h"
#include "app/workers/ExperimentArchive.h"
#include "app/workers/RunThread.h"
#include "core/DemonstrationCsv.h"
#include "core/PriscaController.h"
#include "devices/SyntheticCamera.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "support/FileSizeLimit.h"

#include <sys/stat.h>

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSet>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolBar>
#include <QWheelEvent>
#include "sim/DemonstrationStyles.h"

#include <QtTest>

#include <functional>

namespace prisca::test {

using namespace prisca::app;

/// Once per test executable: settings and files in the test's own places (named `name`), and the
/// application kept alive when its windows close.
inline void initGuiTestCase(const char* name) {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("PRISCA Lab Tests"));
    QCoreApplication::setApplicationName(QString::fromLatin1(name));
    QApplication::setQuitOnLastWindowClosed(false);
}

/// Before each test: no settings and no experiment kept from an earlier test or run (a window
/// shows a kept one at start).
inline void resetGuiState() {
    QSettings().clear();
    QFile::remove(keptExperimentPath());
}

inline constexpr int kRunTimeoutMs = 60000;

// Reads and dismisses the next modal message box while `trigger` runs.
inline QString answerMessageBox(QObject* context, const std::function<void()>& trigger) {
    QString text;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, context, [&] {
        if (auto* box = qobject_cast<QMessageBox*>(ModalDialog::top())) {
            text = box->text();
            box->accept();
        }
    });
    poll.start(20);
    trigger();
    poll.stop();
    return text;
}

// Presses the button named `button` ("quitFinish", "quitKeep", "quitDiscard", "quitCancel") of
// the quit question while `trigger` runs; returns the question's text (empty: none was asked).
inline QString answerQuitQuestion(QObject* context, const char* button,
                                  const std::function<void()>& trigger) {
    QString text;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, context, [&] {
        auto* box = qobject_cast<QMessageBox*>(ModalDialog::top());
        if (box && box->objectName() == QLatin1String("quitQuestion")) {
            text = box->text();
            if (auto* b = box->findChild<QAbstractButton*>(QLatin1String(button))) {
                b->click();
            }
        }
    });
    poll.start(20);
    trigger();
    poll.stop();
    return text;
}

// Answers the next file dialog with `path` while `trigger` runs.
inline void answerFileDialog(QObject* context, const QString& path,
                             const std::function<void()>& trigger) {
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, context, [&] {
        if (auto* dialog = qobject_cast<QFileDialog*>(ModalDialog::top())) {
            // Typed into the file name field and confirmed, as an operator would.
            if (auto* edit = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))) {
                edit->setText(path);
                QTest::keyClick(edit, Qt::Key_Return);
            }
        }
    });
    poll.start(20);
    trigger();
    poll.stop();
}

struct Window {
    LanguageSwitcher languages;
    MainWindow window{languages};
    Window() {
        window.resize(1280, 800);
        window.show();
        activate();
    }
    // Keys reach the shortcuts of the active window only (a window manager gives the window
    // back its activation when a popup closes; the offscreen platform does not): wait for it.
    void activate() {
        QApplication::setActiveWindow(&window);
        if (!QTest::qWaitForWindowActive(&window)) {
            qWarning("the window did not become active");
        }
    }
    template <class T>
    T* find(const char* name) {
        return window.findChild<T*>(QLatin1String(name));
    }
    void setSpeedIndex(int index) { find<QComboBox>("speed")->setCurrentIndex(index); }
    // Presses Run as the operator does and waits for the run's end and for the panel to be idle
    // again: the worker tells the end before its phase, so Run pressed again in between would
    // meet a disabled button. False when either does not come within kRunTimeoutMs.
    bool runToEnd() {
        auto* run = find<QAbstractButton>("runButton");
        if (!QTest::qWaitFor([&] { return run->isEnabled(); }, kRunTimeoutMs)) {
            qWarning("the Run button stayed disabled");
            return false;
        }
        QSignalSpy finished(&window.run(), &RunThread::runFinished);
        run->click();
        return QTest::qWaitFor([&] { return finished.count() > 0; }, kRunTimeoutMs) &&
               QTest::qWaitFor([&] { return run->isEnabled(); }, kRunTimeoutMs);
    }
    QTableWidget* results() { return find<QTableWidget>("trialResults"); }
};

// The virtual rig's camera running with a pose, and the link connected to its car.
inline bool startVirtualRig(Window& w, RigPanel* rig) {
    w.find<QComboBox>("cameraSource")->setCurrentIndex(0);
    rig->startCamera();
    if (!QTest::qWaitFor([&] { return rig->lastPose().has_value(); }, 10000)) {
        return false;
    }
    w.find<QComboBox>("linkPort")->setEditText(rig->virtualPort());
    rig->connectLink();
    return QTest::qWaitFor([&] { return rig->linkStatus().connected; }, 5000);
}

}  // namespace prisca::test
