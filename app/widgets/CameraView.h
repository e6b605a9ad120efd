#pragma once

#include "devices/FloorCalibration.h"
#include "devices/LedTracker.h"

#include <QImage>
#include <QPointF>
#include <QVector>
#include <QWidget>

#include <optional>
#include <vector>

namespace prisca::app {

/// The live camera image with what the rig knows drawn over it through the floor calibration:
/// the tracked pose (the LED triangle and a heading arrow, or "no pose"), the desired path and
/// the parking lot, and the calibration points. In calibration mode a click reports the image
/// point under the cursor (pixels of the camera image, whatever the widget's size).
class CameraView : public QWidget {
    Q_OBJECT
  public:
    explicit CameraView(QWidget* parent = nullptr);

    void setFrame(const QImage& image, const std::optional<devices::PlanarPose>& pose);
    /// A camera's frame (8-bit grey or BGR; copied); another type shows as no image.
    void setFrame(const cv::Mat& frame, const std::optional<devices::PlanarPose>& pose);
    /// No image (the camera stopped): the view says so instead of keeping the last frame.
    void clearFrame();
    bool hasFrame() const { return !image_.isNull(); }
    void setCalibration(const devices::FloorCalibration& calibration);
    /// The demonstration's path and lot on the floor [m] (x, y) and the lot's heading [rad].
    void setTask(const QVector<QPointF>& path, const QPointF& lot, double lotHeading);
    void setCalibrating(bool on);
    /// Clicks report image points (setCalibrating's mode) with this hint shown at the bottom.
    void setClickHint(const QString& hint);
    /// The fence on the floor [m], drawn through the calibration (closed from 3 corners).
    void setFence(const QVector<QPointF>& corners);
    /// Where the car has been this trial, on the floor [m] (a replay up to its moment).
    void setTrail(const QVector<QPointF>& floorPoints);
    /// Board corners captured for the lens calibration [px]: the image's coverage.
    void setBoardCorners(const std::vector<cv::Point2f>& corners);

    QSize sizeHint() const override { return {640, 480}; }

  signals:
    /// In calibration mode: the operator clicked this image point [px].
    void imagePointClicked(const QPointF& image);

  protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;

  private:
    QRectF imageRect() const;
    QPointF toWidget(const cv::Point2d& imagePoint) const;

    QImage image_;
    std::optional<devices::PlanarPose> pose_;
    devices::FloorCalibration calibration_;
    bool hasCalibration_ = false;
    QVector<QPointF> path_;
    QVector<QPointF> trail_;  ///< floor [m]
    QPointF lot_;
    double lotHeading_ = 0.0;
    bool calibrating_ = false;
    QString clickHint_;
    QVector<QPointF> fence_;
    std::vector<cv::Point2f> boardCorners_;
};

}  // namespace prisca::app
