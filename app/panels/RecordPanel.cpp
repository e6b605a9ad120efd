#include "app/panels/RecordPanel.h"

#include "app/OperatorText.h"

#include "app/MessageLog.h"

#include "app/EmergencyStop.h"
#include "app/LabSession.h"
#include "app/input/DrivingInput.h"
#include "app/widgets/ModalDialog.h"
#include "core/DemonstrationCsv.h"
#include "sim/PlantCatalog.h"
#include "sim/run/TaskCheck.h"

#include <QApplication>
#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace prisca::app {

namespace {
constexpr int kRampTickMs = 25;  // keyboard ramp and countdown resolution [ms]
}  // namespace

RecordPanel::RecordPanel(LabSession& session, EmergencyStop& emergency, QWidget* parent)
    : QWidget(parent),
      session_(session),
      emergency_(emergency),
      recorder_(new RecordingThread(this)),
      driving_(new DrivingInput(this)),
      keys_(new QLabel(this)),
      gamepadLabel_(new QLabel(this)),
      countdownLabel_(new QLabel(this)),
      countdown_(new QSpinBox(this)),
      record_(new QPushButton(this)),
      stop_(new QPushButton(this)),
      save_(new QPushButton(this)),
      discard_(new QPushButton(this)),
      status_(new QLabel(this)),
      timer_(new QTimer(this)) {
    setObjectName(QStringLiteral("recordPanel"));
    qRegisterMetaType<core::Demonstration>();
    record_->setObjectName(QStringLiteral("recordButton"));
    stop_->setObjectName(QStringLiteral("stopRecordingButton"));
    save_->setObjectName(QStringLiteral("saveRecordingButton"));
    discard_->setObjectName(QStringLiteral("discardRecordingButton"));
    countdown_->setObjectName(QStringLiteral("countdown"));
    countdown_->setRange(0, 10);
    countdown_->setValue(QSettings().value(QStringLiteral("record/countdown"), 3).toInt());
    status_->setObjectName(QStringLiteral("recordStatus"));
    status_->setWordWrap(true);
    keys_->setWordWrap(true);

    auto* form = new QFormLayout;
    form->addRow(countdownLabel_, countdown_);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(record_);
    buttons->addWidget(stop_);
    auto* after = new QHBoxLayout;
    after->addWidget(save_);
    after->addWidget(discard_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(keys_);
    layout->addWidget(gamepadLabel_);
    layout->addLayout(form);
    layout->addLayout(buttons);
    layout->addLayout(after);
    layout->addWidget(status_);
    layout->addStretch(1);

    connect(recorder_, &RecordingThread::samplesReady, this, &RecordPanel::samplesReady);
    connect(recorder_, &RecordingThread::finished, this, &RecordPanel::finished);
    connect(recorder_, &RecordingThread::failed, this, [this](const QString& message) {
        recording_ = false;
        timer_->stop();
        driving_->stop();
        updateButtons();
        status_->setText(message);
        warningBox(this, tr("Record"), message);
    });
    timer_->setInterval(kRampTickMs);
    connect(timer_, &QTimer::timeout, this, &RecordPanel::tick);
    connect(record_, &QPushButton::clicked, this, &RecordPanel::startCountdown);
    connect(&emergency_, &EmergencyStop::engaged, this, &RecordPanel::emergencyStop);
    connect(&emergency_, &EmergencyStop::latchChanged, this, &RecordPanel::updateButtons);
    connect(stop_, &QPushButton::clicked, this, &RecordPanel::stopRecording);
    connect(save_, &QPushButton::clicked, this, &RecordPanel::save);
    connect(discard_, &QPushButton::clicked, this, &RecordPanel::discard);
    connect(countdown_, &QSpinBox::valueChanged, this,
            [](int s) { QSettings().setValue(QStringLiteral("record/countdown"), s); });
    connect(&session_, &LabSession::plantChanged, this, [this] {
        streamPath_.clear();
        previous_.reset();
        retranslateUi();
        updateButtons();
    });
    retranslateUi();
    updateButtons();
}

RecordPanel::~RecordPanel() {
    delete recorder_;  // its thread ends (stopped, bounded wait) before the widgets go
}

const Eigen::VectorXd& RecordPanel::input() const {
    return driving_->input();
}

QString RecordPanel::recordingsFolder() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
           QStringLiteral("/recordings");
}

void RecordPanel::startCountdown() {
    if (recording_ || countdownLeft_ > 0 || session_.plant().isEmpty()) {
        return;
    }
    if (emergency_.isLatched()) {
        showStatus(status_, tr("Record"), emergency_.refusal());
        return;
    }
    // Driving keys reach the input wherever the focus is, for as long as the recording lasts.
    driving_->start(session_.profile().info.actionDimension());
    countdownLeft_ = countdown_->value() * 1000 / kRampTickMs;
    timer_->start();
    if (countdownLeft_ == 0) {
        beginRecording();
    } else {
        updateButtons();
        tick();
    }
}

void RecordPanel::beginRecording() {
    countdownLeft_ = 0;
    recording_ = true;
    streamPath_ =
        recordingsFolder() + QStringLiteral("/%1-%2.csv")
                                 .arg(session_.plant(), QDateTime::currentDateTime().toString(
                                                            QStringLiteral("yyyyMMdd-HHmmss")));
    emit recordingStarted();
    recorder_->start(session_.plant(), streamPath_, session_.plantParameters());
    recordingClock_.start();
    lastReadoutMs_ = -1000;
    showStatus(status_, tr("Record"),
               [this] { return tr("Recording... drive, then press Stop."); });
    updateButtons();
}

void RecordPanel::tick() {
    if (countdownLeft_ > 0) {
        showStatus(status_, tr("Record"),
                   tr("Recording starts in %1 s").arg((countdownLeft_ * kRampTickMs + 999) / 1000));
        if (--countdownLeft_ == 0) {
            beginRecording();
        }
        return;
    }
    if (!recording_) {
        timer_->stop();
        return;
    }
    const sim::PlantInfo& info = session_.profile().info;
    Eigen::VectorXd input = driving_->advance(kRampTickMs / 1000.0);
    if (driving_->gamepadAvailable() != padShown_) {
        retranslateUi();  // plugged in or pulled out mid-recording
    }
    // The plant may mix the two stick axes into its actions (a differential drive's wheels).
    if (const sim::PlantEntry* entry = sim::PlantCatalog::find(session_.plant());
        entry && entry->fromStick && input.size() == 2) {
        input = entry->fromStick(input);
    }
    // Inputs are in [-1, 1] per channel; the plant's own limits scale them.
    Eigen::VectorXd scaled(input.size());
    for (Eigen::Index l = 0; l < input.size(); ++l) {
        scaled[l] =
            input[l] >= 0.0 ? input[l] * info.actionUpper[l] : -input[l] * info.actionLower[l];
    }
    recorder_->setInput(scaled);
    // What the operator is commanding, and for how long, a few times a second.
    if (recordingClock_.isValid() && recordingClock_.elapsed() - lastReadoutMs_ >= 200) {
        lastReadoutMs_ = recordingClock_.elapsed();
        QStringList commands;
        for (Eigen::Index l = 0; l < scaled.size(); ++l) {
            commands << QStringLiteral("%1 %2")
                            .arg(controlName(info.actionNames.value(static_cast<int>(l))))
                            .arg(scaled[l], 0, 'f', 2);
        }
        QString text = tr("Recording %1 s: %2. Press Stop when done.")
                           .arg(recordingClock_.elapsed() / 1000.0, 0, 'f', 1)
                           .arg(commands.join(QStringLiteral(", ")));
        if (info.name == QLatin1String("slidecar")) {
            text += QLatin1Char('\n') +
                    tr("The car has no brakes: let go of the throttle early, it slides on.");
        }
        status_->setText(text);  // live, not logged
    }
}

void RecordPanel::stopRecording() {
    if (countdownLeft_ > 0) {
        countdownLeft_ = 0;
        timer_->stop();
        driving_->stop();
        showStatus(status_, tr("Record"), tr("Recording cancelled."));
        updateButtons();
        return;
    }
    if (recording_) {
        recorder_->stop();
    }
}

void RecordPanel::emergencyStop() {
    if (countdownLeft_ > 0 || recording_) {
        // Neutral at once, and no key held any more can ramp it up again.
        driving_->neutral();
        timer_->stop();
        recorder_->requestStop();
        recorder_->setInput(Eigen::VectorXd::Zero(driving_->input().size()));
        endedByEmergency_ = recording_;
        stopRecording();
    }
}

void RecordPanel::finished(const core::Demonstration& demonstration, const QString& streamPath) {
    recording_ = false;
    timer_->stop();
    driving_->stop();
    if (endedByEmergency_) {
        // A take cut short by E-STOP is not what the operator meant to demonstrate.
        endedByEmergency_ = false;
        showStatus(
            status_, tr("Record"),
            demonstration.length() == 0
                ? tr("E-STOP ended the recording; nothing was recorded.")
                : tr("E-STOP ended the recording after %1 s; the demonstration is unchanged. The "
                     "take is kept in %2 (open it from the Task panel to use it).")
                      .arg(demonstration.length() * demonstration.dt, 0, 'f', 1)
                      .arg(QDir::toNativeSeparators(streamPath)));
        updateButtons();
        return;
    }
    if (demonstration.length() < sim::kMinimumDemonstrationSamples) {
        QFile::remove(streamPath);
        showStatus(status_, tr("Record"),
                   demonstration.length() == 0
                       ? tr("Nothing recorded.")
                       : tr("Too short to use (%1 samples, at least %2 are needed); the "
                            "demonstration is unchanged.")
                             .arg(demonstration.length())
                             .arg(sim::kMinimumDemonstrationSamples));
        updateButtons();
        return;
    }
    auto previous = session_.demonstration();
    const QString previousSource = session_.demonstrationSource();
    try {
        session_.setDemonstration(std::make_shared<core::Demonstration>(demonstration), streamPath);
    } catch (const std::exception& e) {
        // Refused (the session keeps its demonstration); the stream file stays for the record.
        showStatus(
            status_, tr("Record"),
            tr("The recording could not be used: %1. It is kept in %2.")
                .arg(QString::fromStdString(e.what()), QDir::toNativeSeparators(streamPath)));
        updateButtons();
        return;
    }
    previous_ = previous;
    previousSource_ = previousSource;
    showStatus(status_, tr("Record"),
               [this, samples = demonstration.length(),
                seconds = demonstration.length() * demonstration.dt, streamPath] {
                   return tr("Recorded %1 samples (%2 s), kept in %3. It is now the "
                             "demonstration; save it or discard it.")
                       .arg(samples)
                       .arg(seconds, 0, 'f', 1)
                       .arg(QDir::toNativeSeparators(streamPath));
               });
    updateButtons();
}

void RecordPanel::save() {
    QString path = ModalDialog::saveFileName(this, tr("Save demonstration"),
                                             QSettings().value("task/lastDirectory").toString(),
                                             tr("Demonstrations (*.csv)"));
    if (path.isEmpty()) {
        return;
    }
    if (!path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)) {
        path += QStringLiteral(".csv");
    }
    core::FileError error;
    if (!core::writeDemonstrationCsv(*session_.demonstration(), path, &error)) {
        warningBox(this, tr("Save demonstration"), error.toString());
        return;
    }
    session_.setDemonstrationSource(path);  // from now on it is named by its saved file
    showStatus(status_, tr("Record"), tr("Saved %1").arg(QDir::toNativeSeparators(path)));
}

void RecordPanel::discard() {
    if (!previous_) {
        return;
    }
    QFile::remove(streamPath_);
    session_.setDemonstration(previous_, previousSource_);
    previous_.reset();
    streamPath_.clear();
    showStatus(status_, tr("Record"),
               [this] { return tr("Recording discarded; the previous demonstration is back."); });
    updateButtons();
}

void RecordPanel::updateButtons() {
    const bool busy = recording_ || countdownLeft_ > 0;
    record_->setEnabled(!busy && !emergency_.isLatched());
    stop_->setEnabled(busy);
    const bool pending = !busy && previous_ != nullptr;
    save_->setEnabled(pending);
    discard_->setEnabled(pending);
}

void RecordPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void RecordPanel::retranslateUi() {
    const QStringList names = controlNames(session_.profile().info.actionNames);
    keys_->setText(tr("Drive with ↑/W and ↓/S for %1, ←/A and →/D for %2. Space or Esc is "
                      "E-STOP.")
                       .arg(names.value(0), names.value(1)));
    padShown_ = driving_->gamepadAvailable();
    gamepadLabel_->setText(driving_->gamepadAvailable()
                               ? tr("Gamepad: %1 (left stick forward, right stick sideways)")
                                     .arg(driving_->gamepadName())
                               : tr("No gamepad found: the keyboard drives."));
    countdownLabel_->setText(tr("Countdown:"));
    countdown_->setSuffix(tr(" s"));
    record_->setText(tr("Record"));
    record_->setToolTip(tr("Count down, then record while you drive"));
    stop_->setText(tr("Stop"));
    save_->setText(tr("Save as..."));
    discard_->setText(tr("Discard"));
    discard_->setToolTip(tr("Delete this recording and go back to the previous demonstration"));
}

}  // namespace prisca::app
