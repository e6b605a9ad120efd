#include "app/widgets/CameraView.h"

#include <QMouseEvent>
#include <QPainter>

#include <cmath>

namespace prisca::app {

CameraView::CameraView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("cameraView"));
    setMinimumSize(240, 180);  // fits the Rig dock at 1280 x 800
}

void CameraView::setFrame(const QImage& image, const std::optional<devices::PlanarPose>& pose) {
    image_ = image;
    pose_ = pose;
    update();
}

void CameraView::setFrame(const cv::Mat& m, const std::optional<devices::PlanarPose>& pose) {
    QImage image;
    if (m.type() == CV_8UC1) {
        image = QImage(m.data, m.cols, m.rows, static_cast<int>(m.step), QImage::Format_Grayscale8)
                    .copy();
    } else if (m.type() == CV_8UC3) {
        image =
            QImage(m.data, m.cols, m.rows, static_cast<int>(m.step), QImage::Format_BGR888).copy();
    }
    setFrame(image, pose);
}

void CameraView::setCalibration(const devices::FloorCalibration& calibration) {
    calibration_ = calibration;
    hasCalibration_ = true;
    update();
}

void CameraView::setTask(const QVector<QPointF>& path, const QPointF& lot, double lotHeading) {
    path_ = path;
    lot_ = lot;
    lotHeading_ = lotHeading;
    update();
}

void CameraView::setClickHint(const QString& hint) {
    clickHint_ = hint;
    update();
}

void CameraView::setTrail(const QVector<QPointF>& floorPoints) {
    trail_ = floorPoints;
    update();
}

void CameraView::setFence(const QVector<QPointF>& corners) {
    fence_ = corners;
    update();
}

void CameraView::setBoardCorners(const std::vector<cv::Point2f>& corners) {
    boardCorners_ = corners;
    update();
}

void CameraView::setCalibrating(bool on) {
    calibrating_ = on;
    setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
    update();
}

QRectF CameraView::imageRect() const {
    const QSizeF size = image_.isNull() ? QSizeF(640, 480) : QSizeF(image_.size());
    const double scale = std::min(width() / size.width(), height() / size.height());
    const QSizeF shown = size * scale;
    return QRectF(QPointF((width() - shown.width()) / 2, (height() - shown.height()) / 2), shown);
}

QPointF CameraView::toWidget(const cv::Point2d& p) const {
    const QRectF r = imageRect();
    const QSizeF size = image_.isNull() ? QSizeF(640, 480) : QSizeF(image_.size());
    return {r.x() + p.x * r.width() / size.width(), r.y() + p.y * r.height() / size.height()};
}

void CameraView::clearFrame() {
    image_ = QImage();
    pose_.reset();
    update();
}

void CameraView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), Qt::black);
    painter.setRenderHint(QPainter::Antialiasing);
    if (image_.isNull()) {
        painter.setPen(Qt::lightGray);
        painter.drawText(rect(), Qt::AlignCenter, tr("No camera image"));
        return;
    }
    painter.drawImage(imageRect(), image_);
    if (hasCalibration_) {
        const auto floorToWidget = [&](double x, double y) {
            return toWidget(calibration_.toImage({x, y}));
        };
        if (path_.size() > 1) {
            QPolygonF line;
            for (const QPointF& p : path_)
                line << floorToWidget(p.x(), p.y());
            painter.setPen(QPen(QColor(0x2c, 0xa0, 0x2c), 2));
            painter.drawPolyline(line);
            // The lot: 0.55 m x 0.32 m around the demonstration's final pose.
            const double c = std::cos(lotHeading_), s = std::sin(lotHeading_);
            QPolygonF lot;
            for (const auto& [dx, dy] :
                 {std::pair{0.275, 0.16}, {-0.275, 0.16}, {-0.275, -0.16}, {0.275, -0.16}}) {
                lot << floorToWidget(lot_.x() + c * dx - s * dy, lot_.y() + s * dx + c * dy);
            }
            painter.setPen(QPen(QColor(0x1f, 0x77, 0xb4), 2, Qt::DashLine));
            painter.drawPolygon(lot);
        }
        if (trail_.size() > 1) {
            QPolygonF line;
            for (const QPointF& p : trail_) {
                line << floorToWidget(p.x(), p.y());
            }
            painter.setPen(QPen(QColor(0xff, 0x8c, 0x1a, 170), 1.5));
            painter.drawPolyline(line);
        }
        if (pose_) {
            const devices::LedGeometry geometry;
            const double c = std::cos(pose_->heading), s = std::sin(pose_->heading);
            QPolygonF triangle;
            for (const cv::Point2d& led : geometry.leds) {
                triangle << floorToWidget(pose_->x + c * led.x - s * led.y,
                                          pose_->y + s * led.x + c * led.y);
            }
            painter.setPen(QPen(QColor(0xff, 0x8c, 0x1a), 2));
            painter.drawPolygon(triangle);
            painter.drawLine(floorToWidget(pose_->x, pose_->y),
                             floorToWidget(pose_->x + 0.25 * c, pose_->y + 0.25 * s));
        }
        if (!fence_.isEmpty()) {
            QPolygonF fence;
            for (const QPointF& p : fence_) {
                fence << floorToWidget(p.x(), p.y());
            }
            painter.setPen(QPen(QColor(0xe0, 0x30, 0x30), 2));
            if (fence_.size() >= 3) {
                painter.drawPolygon(fence);
            } else {
                painter.drawPolyline(fence);
            }
            for (const QPointF& w : fence) {
                painter.drawEllipse(w, 3, 3);
            }
        }
        painter.setPen(QPen(Qt::yellow, 1.5));
        for (const devices::CalibrationPoint& p : calibration_.points) {
            const QPointF w = toWidget(p.image);
            painter.drawLine(w - QPointF(6, 0), w + QPointF(6, 0));
            painter.drawLine(w - QPointF(0, 6), w + QPointF(0, 6));
        }
    }
    if (!boardCorners_.empty()) {
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(0x2c, 0xd0, 0x2c, 160));
        for (const cv::Point2f& c : boardCorners_) {
            painter.drawEllipse(toWidget({c.x, c.y}), 2.5, 2.5);
        }
        painter.setBrush(Qt::NoBrush);
    }
    painter.setPen(pose_ ? QColor(0xff, 0x8c, 0x1a) : QColor(0xe0, 0x40, 0x40));
    painter.drawText(QRectF(8, 6, width() - 16, 20), Qt::AlignLeft,
                     pose_ ? tr("x %1 m, y %2 m, heading %3°")
                                 .arg(pose_->x, 0, 'f', 3)
                                 .arg(pose_->y, 0, 'f', 3)
                                 .arg(pose_->heading * 180.0 / M_PI, 0, 'f', 1)
                           : tr("no pose (failsafe)"));
    if (calibrating_) {
        painter.setPen(Qt::yellow);
        painter.drawText(QRectF(8, height() - 26, width() - 16, 20), Qt::AlignLeft,
                         clickHint_.isEmpty()
                             ? tr("Calibrating: click a floor point whose position you know")
                             : clickHint_);
    }
}

void CameraView::mousePressEvent(QMouseEvent* event) {
    if (!calibrating_ || image_.isNull() || event->button() != Qt::LeftButton) {
        return;
    }
    const QRectF r = imageRect();
    if (!r.contains(event->position())) {
        return;
    }
    const QPointF local = event->position() - r.topLeft();
    emit imagePointClicked(
        QPointF(local.x() * image_.width() / r.width(), local.y() * image_.height() / r.height()));
}

}  // namespace prisca::app
