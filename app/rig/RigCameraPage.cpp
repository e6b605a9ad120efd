#include "app/rig/RigCameraPage.h"

#include "app/LabSession.h"
#include "app/MessageLog.h"
#include "app/widgets/CameraView.h"
#include "app/widgets/ModalDialog.h"
#include "rig/RigCalibration.h"
#include "sim/plants/Plant.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

namespace prisca::app {

RigCameraPage::RigCameraPage(rig::RigSession& rig, rig::RigCalibration& setup, LabSession& session,
                             CameraView& view, QWidget* parent)
    : QWidget(parent),
      rig_(rig),
      setup_(setup),
      session_(session),
      view_(view),
      sourceLabel_(new QLabel(this)),
      source_(new QComboBox(this)),
      sourcePath_(new QLineEdit(this)),
      settingsLabel_(new QLabel(this)),
      width_(new QSpinBox(this)),
      height_(new QSpinBox(this)),
      fps_(new QSpinBox(this)),
      exposure_(new QSpinBox(this)),
      gain_(new QSpinBox(this)),
      cameraInfo_(new QLabel(this)),
      calibrationInfo_(new QLabel(this)),
      loadCalibration_(new QPushButton(this)),
      saveCalibration_(new QPushButton(this)),
      calibrate_(new QPushButton(this)) {
    setObjectName(QStringLiteral("rigCamera"));
    source_->setObjectName(QStringLiteral("cameraSource"));
    sourcePath_->setObjectName(QStringLiteral("cameraPath"));
    width_->setObjectName(QStringLiteral("cameraWidth"));
    height_->setObjectName(QStringLiteral("cameraHeight"));
    fps_->setObjectName(QStringLiteral("cameraFps"));
    exposure_->setObjectName(QStringLiteral("cameraExposure"));
    gain_->setObjectName(QStringLiteral("cameraGain"));
    cameraInfo_->setObjectName(QStringLiteral("cameraInfo"));
    calibrationInfo_->setObjectName(QStringLiteral("calibrationInfo"));
    calibrate_->setObjectName(QStringLiteral("calibrate"));
    cameraInfo_->setWordWrap(true);
    calibrationInfo_->setWordWrap(true);
    calibrate_->setCheckable(true);
    width_->setRange(160, 4096);
    height_->setRange(120, 4096);
    fps_->setRange(1, 500);
    exposure_->setRange(-1, 100000);
    gain_->setRange(-1, 10000);
    for (int i = 0; i < 3; ++i) {
        source_->addItem(QString(), i);
    }
    const QSettings settings;
    source_->setCurrentIndex(settings.value("rig/source", 0).toInt());
    sourcePath_->setText(settings.value("rig/path", QStringLiteral("/dev/video0")).toString());
    width_->setValue(settings.value("rig/width", 640).toInt());
    height_->setValue(settings.value("rig/height", 480).toInt());
    fps_->setValue(settings.value("rig/fps", 60).toInt());
    exposure_->setValue(settings.value("rig/exposure", -1).toInt());
    gain_->setValue(settings.value("rig/gain", -1).toInt());

    auto* form = new QFormLayout;
    form->addRow(sourceLabel_, source_);
    form->addRow(QString(), sourcePath_);
    // Two rows (size and rate; exposure and gain): the page fits a 1280-wide window.
    auto* size = new QHBoxLayout;
    for (QSpinBox* box : {width_, height_, fps_}) {
        size->addWidget(box);
    }
    auto* exposure = new QHBoxLayout;
    for (QSpinBox* box : {exposure_, gain_}) {
        exposure->addWidget(box);
    }
    form->addRow(settingsLabel_, size);
    form->addRow(QString(), exposure);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(loadCalibration_);
    buttons->addWidget(saveCalibration_);
    buttons->addWidget(calibrate_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(cameraInfo_);
    layout->addWidget(calibrationInfo_);
    layout->addLayout(buttons);
    layout->addStretch(1);

    connect(source_, &QComboBox::currentIndexChanged, this, [this] {
        retranslateUi();
        emit sourceChanged();
    });
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
            setup_.beginFloorPoints();
            showStatus(calibrationInfo_, tr("Floor calibration"), [] {
                return tr(
                    "Calibrating: click a mark on the camera image whose floor position you "
                    "know, then type it (x, y in metres). Four or more marks spread over "
                    "the floor; the fit updates with each. Click Calibrate again when done.");
            });
        }
        emit calibratingChanged(on);
    });
    connect(&rig_, &rig::RigSession::cameraFailed, this, [this](const QString& message) {
        cameraFailed_ = true;
        showStatus(cameraInfo_, tr("Camera"), message, MessageLevel::Error);
        emit cameraStateChanged();
    });
    // A video played to its end is no fault: said plainly, no alarm.
    connect(&rig_, &rig::RigSession::cameraEnded, this, [this](const QString&) {
        cameraEnded_ = true;
        showStatus(cameraInfo_, tr("Camera"), [frames = rig_.framesSeen()] {
            return tr("The video ended after %1 frames; Start plays it again.").arg(frames);
        });
        emit cameraStateChanged();
    });
    connect(&rig_, &rig::RigSession::cameraRunningChanged, this, [this](bool running) {
        setCameraRunning(running);
        if (!running && !cameraFailed_ && !cameraEnded_) {
            showStatus(cameraInfo_, tr("Camera"), tr("Camera stopped."));
        }
    });
    retranslateUi();
}

RigCameraPage::Source RigCameraPage::source() const {
    return static_cast<Source>(source_->currentData().toInt());
}

QString RigCameraPage::sourceText() const {
    return source_->currentText() +
           (source() == Source::Virtual ? QString() : QStringLiteral(" ") + sourcePath_->text());
}

QString RigCameraPage::floorProblem() const {
    return setup_.floorProblem(source() == Source::Virtual);
}

bool RigCameraPage::startCamera() {
    if (rig_.cameraRunning()) {
        return false;
    }
    QSettings settings;
    settings.setValue("rig/source", source_->currentIndex());
    settings.setValue("rig/path", sourcePath_->text());
    rig::CameraRequest request;
    request.source = source();
    if (request.source == Source::Virtual) {
        // One synthetic frame per control step of the demonstration (or of the simulations).
        const auto demo = session_.demonstration();
        const double dt = demo && demo->dt > 0.0 ? demo->dt : sim::SimulationTiming{}.controlPeriod;
        request.virtualFps = 1.0 / dt;
        // The virtual car is the session's car (a slide-car's plant file, if one is loaded).
        if (const auto parameters = session_.plantParameters();
            parameters && parameters->plant == QLatin1String("slidecar")) {
            request.virtualPlant = parameters;
        }
    } else if (request.source == Source::Device) {
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
    QString error;
    if (!rig_.startCamera(request, &error)) {
        cameraFailed_ = true;
        cameraInfo_->setText(error);
        warningBox(this, tr("Camera"), error);
        emit cameraStateChanged();
        return false;
    }
    cameraFailed_ = false;
    cameraEnded_ = false;
    if (const QString problem = floorProblem(); !problem.isEmpty()) {
        showStatus(calibrationInfo_, tr("Floor calibration"), problem, MessageLevel::Warning);
    }
    showStatus(cameraInfo_, tr("Camera"), tr("Camera started: %1").arg(sourceText()));
    emit cameraStateChanged();
    return true;
}

bool RigCameraPage::loadCalibration(const QString& path) {
    const rig::SetupStep step = setup_.loadFloor(path);
    if (!step.ok) {
        warningBox(this, tr("Floor calibration"), step.message);
        return false;
    }
    showFloor();
    return true;
}

bool RigCameraPage::saveCalibration(const QString& path) {
    const rig::SetupStep step = setup_.saveFloor(path);
    if (!step.ok) {
        warningBox(this, tr("Floor calibration"), step.message);
        return false;
    }
    return true;
}

void RigCameraPage::addCalibrationPoint(const QPointF& image, const QPointF& floor) {
    const rig::SetupStep step =
        setup_.addFloorPoint({image.x(), image.y()}, {floor.x(), floor.y()});
    if (!step.ok) {
        showStatus(calibrationInfo_, tr("Floor calibration"), step.message);
        return;
    }
    showFloor();
}

void RigCameraPage::askFloorPoint(const QPointF& image) {
    const std::optional<QString> answer =
        ModalDialog::text(this, tr("Floor point"),
                          tr("Where is this point on the floor? x, y in metres (e.g. 1.5, -0.2):"));
    if (!answer) {
        return;
    }
    QString error;
    const auto floor = rig::RigCalibration::parseFloorPoint(*answer, &error);
    if (!floor) {
        warningBox(this, tr("Floor point"), error);
        return;
    }
    addCalibrationPoint(image, QPointF(floor->x, floor->y));
}

bool RigCameraPage::calibrating() const {
    return calibrate_->isChecked();
}

void RigCameraPage::setCalibrating(bool on) {
    calibrate_->setChecked(on);
}

void RigCameraPage::setCameraRunning(bool running) {
    source_->setEnabled(!running);
}

void RigCameraPage::showFloor() {
    view_.setCalibration(rig_.calibration());
    calibrationInfo_->setText(setup_.floorSummary());
}

void RigCameraPage::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void RigCameraPage::retranslateUi() {
    sourceLabel_->setText(tr("Camera:"));
    source_->setItemText(0, tr("Virtual rig (synthetic camera, simulated car)"));
    source_->setItemText(1, tr("Camera device (V4L2)"));
    source_->setItemText(2, tr("Video file"));
    const Source chosen = source();
    sourcePath_->setEnabled(chosen != Source::Virtual);
    for (QSpinBox* box : {width_, height_, fps_, exposure_, gain_}) {
        box->setEnabled(chosen == Source::Device);
    }
    settingsLabel_->setText(tr("Device:"));
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
    sourcePath_->setPlaceholderText(chosen == Source::Device ? tr("/dev/video0")
                                                             : tr("path of a video file"));
    calibrationInfo_->setText(setup_.floorSummary());
    loadCalibration_->setText(tr("Open..."));
    saveCalibration_->setText(tr("Save..."));
    calibrate_->setText(tr("Calibrate"));
    calibrate_->setToolTip(
        tr("Click four or more floor points of known position on the camera image"));
}

}  // namespace prisca::app
