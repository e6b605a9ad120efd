#pragma once

#include "core/DemonstrationStream.h"
#include "devices/CameraWorker.h"
#include "devices/FloorCalibration.h"
#include "devices/RigLoop.h"
#include "devices/TransmitterLink.h"

#include <QWidget>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;
class QTimer;

namespace prisca::rigsim {
class VirtualCar;
}

namespace prisca::app {

class CameraView;
class LabSession;
class DrivingInput;

/// The real rig (or the virtual one): the camera (a V4L2 device, a video file, or the virtual
/// rig's synthetic camera over a simulated car driven through the link) with the tracked pose,
/// the lot and the desired path drawn over the live image; the floor calibration (load, save,
/// or click four or more floor points of known position); the transmitter link (port chooser
/// listing real ports plus a typed path, protocol, connect, status with rate and errors).
/// The camera and the link each run on their own thread.
class RigPanel : public QWidget {
    Q_OBJECT
  public:
    explicit RigPanel(LabSession& session, QWidget* parent = nullptr);
    ~RigPanel() override;

    /// Camera sources offered.
    enum class Source { Virtual, Device, Video };
    void startCamera();
    void stopCamera();
    void connectLink();
    void disconnectLink();
    /// Loads a calibration file; a bad one gets a message box and changes nothing.
    bool loadCalibration(const QString& path);
    bool saveCalibration(const QString& path);
    /// Adds a calibration point (image px, floor m); fits once there are four or more.
    void addCalibrationPoint(const QPointF& image, const QPointF& floor);

    const devices::FloorCalibration& calibration() const { return calibration_; }
    std::optional<devices::PlanarPose> lastPose() const;
    long long framesSeen() const { return camera_.framesDelivered(); }
    const devices::LinkStatus& linkStatus() const { return linkStatus_; }
    /// The channel mapping as edited (throttle, steering); invalid edits are named and refused.
    const devices::ChannelMap& channels() const { return channels_; }
    /// The virtual car's port (empty unless the virtual rig runs).
    QString virtualPort() const;

    /// One trial of the session's method on the rig: camera pose -> controller -> link, for the
    /// demonstration's length plus the settling time. Needs the camera running and the link
    /// connected (a message says which is missing). Learners keep learning from trial to trial.
    bool runTrial();
    /// Ends the trial; the link falls to failsafe once commands stop.
    void stopTrial();
    /// E-STOP on the rig: the trial ends and the link sends failsafe, latched until
    /// resetEmergencyStop().
    void emergencyStop();
    void resetEmergencyStop();
    bool isRunning() const;
    /// The result line of the last trial ("parked ... cm from the lot").
    QString lastResult() const;

    /// Drive the car through the link with the keyboard or a gamepad and record the camera's
    /// states and the commands as a demonstration (streamed to disk as it goes); stopping makes
    /// it the session's demonstration. Needs the camera running and the link connected.
    bool startDriving();
    void stopDriving();
    bool isDriving() const { return driving_ != nullptr && drivingActive_; }
    const Eigen::VectorXd& drivingInput() const;

  signals:
    void trialFinished(const QString& result);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslateUi();
    void refreshPorts();
    void showFrame(const devices::CameraFrame& frame);
    void showLinkStatus(const devices::LinkStatus& status);
    void showTask();
    void finishTrial();
    void driveTick();
    void showChannels();
    void applyChannels();

    LabSession& session_;
    devices::Camera camera_;
    devices::TransmitterLink link_;
    std::shared_ptr<rigsim::VirtualCar> car_;
    devices::FloorCalibration calibration_;
    std::vector<devices::CalibrationPoint> clicked_;
    devices::LinkStatus linkStatus_;
    /// Shared with the camera thread: the calibration it tracks with and the pose it found.
    struct Shared {
        std::mutex mutex;
        devices::FloorCalibration calibration;
        std::optional<devices::PlanarPose> pose;
        std::unique_ptr<devices::RigLoop> loop;  ///< the closed loop while a trial runs
        bool running = false;
        // A trial lasts this long by the camera's own frame clock (whatever its frame rate).
        double trialSeconds = 0.0;
        std::int64_t trialStartNs = -1;  ///< the trial's first frame; -1 before it
        std::optional<devices::PlanarPose> lastTrackedPose;  ///< the last pose seen in the trial
        // Recording by driving: the command in force, the rows so far, the stream on disk.
        bool recording = false;
        Eigen::VectorXd driveAction;
        devices::PoseStateEstimator estimator;
        std::vector<Eigen::VectorXd> states, actions;
        std::vector<double> times;       ///< each row's frame time since the first [s]
        std::int64_t firstFrameNs = -1;  ///< the recording's first frame with a pose
        std::unique_ptr<core::DemonstrationStream> stream;
        double streamDt = 0.025;  ///< the crash copy's step (the camera's nominal period) [s]
    };
    std::shared_ptr<Shared> shared_;
    double nominalFramePeriod_ = 1.0 / 40.0;  ///< the camera's asked-for frame period [s]

    CameraView* view_;
    QLabel* sourceLabel_;
    QComboBox* source_;
    QLineEdit* sourcePath_;
    QLabel* cameraSettingsLabel_;
    QSpinBox* width_;
    QSpinBox* height_;
    QSpinBox* fps_;
    QSpinBox* exposure_;
    QSpinBox* gain_;
    QPushButton* startCamera_;
    QPushButton* stopCamera_;
    QLabel* calibrationInfo_;
    QPushButton* loadCalibration_;
    QPushButton* saveCalibration_;
    QPushButton* calibrate_;
    QLabel* portLabel_;
    QComboBox* port_;
    QLabel* protocolLabel_;
    QComboBox* protocol_;
    QPushButton* connect_;
    QPushButton* disconnect_;
    QLabel* linkInfo_;
    QLabel* baudLabel_;
    QSpinBox* baud_;
    QTableWidget* channelTable_;
    QLabel* channelProblem_;
    devices::ChannelMap channels_ = devices::ChannelMap::car();
    bool updatingChannels_ = false;
    DrivingInput* driving_ = nullptr;
    bool drivingActive_ = false;
    QTimer* driveTimer_ = nullptr;
    QPushButton* drive_;
    QPushButton* runTrial_;
    QPushButton* stopTrial_;
    QLabel* trialInfo_;
    int trials_ = 0;
    QString loopMethod_;  ///< the method the kept loop was built for
    QString lastResult_;
};

}  // namespace prisca::app
