#include "app/panels/ReplayDialog.h"

#include "app/widgets/ArenaView.h"
#include "app/widgets/CameraView.h"
#include "devices/Geofence.h"
#include "sim/PlantCatalog.h"

#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QImage>
#include <QJsonDocument>
#include <QKeyEvent>
#include <QLabel>
#include <QLineSeries>
#include <QPushButton>
#include <QScreen>
#include <QSlider>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include <cmath>
#include <limits>

namespace prisca::app {

ReplayDialog::ReplayDialog(rig::TrialBundle bundle, QWidget* parent)
    : QDialog(parent),
      bundle_(std::move(bundle)),
      camera_(new CameraView(this)),
      arena_(new ArenaView(this)),
      chart_(new QChart),
      cursor_(new QLineSeries),
      slider_(new QSlider(Qt::Horizontal, this)),
      time_(new QLabel(this)),
      summary_(new QLabel(this)),
      play_(new QPushButton(this)),
      timer_(new QTimer(this)) {
    setObjectName(QStringLiteral("replayDialog"));
    setWindowTitle(tr("Replay: %1").arg(bundle_.folder));
    slider_->setObjectName(QStringLiteral("replaySlider"));
    play_->setObjectName(QStringLiteral("replayPlay"));
    // The bundle's calibration, for drawing the pose over the frames.
    QString error;
    if (const auto calibration = devices::FloorCalibration::fromJson(
            QJsonDocument(bundle_.header.value("calibration").toObject()).toJson(), &error)) {
        camera_->setCalibration(*calibration);
    }
    // The bundle reader checked the plant and that the demonstration has its pose's columns.
    const core::Demonstration& demo = *bundle_.demonstration;
    const QString plant = bundle_.header.value("plant").toString(QStringLiteral("slidecar"));
    const sim::PlantInfo info = sim::PlantCatalog::describe(plant);
    QVector<QPointF> path;
    if (info.pose) {
        for (int k = 0; k < demo.length(); ++k) {
            path << QPointF(demo.states(k, info.pose->x), demo.states(k, info.pose->y));
        }
        if (demo.length() > 0) {
            camera_->setTask(path, path.back(), demo.states(demo.length() - 1, info.pose->heading));
        }
    }
    arena_->setScene(info, bundle_.demonstration);
    // The fence the trial ran in (rig trials keep it in their header).
    if (bundle_.header.contains("fence")) {
        QString fenceError;
        if (const auto fence = devices::Geofence::fromJson(bundle_.header.value("fence").toObject(),
                                                           &fenceError)) {
            QVector<QPointF> corners;
            for (const cv::Point2d& p : fence->polygon) {
                corners << QPointF(p.x, p.y);
            }
            camera_->setFence(corners);
            arena_->setFence(corners);
        }
    }
    for (const rig::BundleSample& s : bundle_.samples) {
        trail_ << (s.found ? QPointF(s.x, s.y)
                           : QPointF(std::numeric_limits<double>::quiet_NaN(), 0.0));
    }
    // Tracking error per sample: the distance to the nearest point of the demonstration.
    auto* errorSeries = new QLineSeries;
    double largest = 0.0;
    for (const rig::BundleSample& s : bundle_.samples) {
        double best = std::numeric_limits<double>::quiet_NaN();
        if (s.found) {
            best = std::numeric_limits<double>::infinity();
            for (const QPointF& p : path) {
                best = std::min(best, std::hypot(s.x - p.x(), s.y - p.y()));
            }
            errorSeries->append(s.t, best);
            largest = std::max(largest, best);
        }
        errors_.push_back(best);
    }
    const double seconds = bundle_.samples.empty() ? 1.0 : bundle_.samples.back().t;
    chart_->addSeries(errorSeries);
    chart_->addSeries(cursor_);
    errorSeries->setName(tr("distance from the path [m]"));
    cursor_->setName(tr("now"));
    auto* x = new QValueAxis;
    auto* y = new QValueAxis;
    x->setTitleText(tr("trial time [s]"));
    y->setTitleText(tr("error [m]"));
    x->setRange(0.0, std::max(seconds, 0.1));
    y->setRange(0.0, std::max(largest * 1.1, 0.05));
    chart_->addAxis(x, Qt::AlignBottom);
    chart_->addAxis(y, Qt::AlignLeft);
    for (QLineSeries* s : {errorSeries, cursor_}) {
        s->attachAxis(x);
        s->attachAxis(y);
    }
    auto* chartView = new QChartView(chart_, this);
    chartView->setRenderHint(QPainter::Antialiasing);
    chartView->setMinimumHeight(150);
    chart_->legend()->setAlignment(Qt::AlignRight);

    slider_->setRange(0, std::max(0, sampleCount() - 1));
    connect(slider_, &QSlider::valueChanged, this, &ReplayDialog::showSample);
    connect(play_, &QPushButton::clicked, this, [this] {
        if (timer_->isActive()) {
            timer_->stop();
        } else {
            if (slider_->value() >= slider_->maximum()) {
                slider_->setValue(0);
            }
            timer_->start();
        }
        play_->setText(timer_->isActive() ? tr("Pause") : tr("Play"));
    });
    timer_->setInterval(25);
    connect(timer_, &QTimer::timeout, this, [this] {
        if (slider_->value() >= slider_->maximum()) {
            timer_->stop();
            play_->setText(tr("Play"));
            return;
        }
        slider_->setValue(slider_->value() + 1);
    });
    play_->setText(tr("Play"));

    const QJsonObject summary = rig::summarizeBundle(bundle_);
    QString text = tr("%1 trial, %2: %3 samples, %4 frames, %5 s")
                       .arg(summary.value("kind").toString(), summary.value("method").toString())
                       .arg(sampleCount())
                       .arg(bundle_.frames.size())
                       .arg(seconds, 0, 'f', 2);
    if (summary.contains("finalPositionErrorCm")) {
        text += tr("; last pose %1 cm, %2° from the lot")
                    .arg(summary.value("finalPositionErrorCm").toDouble(), 0, 'f', 1)
                    .arg(summary.value("finalHeadingErrorDeg").toDouble(), 0, 'f', 1);
    }
    const QJsonObject result = bundle_.header.value("result").toObject();
    if (!bundle_.complete()) {
        text += tr(" (incomplete: the writer stopped before the trial ended)");
    } else if (result.value("failsafe").toBool()) {
        text += tr("; ended in failsafe: %1").arg(result.value("reason").toString());
    }
    summary_->setText(text);
    summary_->setWordWrap(true);

    auto* views = new QSplitter(Qt::Horizontal, this);
    views->addWidget(camera_);
    views->addWidget(arena_);
    auto* controls = new QHBoxLayout;
    controls->addWidget(play_);
    controls->addWidget(slider_, 1);
    controls->addWidget(time_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(summary_);
    layout->addWidget(views, 3);
    layout->addWidget(chartView, 2);
    layout->addLayout(controls);
    // As large as the screen leaves (the window's E-STOP above it stays in view), at most
    // 1200 x 800.
    const QRect available = screen() ? screen()->availableGeometry() : QRect(0, 0, 1280, 800);
    resize(std::min(1200, available.width() - 40), std::min(800, available.height() - 120));
    slider_->setFocus();
    showSample(0);
}

int ReplayDialog::currentSample() const {
    return slider_->value();
}

void ReplayDialog::showSample(int index) {
    if (index < 0 || index >= sampleCount()) {
        time_->setText(tr("no samples"));
        return;
    }
    if (slider_->value() != index) {
        slider_->setValue(index);  // comes back here
        return;
    }
    const rig::BundleSample& s = bundle_.samples[static_cast<size_t>(index)];
    std::optional<devices::PlanarPose> pose;
    if (s.found) {
        pose = devices::PlanarPose{s.x, s.y, s.psi};
    }
    const QString framePath = bundle_.frameAt(static_cast<size_t>(index));
    QImage image = framePath.isEmpty() ? QImage() : QImage(framePath);
    if (image.isNull()) {
        image = QImage(640, 480, QImage::Format_Grayscale8);
        image.fill(Qt::black);
    }
    camera_->setFrame(image, pose);
    QVector<QPointF> trail;
    for (int i = 0; i <= index; ++i) {
        if (!std::isnan(trail_[i].x())) {
            trail << trail_[i];
        }
    }
    camera_->setTrail(trail);
    arena_->setTrail(trail);
    if (s.found) {
        Eigen::VectorXd state = Eigen::VectorXd::Zero(6);
        for (int i = 0; i < 6 && i < static_cast<int>(s.state.size()); ++i) {
            state[i] = s.state[static_cast<size_t>(i)];
        }
        state.head(3) << s.x, s.y, s.psi;
        Eigen::VectorXd action = Eigen::VectorXd::Zero(2);
        for (int i = 0; i < 2 && i < static_cast<int>(s.action.size()); ++i) {
            action[i] = s.action[static_cast<size_t>(i)];
        }
        arena_->showState(state, action);
    }
    const double top = chart_->axes(Qt::Vertical).isEmpty()
                           ? 1.0
                           : static_cast<QValueAxis*>(chart_->axes(Qt::Vertical).front())->max();
    cursor_->replace(QList<QPointF>{{s.t, 0.0}, {s.t, top}});
    time_->setText(tr("%1 s, frame %2%3")
                       .arg(s.t, 0, 'f', 3)
                       .arg(s.frame)
                       .arg(s.failsafe ? tr(", failsafe") : QString()));
}

void ReplayDialog::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Right) {
        slider_->setValue(slider_->value() + 1);
        return;
    }
    if (event->key() == Qt::Key_Left) {
        slider_->setValue(slider_->value() - 1);
        return;
    }
    QDialog::keyPressEvent(event);
}

}  // namespace prisca::app
