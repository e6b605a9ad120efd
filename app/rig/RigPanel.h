#pragma once

#include "devices/ChannelMap.h"
#include "devices/FloorCalibration.h"
#include "devices/TransmitterLink.h"
#include "rig/RigSession.h"

#include <QWidget>

#include <memory>
#include <optional>

class QLabel;
class QPushButton;
class QTabWidget;
class QTimer;

namespace prisca::rig {
class RigCalibration;
}

namespace prisca::app {

class CameraView;
class DrivingInput;
class EmergencyStop;
class LabSession;
class RigCameraPage;
class RigLinkPage;
class RigSetupPage;
class RigDoctorPage;

/// The real rig (or the virtual one), shown and commanded: the camera (a V4L2 device, a video
/// file, or the virtual rig's synthetic camera over a simulated car driven through the link)
/// with the tracked pose, the lot and the desired path drawn over the live image; the floor
/// calibration (load, save, or click four or more floor points of known position); the
/// transmitter link (port chooser listing real ports plus a typed path, protocol, connect,
/// status with rate and errors); driving to record, trials. The rig itself (threads, the closed
/// loop, recording to disk, scoring, which trials may start) is the RigSession this panel owns,
/// and the set-up (floor, lens, fence) its RigCalibration workflow; the panel shows and commands
/// them: the actions and the trial strip above, the camera's image on the left, and three pages
/// (RigCameraPage, RigLinkPage, RigSetupPage).
class RigPanel : public QWidget {
    Q_OBJECT
  public:
    /// When `emergency` engages the trial and the driving end and the link sends failsafe until
    /// it is reset; nothing starts on the rig while it is latched.
    RigPanel(LabSession& session, EmergencyStop& emergency, QWidget* parent = nullptr);
    ~RigPanel() override;

    /// Camera sources offered.
    using Source = rig::CameraRequest::Source;
    void startCamera();
    void stopCamera();
    void connectLink();
    void disconnectLink();
    /// Loads a calibration file; a bad one gets a message box and changes nothing.
    bool loadCalibration(const QString& path);
    bool saveCalibration(const QString& path);
    /// Adds a calibration point (image px, floor m); fits once there are four or more.
    void addCalibrationPoint(const QPointF& image, const QPointF& floor);

    // The lens (camera intrinsics).
    /// Finds the chessboard in the newest camera frame and keeps its corners; false (and the
    /// lens line says why) if there is no frame or no whole board in it.
    bool captureBoardView();
    /// Fits the lens to the views captured; the floor calibration is fitted again under it.
    bool fitLens();
    bool loadLens(const QString& path);
    int boardViewsCaptured() const;
    const std::optional<devices::CameraLens>& lens() const;

    // The loop's latency.
    /// Starts the measurement (the car at rest in view, the link up); the result is shown and
    /// the trials compensate it.
    bool measureLatency();
    bool measuringLatency() const { return rig_.measuringLatency(); }
    std::optional<double> loopLatency() const { return rig_.loopLatency(); }

    // The fence.
    /// Adds a corner [m] (a click on the camera in fence mode does it through the
    /// calibration); from three corners the fence is in force.
    void addFenceCorner(const QPointF& floor);
    void clearFence();
    devices::Geofence geofence() const { return rig_.geofence(); }

    // Trial bundles.
    /// Where trial bundles go (empty: not saved).
    QString bundleParent() const { return rig_.bundleParent(); }
    void setSaveBundles(bool on);
    /// The newest trial's bundle folder (empty: none yet).
    const QString& lastBundle() const;

  signals:
    /// Open this bundle in a replay window.
    void replayRequested(const QString& folder);

  public:
    const devices::FloorCalibration& calibration() const { return rig_.calibration(); }
    std::optional<devices::PlanarPose> lastPose() const { return rig_.lastPose(); }
    long long framesSeen() const { return rig_.framesSeen(); }
    /// The take's recorded time [s] by the frames' clock (-1: not recording).
    double recordedSeconds() const { return rig_.recordedSeconds(); }
    const devices::LinkStatus& linkStatus() const { return rig_.linkStatus(); }
    /// The channel mapping as edited (throttle, steering); invalid edits are named and refused.
    const devices::ChannelMap& channels() const { return rig_.channels(); }
    /// The virtual car's port (empty unless the virtual rig runs).
    QString virtualPort() const { return rig_.virtualPort(); }

    /// One trial of the session's method on the rig: camera pose -> controller -> link, for the
    /// demonstration's length plus the settling time. Needs the camera running and the link
    /// connected (a message says which is missing). Learners keep learning from trial to trial.
    bool runTrial();
    /// Ends the trial; the link falls to failsafe once commands stop.
    void stopTrial() { rig_.stopTrial(); }
    bool isRunning() const { return rig_.trialRunning(); }
    /// Sends statusSummary() with the state now (it is sent on every change, and each second).
    void emitStatus();
    /// The pre-trial check for the session's task and method now (shown in the ready strip).
    rig::PreTrialCheck preTrialCheck() const;
    /// The virtual car back at its start (the Put the car back button).
    bool putVirtualCarBack();
    /// The operator's latency [ms] for the trials to compensate (0: not declared).
    void declareLoopLatency(double milliseconds);

    /// Drive the car through the link with the keyboard or a gamepad and record the camera's
    /// states and the commands as a demonstration (streamed to disk as it goes); once stopped
    /// and written, it becomes the session's demonstration (demonstrationRecorded()). Needs the
    /// camera running and the link connected.
    bool startDriving();
    void stopDriving();
    bool isDriving() const { return driving_ != nullptr && drivingActive_; }
    const Eigen::VectorXd& drivingInput() const;

  signals:
    void trialFinished(const QString& result);
    /// A take recorded by driving became the session's demonstration (or could not: the
    /// message says why).
    void demonstrationRecorded(const QString& message);
    /// The car's tracked pose as a slide-car state (x, y, psi, 0, 0, 0), for the arena.
    void carTracked(const Eigen::VectorXd& state);
    /// One line each for the window's status bar: the link (protocol, rate, failsafe) and the
    /// camera (frames per second, tracking); `alarm` when the operator should look (failsafe,
    /// a port error, a camera failure, the car not tracked).
    void statusSummary(const QString& link, bool linkAlarm, const QString& camera,
                       bool cameraAlarm);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    /// E-STOP on the rig: the trial ends and the link sends failsafe, latched until reset.
    void emergencyStop();
    void resetEmergencyStop();
    void retranslateUi();
    void updateButtons();
    void showFrame(const devices::CameraFrame& frame,
                   const std::optional<devices::PlanarPose>& pose);
    void showLinkStatus(const devices::LinkStatus& status);
    void showTask();
    void showTrialResult(const rig::RigTrialResult& result);
    /// The ready / not-ready strip from the check now.
    void showReadiness();
    void useRecording(const rig::RigRecording& recording);
    void driveTick();
    /// The pages, the actions and the trial strip laid out beside the camera's image.
    void buildLayout();
    /// The session's, the pages' and the buttons' signals to the panel.
    void connectParts();
    /// Clicks on the camera's image: fence corners or floor points, as the pages ask.
    void clickOnImage(const QPointF& image);
    void setClickMode();

    LabSession& session_;
    EmergencyStop& emergency_;
    rig::RigSession rig_;
    std::unique_ptr<rig::RigCalibration> setup_;
    CameraView* view_;
    RigCameraPage* cameraPage_ = nullptr;
    RigLinkPage* linkPage_ = nullptr;
    RigSetupPage* setupPage_ = nullptr;
    RigDoctorPage* doctorPage_ = nullptr;
    QTabWidget* tabs_ = nullptr;
    QPushButton* startCamera_;
    QPushButton* stopCamera_;
    QPushButton* connect_;
    QPushButton* disconnect_;
    QPushButton* drive_;
    QPushButton* runTrial_;
    QPushButton* stopTrial_;
    QLabel* readiness_;     ///< ready / not ready for a trial, and what is missing
    QPushButton* putBack_;  ///< the virtual car back at its start
    QLabel* trialInfo_;
    DrivingInput* driving_ = nullptr;
    bool drivingActive_ = false;
    QTimer* driveTimer_ = nullptr;
    QString lastResult_;
    QTimer* statusTimer_ = nullptr;  ///< the camera's frame rate, once a second
    long long framesAtLastTick_ = 0;
    double cameraFps_ = 0.0;
    bool tracking_ = false;  ///< the newest frame shown had the car in it
    bool recordingEndedByEmergency_ = false;
};

}  // namespace prisca::app
