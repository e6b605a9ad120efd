#pragma once

#include <QString>
#include <QWidget>

#include <opencv2/core.hpp>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace prisca::rig {
class RigCalibration;
class RigSession;
}  // namespace prisca::rig

namespace prisca::app {

class CameraView;
class EmergencyStop;

/// The Rig panel's "Lens, latency, fence" page, the set-up a lab does once per rig: the lens
/// (chessboard views captured from the camera, fitted, or a file), the loop's latency (measured
/// through the link and camera, or declared), the fence (corners clicked on the image, a speed
/// limit, the longest lost track), and whether trials are kept as bundles. It commands the rig
/// session and the set-up workflow and shows what they say; the fence and the bundle switch are
/// remembered between runs.
class RigSetupPage : public QWidget {
    Q_OBJECT
  public:
    RigSetupPage(rig::RigSession& rig, rig::RigCalibration& setup, EmergencyStop& emergency,
                 CameraView& view, QWidget* parent = nullptr);

    /// The newest camera image, for capturing board views.
    void setNewestFrame(const cv::Mat& frame) { newestFrame_ = frame; }
    bool captureBoardView();
    /// Fits the lens, then offers to save it.
    bool fitLens();
    bool loadLens(const QString& path);

    bool measureLatency();
    /// The operator's latency [ms] for the trials to compensate (0: not declared).
    void declareLoopLatency(double milliseconds);

    void addFenceCorner(const QPointF& floor);
    /// A fence corner where the camera sees `image` [px].
    void addFenceCornerAt(const QPointF& image);
    void clearFence();
    /// Clicks on the camera image are fence corners while this is on.
    bool drawingFence() const;
    void setDrawingFence(bool on);

    void setSaveBundles(bool on);
    /// The newest trial's bundle folder (empty: none yet).
    const QString& lastBundle() const { return lastBundle_; }
    /// Where trial bundles go when they are saved.
    static QString defaultBundleFolder();

    /// The controls E-STOP or a measurement under way fixes.
    void updateButtons();

  signals:
    void drawingFenceChanged(bool on);
    /// The loop latency the trials will compensate changed (measured or declared).
    void latencyChanged();
    /// Open this bundle in a replay window.
    void replayRequested(const QString& folder);
    /// A trial's bundle could not be written (the reason).
    void bundleFailed(const QString& problem);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    /// The lens, latency, fence and bundle rows, top to bottom.
    void buildLayout();
    void retranslateUi();
    void showLens();
    void showFence();
    void fenceLimitsChanged();

    rig::RigSession& rig_;
    rig::RigCalibration& setup_;
    EmergencyStop& emergency_;
    CameraView& view_;
    cv::Mat newestFrame_;
    QLabel* lensInfo_;
    QPushButton* captureBoard_;
    QPushButton* fitLens_;
    QPushButton* loadLens_;
    QLabel* latencyInfo_;
    QPushButton* measureLatency_;
    QLabel* declaredLatencyLabel_;
    QDoubleSpinBox* declaredLatency_;
    QLabel* fenceInfo_;
    QPushButton* drawFence_;
    QPushButton* clearFence_;
    QLabel* maxSpeedLabel_;
    QDoubleSpinBox* maxSpeed_;
    QLabel* maxLostLabel_;
    QDoubleSpinBox* maxLost_;
    QCheckBox* saveBundles_;
    QPushButton* replayLast_;
    QString lastBundle_;
};

}  // namespace prisca::app
