#include "app/RigPanel.h"

#include "app/CameraView.h"
#include "app/DrivingInput.h"
#include "app/LabSession.h"
#include "app/RecordPanel.h"
#include "core/DemonstrationCsv.h"
#include "core/DeviationModel.h"
#include "devices/LedTracker.h"
#include "devices/SyntheticCamera.h"
#include "rigsim/VirtualCar.h"
#include "sim/DemonstrationRecorder.h"
#include "sim/EpisodeRunner.h"
#include "sim/MethodCatalog.h"
#include "sim/MethodTraining.h"
#include "sim/TrialMetrics.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace prisca::app {

namespace {
// The virtual rig's synthetic ceiling camera runs at the control rate of the simulations.
constexpr double kVirtualCameraFps = 40.0;
}  // namespace

namespace {

QImage toImage(const cv::Mat& m) {
    if (m.type() == CV_8UC1) {
        return QImage(m.data, m.cols, m.rows, static_cast<int>(m.step), QImage::Format_Grayscale8)
            .copy();
    }
    if (m.type() == CV_8UC3) {
        return QImage(m.data, m.cols, m.rows, static_cast<int>(m.step), QImage::Format_BGR888)
            .copy();
    }
    return {};
}

}  // namespace

RigPanel::RigPanel(LabSession& session, QWidget* parent)
    : QWidget(parent),
      session_(session),
      shared_(std::make_shared<Shared>()),
      view_(new CameraView(this)),
      sourceLabel_(new QLabel(this)),
      source_(new QComboBox(this)),
      sourcePath_(new QLineEdit(this)),
      cameraSettingsLabel_(new QLabel(this)),
      width_(new QSpinBox(this)),
      height_(new QSpinBox(this)),
      fps_(new QSpinBox(this)),
      exposure_(new QSpinBox(this)),
      gain_(new QSpinBox(this)),
      startCamera_(new QPushButton(this)),
      stopCamera_(new QPushButton(this)),
      calibrationInfo_(new QLabel(this)),
      loadCalibration_(new QPushButton(this)),
      saveCalibration_(new QPushButton(this)),
      calibrate_(new QPushButton(this)),
      portLabel_(new QLabel(this)),
      port_(new QComboBox(this)),
      protocolLabel_(new QLabel(this)),
      protocol_(new QComboBox(this)),
      connect_(new QPushButton(this)),
      disconnect_(new QPushButton(this)),
      linkInfo_(new QLabel(this)),
      baudLabel_(new QLabel(this)),
      baud_(new QSpinBox(this)),
      channelTable_(new QTableWidget(this)),
      channelProblem_(new QLabel(this)),
      drive_(new QPushButton(this)),
      runTrial_(new QPushButton(this)),
      stopTrial_(new QPushButton(this)),
      trialInfo_(new QLabel(this)) {
    setObjectName(QStringLiteral("rigPanel"));
    source_->setObjectName(QStringLiteral("cameraSource"));
    sourcePath_->setObjectName(QStringLiteral("cameraPath"));
    width_->setObjectName(QStringLiteral("cameraWidth"));
    height_->setObjectName(QStringLiteral("cameraHeight"));
    fps_->setObjectName(QStringLiteral("cameraFps"));
    exposure_->setObjectName(QStringLiteral("cameraExposure"));
    gain_->setObjectName(QStringLiteral("cameraGain"));
    width_->setRange(160, 4096);
    height_->setRange(120, 4096);
    fps_->setRange(1, 500);
    exposure_->setRange(-1, 100000);
    gain_->setRange(-1, 10000);
    startCamera_->setObjectName(QStringLiteral("startCamera"));
    stopCamera_->setObjectName(QStringLiteral("stopCamera"));
    calibrate_->setObjectName(QStringLiteral("calibrate"));
    calibrate_->setCheckable(true);
    port_->setObjectName(QStringLiteral("linkPort"));
    port_->setEditable(true);
    protocol_->setObjectName(QStringLiteral("linkProtocol"));
    connect_->setObjectName(QStringLiteral("connectLink"));
    disconnect_->setObjectName(QStringLiteral("disconnectLink"));
    linkInfo_->setObjectName(QStringLiteral("linkStatus"));
    calibrationInfo_->setObjectName(QStringLiteral("calibrationInfo"));
    for (int i = 0; i < 3; ++i) {
        source_->addItem(QString(), i);
    }
    for (devices::RcProtocol p : {devices::RcProtocol::Crsf, devices::RcProtocol::Sbus,
                                  devices::RcProtocol::Multiprotocol}) {
        protocol_->addItem(devices::protocolName(p).toUpper(), static_cast<int>(p));
    }
    linkInfo_->setWordWrap(true);
    baud_->setObjectName(QStringLiteral("linkBaud"));
    baud_->setRange(0, 4000000);
    baud_->setSingleStep(100000);
    channelTable_->setObjectName(QStringLiteral("channelMap"));
    channelTable_->setColumnCount(5);
    channelTable_->setRowCount(2);
    channelTable_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    channelTable_->setMaximumHeight(90);
    channelProblem_->setObjectName(QStringLiteral("channelProblem"));
    channelProblem_->setStyleSheet(QStringLiteral("color: #b00020"));
    channelProblem_->setWordWrap(true);
    drive_->setObjectName(QStringLiteral("driveOnRig"));
    driving_ = new DrivingInput(this);
    driveTimer_ = new QTimer(this);
    driveTimer_->setInterval(25);
    connect(driveTimer_, &QTimer::timeout, this, &RigPanel::driveTick);
    runTrial_->setObjectName(QStringLiteral("runOnRig"));
    stopTrial_->setObjectName(QStringLiteral("stopOnRig"));
    trialInfo_->setObjectName(QStringLiteral("rigTrialInfo"));
    trialInfo_->setWordWrap(true);
    calibrationInfo_->setWordWrap(true);

    QSettings settings;
    source_->setCurrentIndex(settings.value("rig/source", 0).toInt());
    sourcePath_->setText(settings.value("rig/path", QStringLiteral("/dev/video0")).toString());
    width_->setValue(settings.value("rig/width", 640).toInt());
    height_->setValue(settings.value("rig/height", 480).toInt());
    fps_->setValue(settings.value("rig/fps", 60).toInt());
    exposure_->setValue(settings.value("rig/exposure", -1).toInt());
    gain_->setValue(settings.value("rig/gain", -1).toInt());
    protocol_->setCurrentIndex(settings.value("rig/protocol", 0).toInt());
    baud_->setValue(settings.value("rig/baud", 0).toInt());
    // The channel map as the operator left it: "channel:trim:min:max:reversed" per control.
    const QStringList saved = settings.value("rig/channels").toStringList();
    for (int i = 0; i < saved.size() && i < static_cast<int>(channels_.controls.size()); ++i) {
        const QStringList f = saved[i].split(QLatin1Char(':'));
        if (f.size() == 5) {
            devices::ChannelSetting s{f[0].toInt(), f[1].toDouble(), f[2].toDouble(),
                                      f[3].toDouble(), f[4] == QLatin1String("1")};
            devices::ChannelMap trial = channels_;
            trial.controls[i] = s;
            if (trial.validate().isEmpty()) {
                channels_ = trial;
            }
        }
    }

    auto* form = new QFormLayout;
    form->addRow(sourceLabel_, source_);
    form->addRow(QString(), sourcePath_);
    auto* cameraSettings = new QHBoxLayout;
    for (QSpinBox* box : {width_, height_, fps_, exposure_, gain_}) {
        cameraSettings->addWidget(box);
    }
    form->addRow(cameraSettingsLabel_, cameraSettings);
    auto* cameraButtons = new QHBoxLayout;
    cameraButtons->addWidget(startCamera_);
    cameraButtons->addWidget(stopCamera_);
    auto* calibrationButtons = new QHBoxLayout;
    calibrationButtons->addWidget(loadCalibration_);
    calibrationButtons->addWidget(saveCalibration_);
    calibrationButtons->addWidget(calibrate_);
    auto* linkForm = new QFormLayout;
    linkForm->addRow(portLabel_, port_);
    linkForm->addRow(protocolLabel_, protocol_);
    linkForm->addRow(baudLabel_, baud_);
    auto* linkButtons = new QHBoxLayout;
    linkButtons->addWidget(connect_);
    linkButtons->addWidget(disconnect_);
    auto* controls = new QVBoxLayout;
    controls->addLayout(form);
    controls->addLayout(cameraButtons);
    controls->addWidget(calibrationInfo_);
    controls->addLayout(calibrationButtons);
    controls->addLayout(linkForm);
    controls->addWidget(channelTable_);
    controls->addWidget(channelProblem_);
    controls->addLayout(linkButtons);
    controls->addWidget(linkInfo_);
    auto* trialButtons = new QHBoxLayout;
    trialButtons->addWidget(drive_);
    trialButtons->addWidget(runTrial_);
    trialButtons->addWidget(stopTrial_);
    controls->addLayout(trialButtons);
    controls->addWidget(trialInfo_);
    controls->addStretch(1);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(view_, 3);
    layout->addLayout(controls, 2);

    // The camera thread tracks every frame; the screen gets a thinned copy with the pose.
    camera_.setConsumer([this, shared = shared_, tracker = std::make_shared<devices::LedTracker>()](
                            const devices::CameraFrame& frame) {
        std::lock_guard<std::mutex> lock(shared->mutex);
        if (shared->running && shared->loop) {
            // The closed loop: pose -> controller -> link, on this thread, no queue between.
            const devices::RigStep step = shared->loop->onFrame(frame);
            shared->pose = step.pose;
            if (step.pose) {
                shared->lastTrackedPose = step.pose;
            }
            if (shared->trialStartNs < 0) {
                shared->trialStartNs = frame.steadyNs;
            }
            const double elapsed = (frame.steadyNs - shared->trialStartNs) * 1e-9;
            if (elapsed >= shared->trialSeconds || step.fault) {
                shared->running = false;
                QMetaObject::invokeMethod(this, &RigPanel::finishTrial, Qt::QueuedConnection);
            }
            return;
        }
        shared->pose = tracker->track(frame.image, shared->calibration).pose;
        if (shared->recording) {
            if (!shared->pose) {
                // No pose, no command: the car must not drive blind.
                link_.setPoseLost(true);
                shared->estimator.reset();
                return;
            }
            link_.setPoseLost(false);
            const Eigen::VectorXd state = shared->estimator.update(*shared->pose, frame.steadyNs);
            if (shared->firstFrameNs < 0) {
                shared->firstFrameNs = frame.steadyNs;
            }
            // The frame's own time: frames come at the camera's rate, and some are dropped.
            const double t = (frame.steadyNs - shared->firstFrameNs) * 1e-9;
            if (!shared->times.empty() && t <= shared->times.back()) {
                return;  // a frame out of order or repeated: no new sample
            }
            shared->times.push_back(t);
            shared->states.push_back(state);
            shared->actions.push_back(shared->driveAction);
            if (shared->stream) {
                // The crash copy keeps the demonstration format's even steps (the nominal frame
                // period); the finished take is resampled from the frames' own times. A failed
                // write is retried at the next flush; the take is in memory too.
                QString ignored;
                shared->stream->append((shared->times.size() - 1) * shared->streamDt, state,
                                       shared->driveAction, &ignored);
            }
        }
    });
    connect(&camera_, &devices::Camera::frameReady, this, &RigPanel::showFrame);
    connect(&camera_, &devices::Camera::failed, this,
            [this](const QString& message) { linkInfo_->setText(message); });
    connect(&link_, &devices::TransmitterLink::statusChanged, this, &RigPanel::showLinkStatus);
    connect(startCamera_, &QPushButton::clicked, this, &RigPanel::startCamera);
    connect(stopCamera_, &QPushButton::clicked, this, &RigPanel::stopCamera);
    connect(connect_, &QPushButton::clicked, this, &RigPanel::connectLink);
    connect(disconnect_, &QPushButton::clicked, this, &RigPanel::disconnectLink);
    connect(source_, &QComboBox::currentIndexChanged, this, &RigPanel::retranslateUi);
    connect(loadCalibration_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Open floor calibration"),
                                                          QString(), tr("Calibrations (*.json)"));
        if (!path.isEmpty()) {
            loadCalibration(path);
        }
    });
    connect(saveCalibration_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save floor calibration"),
                                                          QString(), tr("Calibrations (*.json)"));
        if (!path.isEmpty()) {
            saveCalibration(path);
        }
    });
    connect(calibrate_, &QPushButton::toggled, this, [this](bool on) {
        if (on) {
            clicked_.clear();
        }
        view_->setCalibrating(on);
    });
    connect(view_, &CameraView::imagePointClicked, this, [this](const QPointF& image) {
        bool ok = false;
        const QString text = QInputDialog::getText(
            this, tr("Floor point"),
            tr("Where is this point on the floor? x, y in metres (e.g. 1.5, -0.2):"),
            QLineEdit::Normal, QString(), &ok);
        if (!ok) {
            return;
        }
        const QStringList parts = text.split(QLatin1Char(','));
        bool okX = false, okY = false;
        const double x = parts.value(0).trimmed().toDouble(&okX);
        const double y = parts.value(1).trimmed().toDouble(&okY);
        if (parts.size() != 2 || !okX || !okY) {
            QMessageBox::warning(this, tr("Floor point"),
                                 tr("'%1' is not two numbers \"x, y\" in metres.").arg(text));
            return;
        }
        addCalibrationPoint(image, QPointF(x, y));
    });
    connect(&session_, &LabSession::demonstrationChanged, this, &RigPanel::showTask);
    connect(runTrial_, &QPushButton::clicked, this, &RigPanel::runTrial);
    drive_->setCheckable(true);
    connect(drive_, &QPushButton::clicked, this, [this](bool on) {
        if (on) {
            if (!startDriving()) {
                drive_->setChecked(false);
            }
        } else {
            stopDriving();
        }
    });
    connect(channelTable_, &QTableWidget::itemChanged, this, &RigPanel::applyChannels);
    connect(stopTrial_, &QPushButton::clicked, this, &RigPanel::stopTrial);

    // Until the operator calibrates, the synthetic camera's own calibration.
    calibration_ = devices::syntheticCeilingCamera();
    shared_->calibration = calibration_;
    view_->setCalibration(calibration_);
    refreshPorts();
    retranslateUi();
    showChannels();
    showTask();
    showLinkStatus(linkStatus_);
}

RigPanel::~RigPanel() {
    // The session may already be gone (the window deletes it first): a recording in progress is
    // kept on disk, not handed to the session.
    driveTimer_->stop();
    driving_->stop();
    {
        std::lock_guard<std::mutex> lock(shared_->mutex);
        shared_->running = false;
        shared_->recording = false;
        if (shared_->stream) {
            QString ignored;
            shared_->stream->close(&ignored);
        }
    }
    camera_.stop();
    disconnectLink();
}

bool RigPanel::runTrial() {
    if (isRunning()) {
        return false;
    }
    QString missing;
    if (!camera_.isRunning()) {
        missing = tr("Start the camera first.");
    } else if (!linkStatus_.connected) {
        missing = tr("Connect the transmitter link first.");
    } else if (!session_.profile().info.pose) {
        missing = tr("The rig drives a car: choose the slide-car as the target.");
    } else if (sim::MethodCatalog::get(session_.method()).simulationOnly) {
        missing = tr("The oracle plans on copies of a simulated plant; a real car has none. "
                     "Run it in simulation, or choose another method.");
    } else if (sim::trainsOffline(session_.method())) {
        missing = tr("%1 trains offline in simulation; run it there, or choose another method.")
                      .arg(session_.method());
    }
    if (!missing.isEmpty()) {
        trialInfo_->setText(missing);
        return false;
    }
    std::lock_guard<std::mutex> lock(shared_->mutex);
    // One loop per method: learners keep what they learnt from trial to trial (warm start).
    if (!shared_->loop || loopMethod_ != session_.method()) {
        auto controller = sim::MethodCatalog::create(
            session_.method(), session_.profile(), session_.demonstration(), session_.fit().b);
        shared_->loop = std::make_unique<devices::RigLoop>(calibration_, devices::TrackerSettings{},
                                                           std::move(controller), channels_, link_);
        shared_->loop->setLostTrackDistance(session_.profile().lostTrackDistance);
        loopMethod_ = session_.method();
        trials_ = 0;
    }
    shared_->loop->startTrial(sim::resetForTrial(trials_));
    if (car_) {
        car_->requestReset(static_cast<std::uint64_t>(trials_ + 1));  // the car back at the start
    }
    const auto demo = session_.demonstration();
    const double seconds = demo->length() * demo->dt + session_.profile().settleTime;
    shared_->trialSeconds = seconds;
    shared_->trialStartNs = -1;
    shared_->lastTrackedPose.reset();
    shared_->running = true;
    ++trials_;
    trialInfo_->setText(tr("Trial %1 running...").arg(trials_));
    runTrial_->setEnabled(false);
    return true;
}

const Eigen::VectorXd& RigPanel::drivingInput() const {
    return driving_->input();
}

bool RigPanel::startDriving() {
    if (drivingActive_ || isRunning()) {
        return false;
    }
    if (!camera_.isRunning() || !linkStatus_.connected) {
        trialInfo_->setText(!camera_.isRunning() ? tr("Start the camera first.")
                                                 : tr("Connect the transmitter link first."));
        return false;
    }
    const sim::PlantInfo& info = session_.profile().info;
    const QString path =
        RecordPanel::recordingsFolder() +
        QStringLiteral("/rig-%1.csv")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    QDir().mkpath(RecordPanel::recordingsFolder());
    // The header of the demonstration format, on disk at once; rows follow as they are
    // recorded. dt in the streamed header is the camera's nominal frame period; the finished
    // recording is resampled onto the measured one.
    core::Demonstration header =
        sim::DemonstrationRecorder(info, nominalFramePeriod_).demonstration();
    header.metadata.insert(QStringLiteral("source"), QStringLiteral("recorded on the rig"));
    auto stream = std::make_unique<core::DemonstrationStream>();
    QString error;
    if (!stream->open(path, header, &error)) {
        trialInfo_->setText(tr("Cannot record to %1").arg(error));
        return false;
    }
    {
        std::lock_guard<std::mutex> lock(shared_->mutex);
        shared_->states.clear();
        shared_->actions.clear();
        shared_->times.clear();
        shared_->firstFrameNs = -1;
        shared_->estimator.reset();
        shared_->driveAction = Eigen::VectorXd::Zero(info.actionDimension());
        shared_->stream = std::move(stream);
        shared_->streamDt = nominalFramePeriod_;
        shared_->recording = true;
    }
    if (car_) {
        car_->requestReset(1);
    }
    driving_->start(info.actionDimension());
    drivingActive_ = true;
    driveTimer_->start();
    trialInfo_->setText(
        tr("Driving and recording: arrows or WASD (or a gamepad); press Drive "
           "again to stop."));
    drive_->setChecked(true);
    return true;
}

void RigPanel::driveTick() {
    const Eigen::VectorXd& input = driving_->advance(driveTimer_->interval() / 1000.0);
    {
        std::lock_guard<std::mutex> lock(shared_->mutex);
        shared_->driveAction = input;
    }
    link_.setCommand(channels_.command(input));
}

void RigPanel::stopDriving() {
    if (!drivingActive_) {
        return;
    }
    driveTimer_->stop();
    driving_->stop();
    drivingActive_ = false;
    drive_->setChecked(false);
    link_.setCommand(channels_.failsafe());  // neutral now; stale (failsafe) after that
    std::vector<Eigen::VectorXd> states, actions;
    std::vector<double> times;
    QString path;
    {
        std::lock_guard<std::mutex> lock(shared_->mutex);
        shared_->recording = false;
        if (shared_->stream) {
            path = shared_->stream->fileName();
            QString ignored;  // the file is rewritten below from the samples in memory
            shared_->stream->close(&ignored);
            shared_->stream.reset();
        }
        states.swap(shared_->states);
        actions.swap(shared_->actions);
        times.swap(shared_->times);
    }
    if (states.size() < 2) {
        QFile::remove(path);
        trialInfo_->setText(tr("Nothing recorded (no pose seen)."));
        return;
    }
    // The frames' own times onto one uniform step (the camera's median frame interval).
    core::Demonstration demo = sim::DemonstrationRecorder::fromTimedSamples(
        session_.profile().info, times, states, actions);
    demo.metadata.insert(QStringLiteral("source"), QStringLiteral("recorded on the rig"));
    // The streamed file (frame times as they came, kept for a crash) becomes the uniform one.
    core::FileError writeError;
    if (!core::writeDemonstrationCsv(demo, path, &writeError)) {
        trialInfo_->setText(tr("The rig recording could not be saved: %1").arg(writeError.toString()));
        return;
    }
    try {
        session_.setDemonstration(std::make_shared<core::Demonstration>(std::move(demo)), path);
    } catch (const std::exception& e) {
        trialInfo_->setText(tr("The rig recording could not be used: %1. It is kept in %2.")
                                .arg(QString::fromStdString(e.what()),
                                     QDir::toNativeSeparators(path)));
        return;
    }
    trialInfo_->setText(tr("Recorded %1 samples on the rig, kept in %2; it is now the "
                           "demonstration.")
                            .arg(states.size())
                            .arg(QDir::toNativeSeparators(path)));
}

void RigPanel::stopTrial() {
    bool was = false;
    {
        std::lock_guard<std::mutex> lock(shared_->mutex);
        was = shared_->running;
        shared_->running = false;
    }
    if (was) {
        finishTrial();
    }
}

void RigPanel::emergencyStop() {
    link_.emergencyStop();  // failsafe from the link's next frame, latched
    driving_->neutral();
    stopDriving();
    stopTrial();
    trialInfo_->setText(tr("E-STOP: the transmitter sends failsafe until E-STOP is reset."));
}

void RigPanel::resetEmergencyStop() {
    link_.resetEmergencyStop();
}

bool RigPanel::isRunning() const {
    std::lock_guard<std::mutex> lock(shared_->mutex);
    return shared_->running;
}

QString RigPanel::lastResult() const {
    return lastResult_;
}

void RigPanel::finishTrial() {
    std::optional<devices::PlanarPose> last;
    {
        std::lock_guard<std::mutex> lock(shared_->mutex);
        last = shared_->lastTrackedPose;
    }
    const auto demo = session_.demonstration();
    const auto& pose = session_.profile().info.pose;
    if (last && demo && pose) {
        const sim::ParkingError parked = sim::parkingError(session_.profile().info, *demo,
                                                           last->x, last->y, last->heading);
        lastResult_ = tr("Trial %1: parked %2 cm from the lot, heading off by %3°")
                          .arg(trials_)
                          .arg(parked.position * 100.0, 0, 'f', 1)
                          .arg(parked.heading * 180.0 / core::kPi, 0, 'f', 1);
    } else {
        lastResult_ = tr("Trial %1 ended without a pose").arg(trials_);
    }
    trialInfo_->setText(lastResult_);
    runTrial_->setEnabled(true);
    emit trialFinished(lastResult_);
}

void RigPanel::refreshPorts() {
    const QString current = port_->currentText();
    port_->clear();
    if (car_) {
        port_->addItem(car_->portPath());
    }
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts()) {
        port_->addItem(info.systemLocation());
    }
    port_->setEditText(current.isEmpty() ? QSettings().value("rig/port").toString() : current);
}

QString RigPanel::virtualPort() const {
    return car_ ? car_->portPath() : QString();
}

void RigPanel::startCamera() {
    if (camera_.isRunning()) {
        return;
    }
    const auto source = static_cast<Source>(source_->currentData().toInt());
    QSettings().setValue("rig/source", source_->currentIndex());
    QSettings().setValue("rig/path", sourcePath_->text());
    std::unique_ptr<devices::CameraSource> camera;
    if (source == Source::Virtual) {
        if (!car_) {
            auto car = std::make_shared<rigsim::VirtualCar>(devices::RcProtocol::Crsf,
                                                    devices::ChannelMap::car(), 1, 1.0);
            QString error;
            if (!car->open(&error)) {
                QMessageBox::warning(this, tr("Camera"), error);
                return;
            }
            car_ = car;
            refreshPorts();
            port_->setEditText(car_->portPath());
        }
        car_->reset(1);
        camera = devices::makeSyntheticSource(
            [car = car_](double t) { return std::optional<devices::PlanarPose>(car->poseAt(t)); },
            devices::syntheticCeilingCamera(), {}, kVirtualCameraFps);
        nominalFramePeriod_ = 1.0 / kVirtualCameraFps;
    } else if (source == Source::Device) {
        devices::V4l2Settings settings;
        settings.device = sourcePath_->text();
        settings.width = width_->value();
        settings.height = height_->value();
        settings.fps = fps_->value();
        nominalFramePeriod_ = 1.0 / settings.fps;
        settings.exposure = exposure_->value();
        settings.gain = gain_->value();
        QSettings s;
        s.setValue("rig/width", settings.width);
        s.setValue("rig/height", settings.height);
        s.setValue("rig/fps", fps_->value());
        s.setValue("rig/exposure", exposure_->value());
        s.setValue("rig/gain", gain_->value());
        camera = devices::makeV4l2Source(settings);
    } else {
        camera = devices::makeVideoFileSource(sourcePath_->text(), true);
    }
    camera_.start(std::shared_ptr<devices::CameraSource>(std::move(camera)));
}

void RigPanel::stopCamera() {
    camera_.stop();
}

void RigPanel::connectLink() {
    devices::LinkSettings settings;
    settings.port = port_->currentText().trimmed();
    if (settings.port.isEmpty()) {
        linkInfo_->setText(tr("Choose or type the transmitter's port first."));
        return;
    }
    settings.protocol = static_cast<devices::RcProtocol>(protocol_->currentData().toInt());
    settings.failsafe = channels_.failsafe();
    settings.baud = baud_->value();
    QSettings().setValue("rig/baud", baud_->value());
    settings.sendOnCommand = true;  // a camera frame's command goes out at once
    QSettings().setValue("rig/port", settings.port);
    QSettings().setValue("rig/protocol", protocol_->currentIndex());
    link_.start(settings);
}

void RigPanel::disconnectLink() {
    link_.stop();
}

bool RigPanel::loadCalibration(const QString& path) {
    QString error;
    const auto loaded = devices::FloorCalibration::load(path, &error);
    if (!loaded) {
        QMessageBox::warning(this, tr("Floor calibration"),
                             tr("The calibration could not be read.\n\n%1").arg(error));
        return false;
    }
    calibration_ = *loaded;
    {
        std::lock_guard<std::mutex> lock(shared_->mutex);
        shared_->calibration = calibration_;
    }
    view_->setCalibration(calibration_);
    retranslateUi();
    return true;
}

bool RigPanel::saveCalibration(const QString& path) {
    QString error;
    if (!calibration_.save(path, &error)) {
        QMessageBox::warning(this, tr("Floor calibration"), error);
        return false;
    }
    return true;
}

void RigPanel::addCalibrationPoint(const QPointF& image, const QPointF& floor) {
    clicked_.push_back({{image.x(), image.y()}, {floor.x(), floor.y()}});
    if (clicked_.size() < 4) {
        calibrationInfo_->setText(
            tr("%1 point(s) clicked; at least 4 are needed.").arg(clicked_.size()));
        return;
    }
    QString error;
    const auto fit = devices::FloorCalibration::fit(clicked_, &error);
    if (!fit) {
        calibrationInfo_->setText(error);
        return;
    }
    calibration_ = *fit;
    {
        std::lock_guard<std::mutex> lock(shared_->mutex);
        shared_->calibration = calibration_;
    }
    view_->setCalibration(calibration_);
    retranslateUi();
}

std::optional<devices::PlanarPose> RigPanel::lastPose() const {
    std::lock_guard<std::mutex> lock(shared_->mutex);
    return shared_->pose;
}

void RigPanel::showFrame(const devices::CameraFrame& frame) {
    view_->setFrame(toImage(frame.image), lastPose());
}

void RigPanel::showLinkStatus(const devices::LinkStatus& status) {
    linkStatus_ = status;
    QString text = status.connected ? tr("Link: connected, %1 frames/s, %2 sent")
                                          .arg(status.measuredRateHz, 0, 'f', 0)
                                          .arg(status.framesSent)
                                    : tr("Link: not connected");
    if (status.connected && status.failsafe != devices::FailsafeReason::None) {
        text += tr("; failsafe (%1)").arg(devices::failsafeReasonText(status.failsafe));
    }
    if (!status.lastError.isEmpty()) {
        text += QStringLiteral("\n") + status.lastError;
    }
    linkInfo_->setText(text);
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

void RigPanel::showChannels() {
    updatingChannels_ = true;
    const QStringList names = session_.profile().info.actionNames;
    channelTable_->setVerticalHeaderLabels({names.value(0), names.value(1)});
    for (int row = 0; row < 2 && row < static_cast<int>(channels_.controls.size()); ++row) {
        const devices::ChannelSetting& s = channels_.controls[row];
        const QStringList cells = {QString::number(s.channel + 1), QString::number(s.trim),
                                   QString::number(s.minimum), QString::number(s.maximum)};
        for (int col = 0; col < 4; ++col) {
            channelTable_->setItem(row, col, new QTableWidgetItem(cells[col]));
        }
        auto* reversed = new QTableWidgetItem;
        reversed->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
        reversed->setCheckState(s.reversed ? Qt::Checked : Qt::Unchecked);
        channelTable_->setItem(row, 4, reversed);
    }
    updatingChannels_ = false;
}

void RigPanel::applyChannels() {
    if (updatingChannels_) {
        return;
    }
    devices::ChannelMap edited = channels_;
    QString problem;
    for (int row = 0; row < 2 && row < static_cast<int>(edited.controls.size()); ++row) {
        double values[4] = {};
        for (int col = 0; col < 4; ++col) {
            bool ok = false;
            const QTableWidgetItem* item = channelTable_->item(row, col);
            values[col] = item ? item->text().toDouble(&ok) : 0.0;
            if (!ok) {
                problem = tr("'%1' is not a number").arg(item ? item->text() : QString());
            }
        }
        devices::ChannelSetting& s = edited.controls[row];
        s.channel = static_cast<int>(values[0]) - 1;
        s.trim = values[1];
        s.minimum = values[2];
        s.maximum = values[3];
        s.reversed =
            channelTable_->item(row, 4) && channelTable_->item(row, 4)->checkState() == Qt::Checked;
    }
    if (problem.isEmpty()) {
        problem = edited.validate();
    }
    channelProblem_->setText(problem);
    if (!problem.isEmpty()) {
        return;  // nothing half-applied
    }
    channels_ = edited;
    QStringList saved;
    for (const devices::ChannelSetting& s : channels_.controls) {
        saved << QStringLiteral("%1:%2:%3:%4:%5")
                     .arg(s.channel)
                     .arg(s.trim)
                     .arg(s.minimum)
                     .arg(s.maximum)
                     .arg(s.reversed ? 1 : 0);
    }
    QSettings().setValue("rig/channels", saved);
    // A new map takes effect on the next trial (the loop is rebuilt with it).
    std::lock_guard<std::mutex> lock(shared_->mutex);
    if (!shared_->running) {
        shared_->loop.reset();
    }
}

void RigPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void RigPanel::retranslateUi() {
    sourceLabel_->setText(tr("Camera:"));
    source_->setItemText(0, tr("Virtual rig (synthetic camera, simulated car)"));
    source_->setItemText(1, tr("Camera device (V4L2)"));
    source_->setItemText(2, tr("Video file"));
    const auto source = static_cast<Source>(source_->currentData().toInt());
    sourcePath_->setEnabled(source != Source::Virtual);
    for (QSpinBox* box : {width_, height_, fps_, exposure_, gain_}) {
        box->setEnabled(source == Source::Device);
    }
    cameraSettingsLabel_->setText(tr("Device:"));
    width_->setToolTip(tr("Width [px] asked of the camera"));
    height_->setToolTip(tr("Height [px] asked of the camera"));
    fps_->setSuffix(tr(" fps"));
    fps_->setToolTip(tr("Frame rate asked of the camera"));
    exposure_->setSpecialValueText(tr("auto exposure"));
    exposure_->setToolTip(
        tr("Exposure in the driver's units; lowest: the driver's automatic "
           "exposure. IR LEDs track best with a short exposure."));
    gain_->setSpecialValueText(tr("auto gain"));
    gain_->setToolTip(tr("Gain in the driver's units; lowest: leave the driver's"));
    sourcePath_->setPlaceholderText(source == Source::Device ? tr("/dev/video0")
                                                             : tr("path of a video file"));
    startCamera_->setText(tr("Start camera"));
    stopCamera_->setText(tr("Stop camera"));
    calibrationInfo_->setText(tr("Floor calibration: %1 points, reprojection error %2 cm")
                                  .arg(calibration_.points.size())
                                  .arg(calibration_.rmsMetres * 100.0, 0, 'f', 2));
    loadCalibration_->setText(tr("Open..."));
    saveCalibration_->setText(tr("Save..."));
    calibrate_->setText(tr("Calibrate"));
    calibrate_->setToolTip(
        tr("Click four or more floor points of known position on the camera image"));
    portLabel_->setText(tr("Transmitter port:"));
    port_->setToolTip(tr("A serial port found on this computer, or type a device path"));
    protocolLabel_->setText(tr("Protocol:"));
    connect_->setText(tr("Connect"));
    disconnect_->setText(tr("Disconnect"));
    baudLabel_->setText(tr("Baud rate:"));
    baud_->setSpecialValueText(tr("protocol default"));
    baud_->setToolTip(tr("0: the protocol's own (CRSF 420000; SBUS and Multiprotocol 100000 8E2)"));
    channelTable_->setHorizontalHeaderLabels(
        {tr("CH"), tr("trim [µs]"), tr("min [µs]"), tr("max [µs]"), tr("reversed")});
    channelTable_->setToolTip(
        tr("Which transmitter channel each control drives, its trim, its "
           "travel limits and its direction"));
    drive_->setText(tr("Drive and record"));
    drive_->setToolTip(
        tr("Drive the car through the link (arrows or WASD, or a gamepad) and "
           "record a demonstration from the camera"));
    runTrial_->setText(tr("Run a trial on the rig"));
    runTrial_->setToolTip(
        tr("The session's method drives the car through the link, with the "
           "camera's pose as its state"));
    stopTrial_->setText(tr("Stop the trial"));
}

}  // namespace prisca::app
