// MainWindow: the work under way, stopping it, quitting when it is done, and closing.
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
    logMessage(this, tr("Quit"), MessageLevel::Info,
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
                logMessage(this, tr("Quit"), MessageLevel::Info,
                           tr("The run's log was kept in %1").arg(path));
            } else {
                logMessage(this, tr("Quit"), MessageLevel::Error, error);
            }
        }
        if (!experimentsPanel_->tableText(core::TableFormat::Markdown).isEmpty()) {
            const QString path =
                QDir(keptFolder()).filePath(QStringLiteral("experiment-%1.md").arg(stamp));
            if (experimentsPanel_->exportTable(path, &error)) {
                logMessage(this, tr("Quit"), MessageLevel::Info,
                           tr("The experiment's table was kept in %1").arg(path));
            } else {
                logMessage(this, tr("Quit"), MessageLevel::Error, error);
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

}  // namespace prisca::app
