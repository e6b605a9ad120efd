#include "app/rig/RigSetupPage.h"

#include "app/EmergencyStop.h"
#include "app/MessageLog.h"
#include "app/widgets/CameraView.h"
#include "app/widgets/ModalDialog.h"
#include "devices/Geofence.h"
#include "rig/RigCalibration.h"
#include "rig/RigSession.h"

#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QStandardPaths>
#include <QVBoxLayout>

namespace prisca::app {

namespace {

QVector<QPointF> toQt(const std::vector<cv::Point2d>& points) {
    QVector<QPointF> out;
    for (const cv::Point2d& p : points) {
        out.push_back(QPointF(p.x, p.y));
    }
    return out;
}

}  // namespace

RigSetupPage::RigSetupPage(rig::RigSession& rig, rig::RigCalibration& setup,
                           EmergencyStop& emergency, CameraView& view, QWidget* parent)
    : QWidget(parent),
      rig_(rig),
      setup_(setup),
      emergency_(emergency),
      view_(view),
      lensInfo_(new QLabel(this)),
      captureBoard_(new QPushButton(this)),
      fitLens_(new QPushButton(this)),
      loadLens_(new QPushButton(this)),
      latencyInfo_(new QLabel(this)),
      measureLatency_(new QPushButton(this)),
      declaredLatencyLabel_(new QLabel(this)),
      declaredLatency_(new QDoubleSpinBox(this)),
      fenceInfo_(new QLabel(this)),
      drawFence_(new QPushButton(this)),
      clearFence_(new QPushButton(this)),
      maxSpeedLabel_(new QLabel(this)),
      maxSpeed_(new QDoubleSpinBox(this)),
      maxLostLabel_(new QLabel(this)),
      maxLost_(new QDoubleSpinBox(this)),
      saveBundles_(new QCheckBox(this)),
      replayLast_(new QPushButton(this)) {
    setObjectName(QStringLiteral("rigSetup"));
    lensInfo_->setObjectName(QStringLiteral("lensInfo"));
    captureBoard_->setObjectName(QStringLiteral("captureBoard"));
    fitLens_->setObjectName(QStringLiteral("fitLens"));
    loadLens_->setObjectName(QStringLiteral("loadLens"));
    latencyInfo_->setObjectName(QStringLiteral("latencyInfo"));
    measureLatency_->setObjectName(QStringLiteral("measureLatency"));
    declaredLatency_->setObjectName(QStringLiteral("declaredLatency"));
    fenceInfo_->setObjectName(QStringLiteral("fenceInfo"));
    drawFence_->setObjectName(QStringLiteral("drawFence"));
    clearFence_->setObjectName(QStringLiteral("clearFence"));
    maxSpeed_->setObjectName(QStringLiteral("fenceMaxSpeed"));
    maxLost_->setObjectName(QStringLiteral("fenceMaxLost"));
    saveBundles_->setObjectName(QStringLiteral("saveBundles"));
    replayLast_->setObjectName(QStringLiteral("replayLastTrial"));
    replayLast_->setEnabled(false);
    drawFence_->setCheckable(true);
    declaredLatency_->setRange(0.0, 1000.0);
    declaredLatency_->setDecimals(1);
    declaredLatency_->setSingleStep(5.0);
    maxSpeed_->setRange(0.0, 20.0);
    maxSpeed_->setDecimals(1);
    maxSpeed_->setSingleStep(0.5);
    maxSpeed_->setSuffix(QStringLiteral(" m/s"));
    maxLost_->setRange(0.0, 10.0);
    maxLost_->setDecimals(2);
    maxLost_->setSingleStep(0.1);
    maxLost_->setSuffix(QStringLiteral(" s"));

    buildLayout();

    connect(captureBoard_, &QPushButton::clicked, this, &RigSetupPage::captureBoardView);
    connect(fitLens_, &QPushButton::clicked, this, &RigSetupPage::fitLens);
    connect(loadLens_, &QPushButton::clicked, this, [this] {
        const QString path = ModalDialog::openFileName(this, tr("Open camera intrinsics"),
                                                       QString(), tr("Camera (*.json)"));
        if (!path.isEmpty()) {
            loadLens(path);
        }
    });
    connect(measureLatency_, &QPushButton::clicked, this, &RigSetupPage::measureLatency);
    connect(declaredLatency_, &QDoubleSpinBox::editingFinished, this,
            [this] { declareLoopLatency(declaredLatency_->value()); });
    connect(&rig_, &rig::RigSession::latencyMeasured, this,
            [this](const rig::LatencyMeasurement& m) {
                updateButtons();
                if (!m.error.isEmpty()) {
                    showStatus(latencyInfo_, tr("Latency"),
                               tr("Loop latency: not measured (%1)").arg(m.error));
                    return;
                }
                // (The session compensates what it measured; the page shows it.)
                declaredLatency_->setValue(0.0);
                showStatus(latencyInfo_, tr("Latency"),
                           tr("Loop latency: %1 ms (median of %2 steps, from %3 to %4 ms, std "
                              "%5 ms); the trials compensate it")
                               .arg(m.median * 1000.0, 0, 'f', 1)
                               .arg(m.stepsSeconds.size())
                               .arg(m.min * 1000.0, 0, 'f', 1)
                               .arg(m.max * 1000.0, 0, 'f', 1)
                               .arg(m.spread * 1000.0, 0, 'f', 1));
                emit latencyChanged();
            });
    connect(drawFence_, &QPushButton::toggled, this, &RigSetupPage::drawingFenceChanged);
    connect(clearFence_, &QPushButton::clicked, this, &RigSetupPage::clearFence);
    connect(maxSpeed_, &QDoubleSpinBox::valueChanged, this, &RigSetupPage::fenceLimitsChanged);
    connect(maxLost_, &QDoubleSpinBox::valueChanged, this, &RigSetupPage::fenceLimitsChanged);
    connect(saveBundles_, &QCheckBox::toggled, this, &RigSetupPage::setSaveBundles);
    connect(replayLast_, &QPushButton::clicked, this,
            [this] { emit replayRequested(lastBundle_); });
    connect(&rig_, &rig::RigSession::bundleSaved, this,
            [this](const QString& folder, const QString& error) {
                if (!error.isEmpty()) {
                    emit bundleFailed(tr("The trial's bundle could not be written: %1").arg(error));
                    return;
                }
                lastBundle_ = folder;
                replayLast_->setEnabled(true);
            });

    const QSettings settings;
    saveBundles_->setChecked(settings.value(QStringLiteral("rig/saveBundles"), true).toBool());
    setSaveBundles(saveBundles_->isChecked());
    {
        // The fence as the operator left it (floor metres; the same floor next time).
        const QSignalBlocker speed(maxSpeed_);
        const QSignalBlocker lost(maxLost_);
        maxSpeed_->setValue(settings.value(QStringLiteral("rig/fenceMaxSpeed"), 0.0).toDouble());
        maxLost_->setValue(settings.value(QStringLiteral("rig/fenceMaxLost"), 0.0).toDouble());
    }
    setup_.setFenceLimits(maxSpeed_->value(), maxLost_->value());
    QString ignored;
    setup_.setFenceCorners(devices::Geofence::parsePolygon(
                               settings.value(QStringLiteral("rig/fence")).toString(), &ignored)
                               .value_or(std::vector<cv::Point2d>{}));
    retranslateUi();
}

void RigSetupPage::buildLayout() {
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(lensInfo_);
    auto* lensButtons = new QHBoxLayout;
    lensButtons->addWidget(captureBoard_);
    lensButtons->addWidget(fitLens_);
    lensButtons->addWidget(loadLens_);
    layout->addLayout(lensButtons);
    layout->addSpacing(12);
    layout->addWidget(latencyInfo_);
    auto* latencyRow = new QHBoxLayout;
    latencyRow->addWidget(measureLatency_);
    latencyRow->addSpacing(8);
    latencyRow->addWidget(declaredLatencyLabel_);
    latencyRow->addWidget(declaredLatency_);
    layout->addLayout(latencyRow);
    layout->addSpacing(12);
    layout->addWidget(fenceInfo_);
    auto* fenceButtons = new QHBoxLayout;
    fenceButtons->addWidget(drawFence_);
    fenceButtons->addWidget(clearFence_);
    layout->addLayout(fenceButtons);
    auto* fenceLimits = new QFormLayout;
    fenceLimits->addRow(maxSpeedLabel_, maxSpeed_);
    fenceLimits->addRow(maxLostLabel_, maxLost_);
    layout->addLayout(fenceLimits);
    layout->addSpacing(12);
    layout->addWidget(saveBundles_);
    layout->addWidget(replayLast_);
    layout->addStretch(1);
    // Room for three lines each, so the buttons below do not move as the messages change.
    for (QLabel* info : {lensInfo_, latencyInfo_, fenceInfo_}) {
        info->setWordWrap(true);
        info->setMinimumHeight(3 * info->fontMetrics().lineSpacing());
        info->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    }
}

QString RigSetupPage::defaultBundleFolder() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
        .filePath(QStringLiteral("trials"));
}

void RigSetupPage::setSaveBundles(bool on) {
    if (saveBundles_->isChecked() != on) {
        saveBundles_->setChecked(on);  // comes back here
        return;
    }
    rig_.setBundles(on ? defaultBundleFolder() : QString(), 10.0);
    QSettings().setValue(QStringLiteral("rig/saveBundles"), on);
}

bool RigSetupPage::captureBoardView() {
    const rig::SetupStep step = setup_.captureBoardView(newestFrame_);
    if (!step.ok) {
        showStatus(lensInfo_, tr("Lens"), step.message);
        return false;
    }
    view_.setBoardCorners(setup_.capturedCorners());
    showLens();
    return true;
}

bool RigSetupPage::fitLens() {
    const rig::SetupStep step = setup_.fitLens();
    if (!step.ok) {
        showStatus(lensInfo_, tr("Lens"), step.message);
        return false;
    }
    view_.setBoardCorners({});
    view_.setCalibration(rig_.calibration());
    showLens();
    const QString path = ModalDialog::saveFileName(
        this, tr("Save camera intrinsics"), QStringLiteral("camera.json"), tr("Camera (*.json)"));
    QString error;
    if (!path.isEmpty() && !setup_.saveLens(path, &error)) {
        warningBox(this, tr("Save camera intrinsics"), error);
    }
    return true;
}

bool RigSetupPage::loadLens(const QString& path) {
    const rig::SetupStep step = setup_.loadLens(path);
    if (!step.ok) {
        warningBox(this, tr("Open camera intrinsics"), step.message);
        return false;
    }
    view_.setCalibration(rig_.calibration());
    showLens();
    return true;
}

void RigSetupPage::showLens() {
    showStatus(lensInfo_, tr("Lens"), [this] { return setup_.lensSummary(); });
}

bool RigSetupPage::measureLatency() {
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
    showStatus(latencyInfo_, tr("Latency"),
               tr("Loop latency: measuring (keep the car at rest in view)..."));
    return true;
}

void RigSetupPage::declareLoopLatency(double milliseconds) {
    if (milliseconds > 0.0) {
        rig_.setLoopLatency(milliseconds / 1000.0, rig::LoopLatencySource::Declared);
        showStatus(latencyInfo_, tr("Latency"), [milliseconds] {
            return tr("Loop latency: %1 ms, declared; the trials compensate it.")
                .arg(milliseconds, 0, 'f', 1);
        });
    } else if (rig_.loopLatencySource() == rig::LoopLatencySource::Declared) {
        rig_.setLoopLatency(std::nullopt);
        showStatus(latencyInfo_, tr("Latency"), [] {
            return tr(
                "Loop latency: not declared any more (the controllers assume the "
                "profile's camera latency).");
        });
    }
    emit latencyChanged();
}

void RigSetupPage::addFenceCorner(const QPointF& floor) {
    setup_.addFenceCorner({floor.x(), floor.y()});
    showFence();
}

void RigSetupPage::addFenceCornerAt(const QPointF& image) {
    setup_.addFenceCornerAt({image.x(), image.y()});
    showFence();
}

void RigSetupPage::clearFence() {
    setup_.clearFence();
    drawFence_->setChecked(false);
    showFence();
}

bool RigSetupPage::drawingFence() const {
    return drawFence_->isChecked();
}

void RigSetupPage::setDrawingFence(bool on) {
    drawFence_->setChecked(on);
}

void RigSetupPage::fenceLimitsChanged() {
    setup_.setFenceLimits(maxSpeed_->value(), maxLost_->value());
    showFence();
}

void RigSetupPage::showFence() {
    view_.setFence(toQt(setup_.fenceCorners()));
    showStatus(fenceInfo_, tr("Fence"), [this] { return setup_.fenceSummary(); });
    QSettings settings;
    settings.setValue(QStringLiteral("rig/fence"), setup_.fencePolygonText());
    settings.setValue(QStringLiteral("rig/fenceMaxSpeed"), maxSpeed_->value());
    settings.setValue(QStringLiteral("rig/fenceMaxLost"), maxLost_->value());
}

void RigSetupPage::updateButtons() {
    measureLatency_->setEnabled(!emergency_.isLatched() && !rig_.measuringLatency());
}

void RigSetupPage::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void RigSetupPage::retranslateUi() {
    captureBoard_->setText(tr("Capture board view"));
    captureBoard_->setToolTip(
        tr("Find the 9 x 6 chessboard (40 mm squares) in the camera's "
           "image and keep its corners; capture views over the whole "
           "image, tilted, its corners too"));
    fitLens_->setText(tr("Fit lens"));
    fitLens_->setToolTip(
        tr("Fit the camera's intrinsics and distortion to the views captured; "
           "the floor calibration is fitted again through them"));
    loadLens_->setText(tr("Load lens..."));
    loadLens_->setToolTip(tr("Camera intrinsics from a file (prisca-cli calibrate-camera)"));
    measureLatency_->setText(tr("Measure latency"));
    measureLatency_->setToolTip(
        tr("With the car at rest in view and the link connected: step "
           "the throttle forward and back and time the response in "
           "the camera"));
    declaredLatencyLabel_->setText(tr("or declare:"));
    declaredLatency_->setSuffix(tr(" ms"));
    declaredLatency_->setSpecialValueText(tr("not declared"));
    declaredLatency_->setToolTip(
        tr("A latency measured elsewhere [ms], for the trials to "
           "compensate; 0: not declared"));
    drawFence_->setText(tr("Draw fence"));
    clearFence_->setText(tr("Clear fence"));
    maxSpeedLabel_->setText(tr("Speed limit:"));
    maxSpeed_->setSpecialValueText(tr("none"));
    maxLostLabel_->setText(tr("Longest lost track:"));
    maxLost_->setSpecialValueText(tr("none"));
    // Short enough for the page at 1280 px; the details in the tool tip.
    saveBundles_->setText(tr("Save every trial as a bundle"));
    saveBundles_->setToolTip(tr("Poses, commands and 10 camera frames a second, in %1; "
                                "File > Replay a trial bundle opens one")
                                 .arg(QDir::toNativeSeparators(defaultBundleFolder())));
    replayLast_->setText(tr("Replay the last trial"));
    showLens();
    if (latencyInfo_->text().isEmpty() || !rig_.loopLatency()) {
        latencyInfo_->setText(
            tr("Loop latency: not measured (the controllers assume the "
               "camera's latency)."));
    }
    showFence();
}

}  // namespace prisca::app
