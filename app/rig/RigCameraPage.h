#pragma once

#include "rig/RigSession.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace prisca::rig {
class RigCalibration;
}

namespace prisca::app {

class CameraView;
class LabSession;

/// The Rig panel's "Camera and floor" page: which camera (the virtual rig's, a V4L2 device with
/// its size, rate, exposure and gain, or a video file), the camera's state, and the floor
/// calibration (open, save, or click floor points of known position on the image). It starts
/// the camera through the rig session and fits the floor through the set-up workflow; it keeps
/// only what it shows.
class RigCameraPage : public QWidget {
    Q_OBJECT
  public:
    using Source = rig::CameraRequest::Source;
    RigCameraPage(rig::RigSession& rig, rig::RigCalibration& setup, LabSession& session,
                  CameraView& view, QWidget* parent = nullptr);

    Source source() const;
    /// The source chosen and its path, as the operator reads it.
    QString sourceText() const;
    /// Starts the camera chosen (its settings remembered); false, said here and in a box, if
    /// it cannot.
    bool startCamera();
    bool cameraFailed() const { return cameraFailed_; }
    /// A video file played to its end.
    bool cameraEnded() const { return cameraEnded_; }
    /// Empty, or why the floor calibration does not fit the camera chosen.
    QString floorProblem() const;

    /// A calibration file; a bad one gets a message box and changes nothing.
    bool loadCalibration(const QString& path);
    bool saveCalibration(const QString& path);
    /// One clicked point (image px, floor m); fits from four on.
    void addCalibrationPoint(const QPointF& image, const QPointF& floor);
    /// Asks where `image` is on the floor, then adds the point.
    void askFloorPoint(const QPointF& image);
    /// Clicks on the camera image are floor points while this is on.
    bool calibrating() const;
    void setCalibrating(bool on);
    /// The controls a running camera fixes.
    void setCameraRunning(bool running);

  signals:
    /// Floor calibration by clicks switched on or off.
    void calibratingChanged(bool on);
    /// Another camera source was chosen.
    void sourceChanged();
    /// The camera's state as the status bar shows it changed (failed, ended).
    void cameraStateChanged();

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslateUi();
    void showFloor();

    rig::RigSession& rig_;
    rig::RigCalibration& setup_;
    LabSession& session_;
    CameraView& view_;
    QLabel* sourceLabel_;
    QComboBox* source_;
    QLineEdit* sourcePath_;
    QLabel* settingsLabel_;
    QSpinBox* width_;
    QSpinBox* height_;
    QSpinBox* fps_;
    QSpinBox* exposure_;
    QSpinBox* gain_;
    QLabel* cameraInfo_;
    QLabel* calibrationInfo_;
    QPushButton* loadCalibration_;
    QPushButton* saveCalibration_;
    QPushButton* calibrate_;
    bool cameraFailed_ = false;
    bool cameraEnded_ = false;
};

}  // namespace prisca::app
