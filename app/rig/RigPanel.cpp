#include "app/rig/RigPanel.h"

#include "app/EmergencyStop.h"
#include "app/LabSession.h"
#include "app/MessageLog.h"
#include "app/input/DrivingInput.h"
#include "app/panels/RecordPanel.h"
#include "app/rig/RigCameraPage.h"
#include "app/rig/RigDoctorPage.h"
#include "app/rig/RigLinkPage.h"
#include "app/rig/RigSetupPage.h"
#include "app/widgets/CameraView.h"
#include "app/widgets/NamedWidget.h"
#include "devices/ProcessFailsafe.h"
#include "rig/RigCalibration.h"
#include "sim/MethodCatalog.h"

#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QJsonDocument>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace prisca::app {

RigPanel::RigPanel(LabSession& session, EmergencyStop& emergency, QWidget* parent)
    : QWidget(parent),
      session_(session),
      emergency_(emergency),
      setup_(std::make_unique<rig::RigCalibration>(rig_)),
      view_(new CameraView(this)),
      startCamera_(named<QPushButton>(this, "startCamera")),
      stopCamera_(named<QPushButton>(this, "stopCamera")),
      connect_(named<QPushButton>(this, "connectLink")),
      disconnect_(named<QPushButton>(this, "disconnectLink")),
      drive_(named<QPushButton>(this, "driveOnRig")),
      runTrial_(named<QPushButton>(this, "runOnRig")),
      stopTrial_(named<QPushButton>(this, "stopOnRig")),
      readiness_(named<QLabel>(this, "rigReadiness")),
      putBack_(named<QPushButton>(this, "putCarBack")),
      trialInfo_(named<QLabel>(this, "rigTrialInfo")) {
    setObjectName(QStringLiteral("rigPanel"));
    drive_->setCheckable(true);
    readiness_->setWordWrap(true);
    readiness_->setTextFormat(Qt::PlainText);
    trialInfo_->setWordWrap(true);
    driving_ = new DrivingInput(this);
    driveTimer_ = new QTimer(this);
    driveTimer_->setInterval(25);
    statusTimer_ = new QTimer(this);
    statusTimer_->setInterval(1000);
    // The pages first: their handlers of the session's signals run before the panel's.
    cameraPage_ = new RigCameraPage(rig_, *setup_, session_, *view_, this);
    linkPage_ = new RigLinkPage(rig_, session_, this);
    setupPage_ = new RigSetupPage(rig_, *setup_, emergency_, *view_, this);
    doctorPage_ = new RigDoctorPage(this);
    buildLayout();
    connectParts();
    statusTimer_->start();
    view_->setCalibration(rig_.calibration());
    retranslateUi();
    showTask();
    showLinkStatus(rig_.linkStatus());
    updateButtons();
}

void RigPanel::buildLayout() {
    // What an operator presses in a session stays in view above the tabs, whatever the height:
    // the camera, the link, the trials.
    auto* actions = new QGridLayout;
    actions->addWidget(startCamera_, 0, 0);
    actions->addWidget(stopCamera_, 0, 1);
    actions->addWidget(connect_, 0, 2);
    actions->addWidget(disconnect_, 0, 3);
    actions->addWidget(drive_, 1, 0, 1, 2);
    actions->addWidget(runTrial_, 1, 2);
    actions->addWidget(stopTrial_, 1, 3);
    auto* ready = new QHBoxLayout;
    ready->addWidget(readiness_, 1);
    ready->addWidget(putBack_);
    auto* top = new QVBoxLayout;
    top->addLayout(actions);
    top->addLayout(ready);
    top->addWidget(trialInfo_);
    tabs_ = new QTabWidget(this);
    tabs_->setObjectName(QStringLiteral("rigTabs"));
    // Each page scrolls on its own, so the buttons above stay in view at any height.
    for (QWidget* page :
         std::initializer_list<QWidget*>{cameraPage_, linkPage_, setupPage_, doctorPage_}) {
        auto* scroll = new QScrollArea(tabs_);
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidget(page);
        tabs_->addTab(scroll, QString());
    }
    auto* right = new QVBoxLayout;
    right->addLayout(top);
    right->addWidget(tabs_, 1);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(view_, 1);
    layout->addLayout(right, 1);
}

void RigPanel::connectParts() {
    connect(&emergency_, &EmergencyStop::engaged, this, &RigPanel::emergencyStop);
    connect(&emergency_, &EmergencyStop::released, this, &RigPanel::resetEmergencyStop);
    connect(&emergency_, &EmergencyStop::latchChanged, this, [this] { updateButtons(); });
    connect(statusTimer_, &QTimer::timeout, this, [this] {
        const long long frames = rig_.framesSeen();
        cameraFps_ = rig_.cameraRunning() ? static_cast<double>(frames - framesAtLastTick_) : 0.0;
        framesAtLastTick_ = frames;
        emitStatus();
        showReadiness();
    });
    connect(driveTimer_, &QTimer::timeout, this, &RigPanel::driveTick);
    connect(&rig_, &rig::RigSession::frameReady, this, &RigPanel::showFrame);
    connect(&rig_, &rig::RigSession::linkStatusChanged, this, &RigPanel::showLinkStatus);
    connect(&rig_, &rig::RigSession::cameraRunningChanged, this, [this](bool running) {
        updateButtons();
        if (!running) {
            view_->clearFrame();  // a stopped camera shows no stale image
            setupPage_->setNewestFrame(cv::Mat());
            tracking_ = false;
        }
        emitStatus();
    });
    connect(&rig_, &rig::RigSession::trialFinished, this, &RigPanel::showTrialResult);
    connect(&rig_, &rig::RigSession::recordingFinished, this, &RigPanel::useRecording);
    connect(startCamera_, &QPushButton::clicked, this, &RigPanel::startCamera);
    connect(stopCamera_, &QPushButton::clicked, this, &RigPanel::stopCamera);
    connect(connect_, &QPushButton::clicked, this, &RigPanel::connectLink);
    connect(disconnect_, &QPushButton::clicked, this, &RigPanel::disconnectLink);
    connect(runTrial_, &QPushButton::clicked, this, &RigPanel::runTrial);
    connect(stopTrial_, &QPushButton::clicked, this, &RigPanel::stopTrial);
    connect(putBack_, &QPushButton::clicked, this, &RigPanel::putVirtualCarBack);
    connect(drive_, &QPushButton::clicked, this, [this](bool on) {
        if (!on) {
            stopDriving();
        } else if (!startDriving()) {
            drive_->setChecked(false);
        }
    });
    connect(cameraPage_, &RigCameraPage::cameraStateChanged, this, &RigPanel::emitStatus);
    connect(cameraPage_, &RigCameraPage::sourceChanged, this, &RigPanel::showReadiness);
    // Clicks on the image are floor points or fence corners, one at a time.
    connect(cameraPage_, &RigCameraPage::calibratingChanged, this, [this](bool on) {
        if (on) {
            setupPage_->setDrawingFence(false);
        }
        setClickMode();
    });
    connect(setupPage_, &RigSetupPage::drawingFenceChanged, this, [this](bool on) {
        if (on) {
            cameraPage_->setCalibrating(false);
        }
        setClickMode();
    });
    connect(view_, &CameraView::imagePointClicked, this, &RigPanel::clickOnImage);
    connect(setupPage_, &RigSetupPage::latencyChanged, this, &RigPanel::showReadiness);
    connect(setupPage_, &RigSetupPage::replayRequested, this, &RigPanel::replayRequested);
    connect(setupPage_, &RigSetupPage::bundleFailed, this, [this](const QString& problem) {
        trialInfo_->setText(trialInfo_->text() + QLatin1Char('\n') + problem);
        logMessage(this, tr("Rig trial"), MessageLevel::Warning, problem);
    });
    connect(&session_, &LabSession::demonstrationChanged, this, &RigPanel::showTask);
}

RigPanel::~RigPanel() {
    // The session may already be gone (the window deletes it first): a recording in progress is
    // kept on disk by the rig session, not handed to the session.
    driveTimer_->stop();
    driving_->stop();
    disconnect(&rig_, nullptr, this, nullptr);
    // The pages hold the rig session and the set-up: gone before them.
    delete tabs_;
    tabs_ = nullptr;
}

void RigPanel::setClickMode() {
    const bool fence = setupPage_->drawingFence();
    const bool floor = cameraPage_->calibrating();
    // What to do, on the image itself and on the panel.
    view_->setClickHint(fence   ? tr("Fence: click its corners in order around the floor; "
                                       "click Draw fence again to finish")
                        : floor ? tr("Floor calibration: click a point of known floor position")
                                : QString());
    view_->setCalibrating(fence || floor);
}

void RigPanel::clickOnImage(const QPointF& image) {
    if (setupPage_->drawingFence()) {
        setupPage_->addFenceCornerAt(image);
    } else if (cameraPage_->calibrating()) {
        cameraPage_->askFloorPoint(image);
    }
}

void RigPanel::startCamera() {
    const bool hadVirtualPort = !rig_.virtualPort().isEmpty();
    if (!cameraPage_->startCamera()) {
        return;
    }
    if (!hadVirtualPort && !rig_.virtualPort().isEmpty()) {
        linkPage_->chooseVirtualPort();
    }
}

void RigPanel::stopCamera() {
    rig_.stopCamera();
}

void RigPanel::connectLink() {
    linkPage_->connectLink();
}

void RigPanel::disconnectLink() {
    rig_.disconnectLink();
}

bool RigPanel::loadCalibration(const QString& path) {
    return cameraPage_->loadCalibration(path);
}

bool RigPanel::saveCalibration(const QString& path) {
    return cameraPage_->saveCalibration(path);
}

void RigPanel::addCalibrationPoint(const QPointF& image, const QPointF& floor) {
    cameraPage_->addCalibrationPoint(image, floor);
}

bool RigPanel::captureBoardView() {
    return setupPage_->captureBoardView();
}

bool RigPanel::fitLens() {
    return setupPage_->fitLens();
}

bool RigPanel::loadLens(const QString& path) {
    return setupPage_->loadLens(path);
}

int RigPanel::boardViewsCaptured() const {
    return setup_->boardViewsCaptured();
}

const std::optional<devices::CameraLens>& RigPanel::lens() const {
    return setup_->lens();
}

bool RigPanel::measureLatency() {
    return setupPage_->measureLatency();
}

void RigPanel::declareLoopLatency(double milliseconds) {
    setupPage_->declareLoopLatency(milliseconds);
}

void RigPanel::addFenceCorner(const QPointF& floor) {
    setupPage_->addFenceCorner(floor);
}

void RigPanel::clearFence() {
    setupPage_->clearFence();
}

void RigPanel::setSaveBundles(bool on) {
    setupPage_->setSaveBundles(on);
}

const QString& RigPanel::lastBundle() const {
    return setupPage_->lastBundle();
}

bool RigPanel::runTrial() {
    if (isRunning()) {
        return false;
    }
    if (emergency_.isLatched()) {
        showStatus(trialInfo_, tr("Rig trial"), emergency_.refusal(), MessageLevel::Warning);
        return false;
    }
    // The session's own check: what the strip shows is what decides.
    const rig::PreTrialCheck check = preTrialCheck();
    showReadiness();
    if (!check.ready()) {
        showStatus(trialInfo_, tr("Rig trial"),
                   tr("Not ready for a trial: %1").arg(check.missingDetails()),
                   MessageLevel::Warning);
        return false;
    }
    rig::TrialRequest request;
    try {
        request.setup = std::make_shared<const sim::RunSetup>(session_.task(), session_.method());
    } catch (const std::exception& e) {
        showStatus(trialInfo_, tr("Rig trial"), QString::fromUtf8(e.what()), MessageLevel::Error);
        return false;
    }
    request.session = QJsonDocument::fromJson(session_.toJson()).object();
    QString error;
    if (!rig_.startTrial(request, &error)) {
        showStatus(trialInfo_, tr("Rig trial"), error);
        return false;
    }
    showStatus(trialInfo_, tr("Rig trial"), tr("Trial %1 running...").arg(rig_.trialNumber()));
    runTrial_->setEnabled(false);
    return true;
}

rig::PreTrialCheck RigPanel::preTrialCheck() const {
    return rig_.preTrialCheck(session_.task(), sim::MethodCatalog::get(session_.method()));
}

void RigPanel::showReadiness() {
    const rig::PreTrialCheck check = preTrialCheck();
    QStringList lines;
    QStringList advice;
    for (const rig::PreTrialItem& item : check.items) {
        lines << QStringLiteral("%1 %2: %3")
                     .arg(item.ok         ? QStringLiteral("✓")
                          : item.blocking ? QStringLiteral("✗")
                                          : QStringLiteral("!"),
                          item.label, item.detail);
        if (!item.ok && !item.blocking) {
            advice << item.label;
        }
    }
    QString text;
    if (check.ready()) {
        text = advice.isEmpty()
                   ? tr("Ready for a trial")
                   : tr("Ready for a trial (note: %1)").arg(advice.join(QStringLiteral(", ")));
    } else {
        text = tr("Not ready: %1").arg(check.missingLabels());
    }
    readiness_->setText(text);
    readiness_->setToolTip(lines.join(QLatin1Char('\n')));
    readiness_->setStyleSheet(
        check.ready() ? QStringLiteral("QLabel { color: #1b5e20; font-weight: bold; }")
                      : QStringLiteral("QLabel { color: #b00020; font-weight: bold; }"));
    const bool virtualCamera = cameraPage_->source() == Source::Virtual;
    putBack_->setVisible(virtualCamera);
    putBack_->setEnabled(virtualCamera && rig_.cameraRunning() && !rig_.trialRunning());
}

bool RigPanel::putVirtualCarBack() {
    QString error;
    if (!rig_.putVirtualCarBack(&error)) {
        showStatus(trialInfo_, tr("Rig trial"), error, MessageLevel::Warning);
        return false;
    }
    showStatus(trialInfo_, tr("Rig trial"), tr("The virtual car is back at its start."));
    return true;
}

const Eigen::VectorXd& RigPanel::drivingInput() const {
    return driving_->input();
}

bool RigPanel::startDriving() {
    if (drivingActive_ || isRunning()) {
        return false;
    }
    if (emergency_.isLatched()) {
        showStatus(trialInfo_, tr("Rig trial"), emergency_.refusal(), MessageLevel::Warning);
        drive_->setChecked(false);
        return false;
    }
    if (const QString problem = cameraPage_->floorProblem(); !problem.isEmpty()) {
        showStatus(trialInfo_, tr("Rig trial"), problem, MessageLevel::Warning);
        return false;
    }
    const sim::PlantInfo& info = session_.profile().info;
    const QString path =
        RecordPanel::recordingsFolder() +
        QStringLiteral("/rig-%1.csv")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    QDir().mkpath(RecordPanel::recordingsFolder());
    QString error;
    if (!rig_.startRecording(info, path, &error)) {
        showStatus(trialInfo_, tr("Rig trial"), error);
        return false;
    }
    driving_->start(info.actionDimension());
    drivingActive_ = true;
    driveTimer_->start();
    showStatus(trialInfo_, tr("Rig trial"),
               tr("Driving and recording: arrows or WASD (or a gamepad); press Drive "
                  "again to stop."));
    drive_->setChecked(true);
    return true;
}

void RigPanel::driveTick() {
    rig_.setDriveCommand(driving_->advance(driveTimer_->interval() / 1000.0));
}

void RigPanel::stopDriving() {
    if (!drivingActive_) {
        return;
    }
    driveTimer_->stop();
    driving_->stop();
    drivingActive_ = false;
    drive_->setChecked(false);
    rig_.stopRecording();  // useRecording() follows once the take is written
    showStatus(trialInfo_, tr("Rig trial"), tr("Saving the recording..."));
}

void RigPanel::useRecording(const rig::RigRecording& recording) {
    QString message;
    if (!recording.demonstration) {
        message = recording.error;
    } else if (recordingEndedByEmergency_) {
        recordingEndedByEmergency_ = false;
        message = tr("E-STOP ended the rig recording; the demonstration is unchanged. The take is "
                     "kept in %1.")
                      .arg(QDir::toNativeSeparators(recording.path));
    } else {
        const int samples = recording.demonstration->length();
        try {
            session_.setDemonstration(recording.demonstration, recording.path);
            message = tr("Recorded %1 samples on the rig, kept in %2; it is now the "
                         "demonstration.")
                          .arg(samples)
                          .arg(QDir::toNativeSeparators(recording.path));
        } catch (const std::exception& e) {
            message = tr("The rig recording could not be used: %1. It is kept in %2.")
                          .arg(QString::fromStdString(e.what()),
                               QDir::toNativeSeparators(recording.path));
        }
    }
    showStatus(trialInfo_, tr("Rig trial"), message);
    emit demonstrationRecorded(message);
}

void RigPanel::emergencyStop() {
    driving_->neutral();
    recordingEndedByEmergency_ = drivingActive_;
    stopDriving();
    rig_.emergencyStop();
    if (rig_.measuringLatency()) {
        rig_.cancelLatencyMeasurement();
    }
    showStatus(trialInfo_, tr("Rig trial"), [] {
        // The latch's cause as the rig's check says it, when it is not the operator's button.
        return devices::processfailsafe::held()
                   ? rig::emergencyProblem(true)
                   : tr("E-STOP: the transmitter sends failsafe until E-STOP is reset.");
    });
}

void RigPanel::resetEmergencyStop() {
    rig_.resetEmergencyStop();
    // Whatever the panel said of the latch (E-STOP pressed, a start refused) is old news now.
    showStatus(trialInfo_, tr("Rig trial"),
               [] { return tr("E-STOP is reset: the link sends the commands again."); });
}

void RigPanel::showTrialResult(const rig::RigTrialResult& result) {
    lastResult_ = rig::trialSentence(result);
    showStatus(trialInfo_, tr("Rig trial"), lastResult_);
    updateButtons();
    emit trialFinished(lastResult_);
}

void RigPanel::showFrame(const devices::CameraFrame& frame,
                         const std::optional<devices::PlanarPose>& pose) {
    setupPage_->setNewestFrame(frame.image);
    tracking_ = pose.has_value();
    view_->setFrame(frame.image, pose);
    if (pose && session_.profile().info.name == QLatin1String("slidecar")) {
        Eigen::VectorXd state = Eigen::VectorXd::Zero(6);
        state.head(3) << pose->x, pose->y, pose->heading;
        emit carTracked(state);
    }
}

void RigPanel::emitStatus() {
    const devices::LinkStatus& link = rig_.linkStatus();
    QString linkText;
    bool linkAlarm = false;
    if (!link.connected) {
        linkText = link.lastError.isEmpty() ? tr("Link: off") : tr("Link: port error");
        linkAlarm = !link.lastError.isEmpty();
    } else if (link.failsafe != devices::FailsafeReason::None) {
        linkText = tr("Link: %1 failsafe (%2)")
                       .arg(linkPage_->protocolName(), devices::failsafeReasonText(link.failsafe));
        linkAlarm = link.failsafe != devices::FailsafeReason::NoCommand;
    } else {
        linkText =
            tr("Link: %1 %2/s").arg(linkPage_->protocolName()).arg(link.measuredRateHz, 0, 'f', 0);
    }
    QString cameraText;
    bool cameraAlarm = false;
    if (rig_.cameraRunning()) {
        cameraText = tracking_ ? tr("Camera: %1 fps, tracking").arg(cameraFps_, 0, 'f', 0)
                               : tr("Camera: %1 fps, no car in view").arg(cameraFps_, 0, 'f', 0);
        cameraAlarm = !tracking_;
    } else {
        cameraText = cameraPage_->cameraFailed()  ? tr("Camera: failed")
                     : cameraPage_->cameraEnded() ? tr("Camera: video ended")
                                                  : tr("Camera: off");
        cameraAlarm = cameraPage_->cameraFailed();
    }
    emit statusSummary(linkText, linkAlarm, cameraText, cameraAlarm);
}

void RigPanel::updateButtons() {
    const bool camera = rig_.cameraRunning();
    const bool linked = rig_.linkStatus().connected;
    startCamera_->setEnabled(!camera);
    stopCamera_->setEnabled(camera);
    cameraPage_->setCameraRunning(camera);
    connect_->setEnabled(!linked);
    disconnect_->setEnabled(linked);
    linkPage_->setLinked(linked);
    // Nothing that moves the car starts while E-STOP is latched.
    const bool latched = emergency_.isLatched();
    runTrial_->setEnabled(!latched && !rig_.trialRunning());
    drive_->setEnabled(!latched || drivingActive_);
    setupPage_->updateButtons();
}

void RigPanel::showLinkStatus(const devices::LinkStatus& status) {
    if (devices::processfailsafe::held() && !emergency_.isLatched()) {
        // Stopped (Ctrl-Z) and continued: the link holds failsafe; the latch says so, and its
        // reset is the operator's taking over.
        emergency_.engage(tr("the process being stopped and continued"));
    }
    updateButtons();
    linkPage_->showLinkStatus(status);
    emitStatus();
}

void RigPanel::showTask() {
    const auto demo = session_.demonstration();
    const auto& pose = session_.profile().info.pose;
    if (!demo || !pose || demo->length() == 0) {
        view_->setTask({}, {}, 0.0);
        return;
    }
    QVector<QPointF> path;
    for (int k = 0; k < demo->length(); ++k) {
        path.push_back({demo->states(k, pose->x), demo->states(k, pose->y)});
    }
    const int last = demo->length() - 1;
    view_->setTask(path, {demo->states(last, pose->x), demo->states(last, pose->y)},
                   demo->states(last, pose->heading));
}

void RigPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void RigPanel::retranslateUi() {
    startCamera_->setText(tr("Start camera"));
    stopCamera_->setText(tr("Stop camera"));
    connect_->setText(tr("Connect"));
    disconnect_->setText(tr("Disconnect"));
    drive_->setText(tr("Drive and record"));
    drive_->setToolTip(
        tr("Drive the car through the link (arrows or WASD, or a gamepad) and "
           "record a demonstration from the camera"));
    runTrial_->setText(tr("Run a trial on the rig"));
    runTrial_->setToolTip(
        tr("The session's method drives the car through the link, with the "
           "camera's pose as its state"));
    stopTrial_->setText(tr("Stop the trial"));
    putBack_->setText(tr("Put the car back"));
    putBack_->setToolTip(
        tr("The virtual car back at its start, at rest (after a trial that "
           "left it out of view)"));
    tabs_->setTabText(0, tr("Camera and floor"));
    tabs_->setTabText(1, tr("Link"));
    tabs_->setTabText(2, tr("Lens, latency, fence"));
    tabs_->setTabText(3, tr("This computer"));
    setClickMode();
    emitStatus();  // the status bar's fields in the new language
    showReadiness();
}

}  // namespace prisca::app
