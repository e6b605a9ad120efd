#include "app/RigPanel.h"

#include "app/ModalDialog.h"

#include "app/MessageLog.h"

#include "app/CameraView.h"
#include "app/ChannelMapEditor.h"
#include "app/DrivingInput.h"
#include "app/EmergencyStop.h"
#include "app/LabSession.h"
#include "app/RecordPanel.h"
#include "core/DeviationModel.h"
#include "devices/ProcessFailsafe.h"
#include "devices/SyntheticCamera.h"
#include "sim/MethodCatalog.h"
#include "sim/MethodTraining.h"
#include "sim/PlantCatalog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QStandardPaths>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QSettings>
#include <QSignalBlocker>
#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QTabWidget>
#include <QGridLayout>
#include <QScrollArea>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace prisca::app {

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

RigPanel::RigPanel(LabSession& session, EmergencyStop& emergency, QWidget* parent)
    : QWidget(parent),
      session_(session),
      emergency_(emergency),
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
      channels_(new ChannelMapEditor(this)),
      drive_(new QPushButton(this)),
      runTrial_(new QPushButton(this)),
      stopTrial_(new QPushButton(this)),
      trialInfo_(new QLabel(this)),
      lensInfo_(new QLabel(this)),
      captureBoard_(new QPushButton(this)),
      fitLens_(new QPushButton(this)),
      loadLens_(new QPushButton(this)),
      latencyInfo_(new QLabel(this)),
      measureLatency_(new QPushButton(this)),
      fenceInfo_(new QLabel(this)),
      drawFence_(new QPushButton(this)),
      clearFence_(new QPushButton(this)),
      maxSpeed_(new QDoubleSpinBox(this)),
      maxLost_(new QDoubleSpinBox(this)),
      saveBundles_(new QCheckBox(this)),
      replayLast_(new QPushButton(this)) {
    saveBundles_->setObjectName(QStringLiteral("saveBundles"));
    replayLast_->setObjectName(QStringLiteral("replayLastTrial"));
    replayLast_->setEnabled(false);
    setObjectName(QStringLiteral("rigPanel"));
    connect(&emergency_, &EmergencyStop::engaged, this, &RigPanel::emergencyStop);
    connect(&emergency_, &EmergencyStop::released, this, &RigPanel::resetEmergencyStop);
    connect(&emergency_, &EmergencyStop::latchChanged, this, [this] { updateButtons(); });
    cameraInfo_ = new QLabel(this);
    cameraInfo_->setObjectName(QStringLiteral("cameraInfo"));
    cameraInfo_->setWordWrap(true);
    statusTimer_ = new QTimer(this);
    statusTimer_->setInterval(1000);
    connect(statusTimer_, &QTimer::timeout, this, [this] {
        const long long frames = rig_.framesSeen();
        cameraFps_ = rig_.cameraRunning() ? static_cast<double>(frames - framesAtLastTick_) : 0.0;
        framesAtLastTick_ = frames;
        emitStatus();
        showReadiness();
    });
    readiness_ = new QLabel(this);
    readiness_->setObjectName(QStringLiteral("rigReadiness"));
    readiness_->setWordWrap(true);
    readiness_->setTextFormat(Qt::PlainText);
    putBack_ = new QPushButton(this);
    putBack_->setObjectName(QStringLiteral("putCarBack"));
    connect(putBack_, &QPushButton::clicked, this, &RigPanel::putVirtualCarBack);
    declaredLatency_ = new QDoubleSpinBox(this);
    declaredLatency_->setObjectName(QStringLiteral("declaredLatency"));
    declaredLatency_->setRange(0.0, 1000.0);
    declaredLatency_->setDecimals(1);
    declaredLatency_->setSingleStep(5.0);
    declaredLatencyLabel_ = new QLabel(this);
    connect(declaredLatency_, &QDoubleSpinBox::editingFinished, this,
            [this] { declareLoopLatency(declaredLatency_->value()); });
    statusTimer_->start();
    lensInfo_->setObjectName(QStringLiteral("lensInfo"));
    lensInfo_->setWordWrap(true);
    captureBoard_->setObjectName(QStringLiteral("captureBoard"));
    fitLens_->setObjectName(QStringLiteral("fitLens"));
    loadLens_->setObjectName(QStringLiteral("loadLens"));
    latencyInfo_->setObjectName(QStringLiteral("latencyInfo"));
    latencyInfo_->setWordWrap(true);
    measureLatency_->setObjectName(QStringLiteral("measureLatency"));
    fenceInfo_->setObjectName(QStringLiteral("fenceInfo"));
    fenceInfo_->setWordWrap(true);
    drawFence_->setObjectName(QStringLiteral("drawFence"));
    drawFence_->setCheckable(true);
    clearFence_->setObjectName(QStringLiteral("clearFence"));
    maxSpeed_->setObjectName(QStringLiteral("fenceMaxSpeed"));
    maxSpeed_->setRange(0.0, 20.0);
    maxSpeed_->setDecimals(1);
    maxSpeed_->setSingleStep(0.5);
    maxSpeed_->setSuffix(QStringLiteral(" m/s"));
    maxLost_->setObjectName(QStringLiteral("fenceMaxLost"));
    maxLost_->setRange(0.0, 10.0);
    maxLost_->setDecimals(2);
    maxLost_->setSingleStep(0.1);
    maxLost_->setSuffix(QStringLiteral(" s"));
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
    // The trainer-port bridge (devices/firmware): SBUS on the wire, PPM to the transmitter.
    protocol_->addItem(tr("PPM bridge (trainer port)"),
                       static_cast<int>(devices::RcProtocol::PpmBridge));
    linkInfo_->setWordWrap(true);
    baud_->setObjectName(QStringLiteral("linkBaud"));
    baud_->setRange(0, 4000000);
    baud_->setSingleStep(100000);
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

    auto* form = new QFormLayout;
    form->addRow(sourceLabel_, source_);
    form->addRow(QString(), sourcePath_);
    // Two rows (size and rate; exposure and gain): the page fits a 1280-wide window.
    auto* cameraSettings = new QHBoxLayout;
    for (QSpinBox* box : {width_, height_, fps_}) {
        cameraSettings->addWidget(box);
    }
    auto* cameraExposure = new QHBoxLayout;
    for (QSpinBox* box : {exposure_, gain_}) {
        cameraExposure->addWidget(box);
    }
    form->addRow(cameraSettingsLabel_, cameraSettings);
    form->addRow(QString(), cameraExposure);
    auto* calibrationButtons = new QHBoxLayout;
    calibrationButtons->addWidget(loadCalibration_);
    calibrationButtons->addWidget(saveCalibration_);
    calibrationButtons->addWidget(calibrate_);
    auto* linkForm = new QFormLayout;
    linkForm->addRow(portLabel_, port_);
    linkForm->addRow(protocolLabel_, protocol_);
    linkForm->addRow(baudLabel_, baud_);
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
    auto* cameraPage = new QVBoxLayout;
    cameraPage->addLayout(form);
    cameraPage->addWidget(cameraInfo_);
    cameraPage->addWidget(calibrationInfo_);
    cameraPage->addLayout(calibrationButtons);
    cameraPage->addStretch(1);
    auto* linkPage = new QVBoxLayout;
    linkPage->addLayout(linkForm);
    linkPage->addWidget(channels_);
    linkPage->addWidget(linkInfo_);
    linkPage->addStretch(1);
    // The set-up a lab does once per rig: the lens, the loop's latency, the fence.
    auto* setup = new QVBoxLayout;
    setup->addWidget(lensInfo_);
    auto* lensButtons = new QHBoxLayout;
    lensButtons->addWidget(captureBoard_);
    lensButtons->addWidget(fitLens_);
    lensButtons->addWidget(loadLens_);
    setup->addLayout(lensButtons);
    setup->addSpacing(12);
    setup->addWidget(latencyInfo_);
    auto* latencyRow = new QHBoxLayout;
    latencyRow->addWidget(measureLatency_);
    latencyRow->addSpacing(8);
    latencyRow->addWidget(declaredLatencyLabel_);
    latencyRow->addWidget(declaredLatency_);
    setup->addLayout(latencyRow);
    setup->addSpacing(12);
    setup->addWidget(fenceInfo_);
    auto* fenceButtons = new QHBoxLayout;
    fenceButtons->addWidget(drawFence_);
    fenceButtons->addWidget(clearFence_);
    setup->addLayout(fenceButtons);
    auto* fenceLimits = new QFormLayout;
    maxSpeedLabel_ = new QLabel(this);
    maxLostLabel_ = new QLabel(this);
    fenceLimits->addRow(maxSpeedLabel_, maxSpeed_);
    fenceLimits->addRow(maxLostLabel_, maxLost_);
    setup->addLayout(fenceLimits);
    setup->addSpacing(12);
    setup->addWidget(saveBundles_);
    setup->addWidget(replayLast_);
    setup->addStretch(1);
    // Room for three lines each, so the buttons below do not move as the messages change.
    for (QLabel* info : {lensInfo_, latencyInfo_, fenceInfo_}) {
        info->setMinimumHeight(3 * info->fontMetrics().lineSpacing());
        info->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    }
    tabs_ = new QTabWidget(this);
    tabs_->setObjectName(QStringLiteral("rigTabs"));
    // Each page scrolls on its own, so the buttons above stay in view at any height.
    const auto page = [this](QLayout* content, const char* name) {
        auto* widget = new QWidget;
        widget->setObjectName(QLatin1String(name));
        widget->setLayout(content);
        auto* scroll = new QScrollArea(tabs_);
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidget(widget);
        tabs_->addTab(scroll, QString());
    };
    page(cameraPage, "rigCamera");
    page(linkPage, "rigLink");
    page(setup, "rigSetup");
    auto* right = new QVBoxLayout;
    right->addLayout(top);
    right->addWidget(tabs_, 1);
    auto* layout = new QHBoxLayout(this);
    layout->addWidget(view_, 1);
    layout->addLayout(right, 1);

    connect(&rig_, &rig::RigSession::frameReady, this, &RigPanel::showFrame);
    connect(&rig_, &rig::RigSession::cameraFailed, this,
            [this](const QString& message) {
                cameraFailed_ = true;
                showStatus(cameraInfo_, tr("Camera"), message, MessageLevel::Error);
                emitStatus();
            });
    // A video played to its end is no fault: said plainly, no alarm.
    connect(&rig_, &rig::RigSession::cameraEnded, this, [this](const QString&) {
        cameraEnded_ = true;
        showStatus(cameraInfo_, tr("Camera"),
                   [frames = rig_.framesSeen()] {
                       return tr("The video ended after %1 frames; Start plays it again.").arg(frames);
                   });
        emitStatus();
    });
    connect(&rig_, &rig::RigSession::linkStatusChanged, this, &RigPanel::showLinkStatus);
    connect(&rig_, &rig::RigSession::cameraRunningChanged, this, [this](bool running) {
        updateButtons();
        if (!running) {
            view_->clearFrame();  // a stopped camera shows no stale image
            lastFrame_ = cv::Mat();
            tracking_ = false;
            if (!cameraFailed_ && !cameraEnded_) {
                showStatus(cameraInfo_, tr("Camera"), tr("Camera stopped."));
            }
        }
        emitStatus();
    });
    connect(&rig_, &rig::RigSession::trialFinished, this, &RigPanel::showTrialResult);
    connect(&rig_, &rig::RigSession::recordingFinished, this, &RigPanel::useRecording);
    connect(startCamera_, &QPushButton::clicked, this, &RigPanel::startCamera);
    connect(stopCamera_, &QPushButton::clicked, this, &RigPanel::stopCamera);
    connect(connect_, &QPushButton::clicked, this, &RigPanel::connectLink);
    connect(disconnect_, &QPushButton::clicked, this, &RigPanel::disconnectLink);
    connect(source_, &QComboBox::currentIndexChanged, this, &RigPanel::retranslateUi);
    connect(loadCalibration_, &QPushButton::clicked, this, [this] {
        const QString path = ModalDialog::openFileName(this, tr("Open floor calibration"),
                                                          QString(), tr("Calibrations (*.json)"));
        if (!path.isEmpty()) {
            loadCalibration(path);
        }
    });
    connect(saveCalibration_, &QPushButton::clicked, this, [this] {
        const QString path = ModalDialog::saveFileName(this, tr("Save floor calibration"),
                                                          QString(), tr("Calibrations (*.json)"));
        if (!path.isEmpty()) {
            saveCalibration(path);
        }
    });
    connect(calibrate_, &QPushButton::toggled, this, [this](bool on) {
        if (on) {
            clicked_.clear();
            drawFence_->setChecked(false);
        }
        // What to do, on the image itself and on the panel.
        view_->setClickHint(on ? tr("Floor calibration: click a point of known floor position") : QString());
        view_->setCalibrating(on);
        if (on) {
            showStatus(calibrationInfo_, tr("Floor calibration"), [this] {
                return tr("Calibrating: click a mark on the camera image whose floor position you "
                          "know, then type it (x, y in metres). Four or more marks spread over "
                          "the floor; the fit updates with each. Click Calibrate again when done.");
            });
        }
    });
    connect(drawFence_, &QPushButton::toggled, this, [this](bool on) {
        if (on) {
            calibrate_->setChecked(false);
        }
        view_->setClickHint(on ? tr("Fence: click its corners in order around the floor; "
                                    "click Draw fence again to finish")
                               : QString());
        view_->setCalibrating(on);
    });
    connect(clearFence_, &QPushButton::clicked, this, &RigPanel::clearFence);
    connect(maxSpeed_, &QDoubleSpinBox::valueChanged, this, &RigPanel::applyFence);
    connect(maxLost_, &QDoubleSpinBox::valueChanged, this, &RigPanel::applyFence);
    connect(captureBoard_, &QPushButton::clicked, this, &RigPanel::captureBoardView);
    connect(fitLens_, &QPushButton::clicked, this, &RigPanel::fitLens);
    connect(loadLens_, &QPushButton::clicked, this, [this] {
        const QString path = ModalDialog::openFileName(this, tr("Open camera intrinsics"),
                                                          QString(), tr("Camera (*.json)"));
        if (!path.isEmpty()) {
            loadLens(path);
        }
    });
    connect(measureLatency_, &QPushButton::clicked, this, &RigPanel::measureLatency);
    connect(saveBundles_, &QCheckBox::toggled, this, &RigPanel::setSaveBundles);
    connect(replayLast_, &QPushButton::clicked, this,
            [this] { emit replayRequested(lastBundle_); });
    connect(&rig_, &rig::RigSession::bundleSaved, this,
            [this](const QString& folder, const QString& error) {
                if (!error.isEmpty()) {
                    const QString problem =
                        tr("The trial's bundle could not be written: %1").arg(error);
                    trialInfo_->setText(trialInfo_->text() + QLatin1Char('\n') + problem);
                    logMessage(tr("Rig trial"), MessageLevel::Warning, problem);
                    return;
                }
                lastBundle_ = folder;
                replayLast_->setEnabled(true);
            });
    {
        QSettings settings;
        saveBundles_->setChecked(settings.value(QStringLiteral("rig/saveBundles"), true).toBool());
        setSaveBundles(saveBundles_->isChecked());
        // The fence as the operator left it (floor metres; the same floor next time).
        QString ignored;
        if (const auto corners = devices::Geofence::parsePolygon(
                settings.value(QStringLiteral("rig/fence")).toString(), &ignored)) {
            for (const cv::Point2d& p : *corners) {
                fenceCorners_.push_back(QPointF(p.x, p.y));
            }
        }
        const QSignalBlocker speed(maxSpeed_), lost(maxLost_);
        maxSpeed_->setValue(settings.value(QStringLiteral("rig/fenceMaxSpeed"), 0.0).toDouble());
        maxLost_->setValue(settings.value(QStringLiteral("rig/fenceMaxLost"), 0.0).toDouble());
    }
    connect(&rig_, &rig::RigSession::latencyMeasured, this,
            [this](const rig::LatencyMeasurement& m) {
                updateButtons();
                if (!m.error.isEmpty()) {
                    showStatus(latencyInfo_, tr("Latency"), tr("Loop latency: not measured (%1)").arg(m.error));
                    return;
                }
                // (The session compensates what it measured; the panel shows it.)
                declaredLatency_->setValue(0.0);
                showReadiness();
                showStatus(latencyInfo_, tr("Latency"), 
                    tr("Loop latency: %1 ms (median of %2 steps, from %3 to %4 ms, std %5 "
                       "ms); the trials compensate it")
                        .arg(m.median * 1000.0, 0, 'f', 1)
                        .arg(m.stepsSeconds.size())
                        .arg(m.min * 1000.0, 0, 'f', 1)
                        .arg(m.max * 1000.0, 0, 'f', 1)
                        .arg(m.spread * 1000.0, 0, 'f', 1));
            });
    connect(view_, &CameraView::imagePointClicked, this, [this](const QPointF& image) {
        if (drawFence_->isChecked()) {
            const cv::Point2d floor = rig_.calibration().toFloor({image.x(), image.y()});
            addFenceCorner(QPointF(floor.x, floor.y));
            return;
        }
        const std::optional<QString> answer = ModalDialog::text(
            this, tr("Floor point"),
            tr("Where is this point on the floor? x, y in metres (e.g. 1.5, -0.2):"));
        if (!answer) {
            return;
        }
        const QString& text = *answer;
        const QStringList parts = text.split(QLatin1Char(','));
        bool okX = false, okY = false;
        const double x = parts.value(0).trimmed().toDouble(&okX);
        const double y = parts.value(1).trimmed().toDouble(&okY);
        if (parts.size() != 2 || !okX || !okY) {
            warningBox(this, tr("Floor point"),
                                 tr("'%1' is not two numbers \"x, y\" in metres.").arg(text));
            return;
        }
        addCalibrationPoint(image, QPointF(x, y));
    });
    connect(&session_, &LabSession::demonstrationChanged, this, &RigPanel::showTask);
    connect(&session_, &LabSession::plantChanged, this,
            [this] { channels_->setControlNames(session_.profile().info.actionNames); });
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
    // A new map takes effect on the next trial (the loop is rebuilt with it).
    connect(channels_, &ChannelMapEditor::channelsChanged, &rig_, &rig::RigSession::setChannels);
    connect(stopTrial_, &QPushButton::clicked, this, &RigPanel::stopTrial);

    rig_.setChannels(channels_->channels());
    view_->setCalibration(rig_.calibration());
    refreshPorts();
    retranslateUi();
    channels_->setControlNames(session_.profile().info.actionNames);
    showTask();
    showLinkStatus(rig_.linkStatus());
    updateButtons();
}

RigPanel::~RigPanel() {
    // The session may already be gone (the window deletes it first): a recording in progress is
    // kept on disk by the rig session, not handed to the session.
    driveTimer_->stop();
    driving_->stop();
    disconnect(&rig_, nullptr, this, nullptr);
}

bool RigPanel::virtualCalibrationOnRealCamera() const {
    // The rig starts with the synthetic camera's calibration: right for the virtual rig, wrong
    // for any real camera until the operator calibrates it or opens its calibration.
    const auto source = static_cast<Source>(source_->currentData().toInt());
    return source != Source::Virtual &&
           rig_.calibration().toJson() == devices::syntheticCeilingCamera().toJson();
}

QString RigPanel::virtualCalibrationWarning() {
    return tr("The floor calibration is the virtual rig's, not this camera's: calibrate this "
              "camera (Calibrate, then click four or more floor points) or open its "
              "calibration before driving or a trial.");
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
                     .arg(item.ok ? QStringLiteral("✓") : item.blocking ? QStringLiteral("✗")
                                                                        : QStringLiteral("!"),
                          item.label, item.detail);
        if (!item.ok && !item.blocking) {
            advice << item.label;
        }
    }
    QString text;
    if (check.ready()) {
        text = advice.isEmpty() ? tr("Ready for a trial")
                                : tr("Ready for a trial (note: %1)").arg(advice.join(QStringLiteral(", ")));
    } else {
        text = tr("Not ready: %1").arg(check.missingLabels());
    }
    readiness_->setText(text);
    readiness_->setToolTip(lines.join(QLatin1Char('\n')));
    readiness_->setStyleSheet(
        check.ready() ? QStringLiteral("QLabel { color: #1b5e20; font-weight: bold; }")
                      : QStringLiteral("QLabel { color: #b00020; font-weight: bold; }"));
    const bool virtualCamera = static_cast<Source>(source_->currentData().toInt()) == Source::Virtual;
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

void RigPanel::declareLoopLatency(double milliseconds) {
    if (milliseconds > 0.0) {
        rig_.setLoopLatency(milliseconds / 1000.0, rig::LatencySource::Declared);
        showStatus(latencyInfo_, tr("Latency"), [milliseconds] {
            return tr("Loop latency: %1 ms, declared; the trials compensate it.")
                .arg(milliseconds, 0, 'f', 1);
        });
    } else if (rig_.loopLatencySource() == rig::LatencySource::Declared) {
        rig_.setLoopLatency(std::nullopt);
        showStatus(latencyInfo_, tr("Latency"), [] {
            return tr("Loop latency: not declared any more (the controllers assume the "
                      "profile's camera latency).");
        });
    }
    showReadiness();
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
    if (virtualCalibrationOnRealCamera()) {
        showStatus(trialInfo_, tr("Rig trial"), virtualCalibrationWarning(), MessageLevel::Warning);
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
    showStatus(trialInfo_, tr("Rig trial"), [this] {
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
    if (result.parked) {
        lastResult_ = tr("Trial %1: parked %2 cm from the lot, heading off by %3°")
                          .arg(result.trial)
                          .arg(result.parked->position * 100.0, 0, 'f', 1)
                          .arg(result.parked->heading * 180.0 / core::kPi, 0, 'f', 1);
    } else {
        lastResult_ = tr("Trial %1 ended without a pose").arg(result.trial);
    }
    if (result.stopped) {
        lastResult_ += tr(" (stopped after %1 s)").arg(result.seconds, 0, 'f', 1);
    } else if (result.fault) {
        lastResult_ += result.reason.isEmpty()
                           ? tr(" (failsafe after %1 s)").arg(result.seconds, 0, 'f', 1)
                           : tr(" (failsafe after %1 s: %2)")
                                 .arg(result.seconds, 0, 'f', 1)
                                 .arg(result.reason);
    }
    if (!result.controllerNote.isEmpty()) {
        //: A rig trial's result, then what the method says of it (which law drove, and why).
        lastResult_ = tr("%1; %2").arg(lastResult_, result.controllerNote);
    }
    showStatus(trialInfo_, tr("Rig trial"), lastResult_);
    updateButtons();
    emit trialFinished(lastResult_);
}

void RigPanel::refreshPorts() {
    const QString current = port_->currentText();
    port_->clear();
    if (!rig_.virtualPort().isEmpty()) {
        port_->addItem(rig_.virtualPort());
    }
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts()) {
        port_->addItem(info.systemLocation());
    }
    port_->setEditText(current.isEmpty() ? QSettings().value("rig/port").toString() : current);
}

void RigPanel::startCamera() {
    if (rig_.cameraRunning()) {
        return;
    }
    const auto source = static_cast<Source>(source_->currentData().toInt());
    QSettings settings;
    settings.setValue("rig/source", source_->currentIndex());
    settings.setValue("rig/path", sourcePath_->text());
    rig::CameraRequest request;
    request.source = source;
    if (source == Source::Virtual) {
        // One synthetic frame per control step of the demonstration (or of the simulations).
        const auto demo = session_.demonstration();
        const double dt = demo && demo->dt > 0.0 ? demo->dt : sim::SimulationTiming{}.controlPeriod;
        request.virtualFps = 1.0 / dt;
        // The virtual car is the session's car (a slide-car's plant file, if one is loaded).
        if (const auto parameters = session_.plantParameters();
            parameters && parameters->plant == QLatin1String("slidecar")) {
            request.virtualPlant = parameters;
        }
    } else if (source == Source::Device) {
        request.device.device = sourcePath_->text();
        request.device.width = width_->value();
        request.device.height = height_->value();
        request.device.fps = fps_->value();
        request.device.exposure = exposure_->value();
        request.device.gain = gain_->value();
        settings.setValue("rig/width", width_->value());
        settings.setValue("rig/height", height_->value());
        settings.setValue("rig/fps", fps_->value());
        settings.setValue("rig/exposure", exposure_->value());
        settings.setValue("rig/gain", gain_->value());
    } else {
        request.videoPath = sourcePath_->text();
    }
    const bool hadVirtualPort = !rig_.virtualPort().isEmpty();
    QString error;
    if (!rig_.startCamera(request, &error)) {
        cameraFailed_ = true;
        cameraInfo_->setText(error);
        warningBox(this, tr("Camera"), error);
        emitStatus();
        return;
    }
    cameraFailed_ = false;
    cameraEnded_ = false;
    if (virtualCalibrationOnRealCamera()) {
        showStatus(calibrationInfo_, tr("Floor calibration"), virtualCalibrationWarning(),
                   MessageLevel::Warning);
    }
    showStatus(cameraInfo_, tr("Camera"),
               tr("Camera started: %1").arg(source_->currentText() +
                                            (source == Source::Virtual
                                                 ? QString()
                                                 : QStringLiteral(" ") + sourcePath_->text())));
    emitStatus();
    if (!hadVirtualPort && !rig_.virtualPort().isEmpty()) {
        refreshPorts();
        port_->setEditText(rig_.virtualPort());
    }
}

void RigPanel::stopCamera() {
    rig_.stopCamera();
}

void RigPanel::connectLink() {
    devices::LinkSettings settings;
    settings.port = port_->currentText().trimmed();
    if (settings.port.isEmpty()) {
        showStatus(linkInfo_, tr("Link"), tr("Choose or type the transmitter's port first."));
        return;
    }
    settings.protocol = static_cast<devices::RcProtocol>(protocol_->currentData().toInt());
    settings.failsafe = channels_->channels().failsafe();
    settings.baud = baud_->value();
    settings.sendOnCommand = true;  // a camera frame's command goes out at once
    QSettings saved;
    saved.setValue("rig/baud", baud_->value());
    saved.setValue("rig/port", settings.port);
    saved.setValue("rig/protocol", protocol_->currentIndex());
    rig_.connectLink(settings);
}

void RigPanel::disconnectLink() {
    rig_.disconnectLink();
}

bool RigPanel::loadCalibration(const QString& path) {
    QString error;
    if (!rig_.loadCalibration(path, &error)) {
        warningBox(this, tr("Floor calibration"),
                             tr("The calibration could not be read.\n\n%1").arg(error));
        return false;
    }
    view_->setCalibration(rig_.calibration());
    retranslateUi();
    return true;
}

bool RigPanel::saveCalibration(const QString& path) {
    QString error;
    if (!rig_.saveCalibration(path, &error)) {
        warningBox(this, tr("Floor calibration"), error);
        return false;
    }
    return true;
}

void RigPanel::addCalibrationPoint(const QPointF& image, const QPointF& floor) {
    clicked_.push_back({{image.x(), image.y()}, {floor.x(), floor.y()}});
    if (clicked_.size() < 4) {
        showStatus(calibrationInfo_, tr("Floor calibration"), 
            tr("%1 point(s) clicked; at least 4 are needed.").arg(clicked_.size()));
        return;
    }
    QString error;
    const auto fit = devices::FloorCalibration::fit(clicked_, &error, lens_);
    if (!fit) {
        showStatus(calibrationInfo_, tr("Floor calibration"), error);
        return;
    }
    rig_.setCalibration(*fit);
    view_->setCalibration(rig_.calibration());
    retranslateUi();
}

void RigPanel::showFrame(const devices::CameraFrame& frame,
                         const std::optional<devices::PlanarPose>& pose) {
    lastFrame_ = frame.image;
    tracking_ = pose.has_value();
    view_->setFrame(toImage(frame.image), pose);
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
                       .arg(protocol_->currentText(), devices::failsafeReasonText(link.failsafe));
        linkAlarm = link.failsafe != devices::FailsafeReason::NoCommand;
    } else {
        linkText = tr("Link: %1 %2/s").arg(protocol_->currentText()).arg(link.measuredRateHz, 0, 'f', 0);
    }
    QString cameraText;
    bool cameraAlarm = false;
    if (rig_.cameraRunning()) {
        cameraText = tracking_ ? tr("Camera: %1 fps, tracking").arg(cameraFps_, 0, 'f', 0)
                               : tr("Camera: %1 fps, no car in view").arg(cameraFps_, 0, 'f', 0);
        cameraAlarm = !tracking_;
    } else {
        cameraText = cameraFailed_  ? tr("Camera: failed")
                     : cameraEnded_ ? tr("Camera: video ended")
                                    : tr("Camera: off");
        cameraAlarm = cameraFailed_;
    }
    emit statusSummary(linkText, linkAlarm, cameraText, cameraAlarm);
}

void RigPanel::updateButtons() {
    const bool camera = rig_.cameraRunning();
    const bool linked = rig_.linkStatus().connected;
    startCamera_->setEnabled(!camera);
    stopCamera_->setEnabled(camera);
    source_->setEnabled(!camera);
    connect_->setEnabled(!linked);
    disconnect_->setEnabled(linked);
    port_->setEnabled(!linked);
    protocol_->setEnabled(!linked);
    baud_->setEnabled(!linked);
    // Nothing that moves the car starts while E-STOP is latched.
    const bool latched = emergency_.isLatched();
    runTrial_->setEnabled(!latched && !rig_.trialRunning());
    drive_->setEnabled(!latched || drivingActive_);
    measureLatency_->setEnabled(!latched && !rig_.measuringLatency());
}

void RigPanel::showLinkStatus(const devices::LinkStatus& status) {
    if (devices::processfailsafe::held() && !emergency_.isLatched()) {
        // Stopped (Ctrl-Z) and continued: the link holds failsafe; the latch says so, and its
        // reset is the operator's taking over.
        emergency_.engage(tr("the process being stopped and continued"));
    }
    updateButtons();
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
    // The log gets the link's changes of state, not its every rate update.
    QString state = status.connected ? tr("Link: connected") : tr("Link: not connected");
    if (status.connected && status.failsafe != devices::FailsafeReason::None) {
        state += tr("; failsafe (%1)").arg(devices::failsafeReasonText(status.failsafe));
    }
    if (!status.lastError.isEmpty()) {
        state += QStringLiteral(": ") + status.lastError;
    }
    // Compared by what it means, not its words (a language switch is no change of state).
    const QString key = QStringLiteral("%1/%2/%3")
                            .arg(status.connected)
                            .arg(static_cast<int>(status.connected ? status.failsafe
                                                                   : devices::FailsafeReason::None))
                            .arg(status.lastError);
    if (key != loggedLinkState_) {
        loggedLinkState_ = key;
        logMessage(tr("Link"), status.lastError.isEmpty() ? MessageLevel::Info : MessageLevel::Warning,
                   state);
    }
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
                                  .arg(rig_.calibration().points.size())
                                  .arg(rig_.calibration().rmsMetres * 100.0, 0, 'f', 2));
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
    drive_->setText(tr("Drive and record"));
    drive_->setToolTip(
        tr("Drive the car through the link (arrows or WASD, or a gamepad) and "
           "record a demonstration from the camera"));
    runTrial_->setText(tr("Run a trial on the rig"));
    runTrial_->setToolTip(
        tr("The session's method drives the car through the link, with the "
           "camera's pose as its state"));
    stopTrial_->setText(tr("Stop the trial"));
    emitStatus();  // the status bar's fields in the new language
    showLinkStatus(rig_.linkStatus());
    protocol_->setItemText(protocol_->findData(static_cast<int>(devices::RcProtocol::PpmBridge)),
                           tr("PPM bridge (trainer port)"));
    tabs_->setTabText(0, tr("Camera and floor"));
    tabs_->setTabText(1, tr("Link"));
    tabs_->setTabText(2, tr("Lens, latency, fence"));
    captureBoard_->setText(tr("Capture board view"));
    captureBoard_->setToolTip(tr("Find the 9 x 6 chessboard (40 mm squares) in the camera's "
                                 "image and keep its corners; capture views over the whole "
                                 "image, tilted, its corners too"));
    fitLens_->setText(tr("Fit lens"));
    fitLens_->setToolTip(tr("Fit the camera's intrinsics and distortion to the views captured; "
                            "the floor calibration is fitted again through them"));
    loadLens_->setText(tr("Load lens..."));
    loadLens_->setToolTip(tr("Camera intrinsics from a file (prisca-cli calibrate-camera)"));
    measureLatency_->setText(tr("Measure latency"));
    measureLatency_->setToolTip(tr("With the car at rest in view and the link connected: step "
                                   "the throttle forward and back and time the response in "
                                   "the camera"));
    declaredLatencyLabel_->setText(tr("or declare:"));
    declaredLatency_->setSuffix(tr(" ms"));
    declaredLatency_->setSpecialValueText(tr("not declared"));
    declaredLatency_->setToolTip(tr("A latency measured elsewhere [ms], for the trials to "
                                    "compensate; 0: not declared"));
    putBack_->setText(tr("Put the car back"));
    putBack_->setToolTip(tr("The virtual car back at its start, at rest (after a trial that "
                            "left it out of view)"));
    drawFence_->setText(tr("Draw fence"));
    // Short enough for the page at 1280 px; the details in the tool tip.
    saveBundles_->setText(tr("Save every trial as a bundle"));
    saveBundles_->setToolTip(tr("Poses, commands and 10 camera frames a second, in %1; "
                                "File > Replay a trial bundle opens one")
                                 .arg(QDir::toNativeSeparators(defaultBundleFolder())));
    replayLast_->setText(tr("Replay the last trial"));
    clearFence_->setText(tr("Clear fence"));
    maxSpeedLabel_->setText(tr("Speed limit:"));
    maxSpeed_->setSpecialValueText(tr("none"));
    maxLostLabel_->setText(tr("Longest lost track:"));
    maxLost_->setSpecialValueText(tr("none"));
    showLensInfo();
    if (latencyInfo_->text().isEmpty() || !rig_.loopLatency()) {
        latencyInfo_->setText(tr("Loop latency: not measured (the controllers assume the "
                                 "camera's latency)."));
    }
    applyFence();
    showReadiness();
}

}  // namespace prisca::app

namespace prisca::app {

QString RigPanel::defaultBundleFolder() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
        .filePath(QStringLiteral("trials"));
}

void RigPanel::setSaveBundles(bool on) {
    if (saveBundles_->isChecked() != on) {
        saveBundles_->setChecked(on);  // comes back here
        return;
    }
    rig_.setBundles(on ? defaultBundleFolder() : QString(), 10.0);
    QSettings().setValue(QStringLiteral("rig/saveBundles"), on);
}

bool RigPanel::captureBoardView() {
    if (lastFrame_.empty()) {
        showStatus(lensInfo_, tr("Lens"), tr("Lens: no camera image to capture a board view from."));
        return false;
    }
    std::vector<cv::Point2f> corners = devices::findBoardCorners(lastFrame_, devices::BoardSpec{});
    if (corners.empty()) {
        showStatus(lensInfo_, tr("Lens"), tr("Lens: no whole 9 x 6 board in this view (%1 captured). Hold the "
                              "board so all of it is seen, still, and try again.")
                               .arg(boardViews_.size()));
        return false;
    }
    boardViews_.push_back(std::move(corners));
    lensImageSize_ = lastFrame_.size();
    std::vector<cv::Point2f> all;
    for (const auto& v : boardViews_) {
        all.insert(all.end(), v.begin(), v.end());
    }
    view_->setBoardCorners(all);
    showLensInfo();
    return true;
}

bool RigPanel::fitLens() {
    QString error;
    auto lens = devices::calibrateLensFromCorners(boardViews_, devices::BoardSpec{},
                                                  lensImageSize_, &error);
    if (lens) {
        if (const QString problem = lens->plausibilityProblem(); !problem.isEmpty()) {
            error = tr("refused: %1").arg(problem);
            lens.reset();
        }
    }
    if (!lens) {
        showStatus(lensInfo_, tr("Lens"), tr("Lens: %1").arg(error));
        return false;
    }
    lens_ = lens;
    boardViews_.clear();
    view_->setBoardCorners({});
    // The floor calibration's own points, fitted again through the lens.
    if (rig_.calibration().points.size() >= 4) {
        if (const auto refit = rig_.calibration().withLens(lens_, &error)) {
            rig_.setCalibration(*refit);
            view_->setCalibration(rig_.calibration());
        }
    }
    showLensInfo();
    const QString path = ModalDialog::saveFileName(this, tr("Save camera intrinsics"),
                                                      QStringLiteral("camera.json"),
                                                      tr("Camera (*.json)"));
    if (!path.isEmpty() && !lens_->save(path, &error)) {
        warningBox(this, tr("Save camera intrinsics"), error);
    }
    retranslateUi();
    return true;
}

bool RigPanel::loadLens(const QString& path) {
    QString error;
    const auto lens = devices::CameraLens::load(path, &error);
    if (!lens) {
        warningBox(this, tr("Open camera intrinsics"), error);
        return false;
    }
    lens_ = lens;
    if (rig_.calibration().points.size() >= 4) {
        if (const auto refit = rig_.calibration().withLens(lens_, &error)) {
            rig_.setCalibration(*refit);
            view_->setCalibration(rig_.calibration());
        }
    }
    showLensInfo();
    retranslateUi();
    return true;
}

void RigPanel::showLensInfo() {
    QString text;
    if (lens_) {
        text = tr("Lens: fx %1 px, k1 %2, k2 %3; RMS %4 px.")
                   .arg(lens_->matrix(0, 0), 0, 'f', 1)
                   .arg(lens_->distortion[0], 0, 'f', 3)
                   .arg(lens_->distortion[1], 0, 'f', 3)
                   .arg(lens_->rmsPixels, 0, 'f', 3);
    } else {
        text = tr("Lens: none (the floor calibration is a homography alone).");
    }
    if (!boardViews_.empty()) {
        text += QLatin1Char(' ') +
                tr("%1 board view(s) captured (at least %2; move the board over the whole "
                   "image, its corners too).")
                    .arg(boardViews_.size())
                    .arg(devices::kMinLensViews);
    }
    showStatus(lensInfo_, tr("Lens"), text);
}

bool RigPanel::measureLatency() {
    if (emergency_.isLatched()) {
        showStatus(latencyInfo_, tr("Latency"), emergency_.refusal(), MessageLevel::Warning);
        return false;
    }
    QString error;
    if (!rig_.measureLatency({}, &error)) {
        showStatus(latencyInfo_, tr("Latency"), tr("Loop latency: %1").arg(error));
        return false;
    }
    measureLatency_->setEnabled(false);
    showStatus(latencyInfo_, tr("Latency"), tr("Loop latency: measuring (keep the car at rest in view)..."));
    return true;
}

void RigPanel::addFenceCorner(const QPointF& floor) {
    fenceCorners_.push_back(floor);
    applyFence();
}

void RigPanel::clearFence() {
    fenceCorners_.clear();
    drawFence_->setChecked(false);
    applyFence();
}

void RigPanel::applyFence() {
    devices::Geofence fence;
    for (const QPointF& p : fenceCorners_) {
        fence.polygon.emplace_back(p.x(), p.y());
    }
    fence.maxSpeed = maxSpeed_->value();
    fence.maxLostSeconds = maxLost_->value();
    view_->setFence(fenceCorners_);
    QString problem = fence.problem();
    if (fence.polygon.size() < 3) {
        problem.clear();
        fence.polygon.clear();  // not a fence yet: the limits alone
    }
    if (!problem.isEmpty()) {
        showStatus(fenceInfo_, tr("Fence"), tr("Fence: %1").arg(problem));
        fence.polygon.clear();
    } else if (fenceCorners_.size() >= 3) {
        showStatus(fenceInfo_, tr("Fence"), tr("Fence: %1 corners; a car outside it ends the trial in failsafe.")
                                .arg(fenceCorners_.size()));
    } else {
        showStatus(fenceInfo_, tr("Fence"), tr("Fence: none (%1 corner(s) clicked; 3 or more make one).")
                                .arg(fenceCorners_.size()));
    }
    rig_.setGeofence(fence);
    QStringList corners;
    for (const QPointF& p : fenceCorners_) {
        corners << QStringLiteral("%1,%2").arg(p.x(), 0, 'g', 10).arg(p.y(), 0, 'g', 10);
    }
    QSettings settings;
    settings.setValue(QStringLiteral("rig/fence"), corners.join(QLatin1Char(';')));
    settings.setValue(QStringLiteral("rig/fenceMaxSpeed"), maxSpeed_->value());
    settings.setValue(QStringLiteral("rig/fenceMaxLost"), maxLost_->value());
}

}  // namespace prisca::app
