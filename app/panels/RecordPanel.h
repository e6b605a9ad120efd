#pragma once

#include "app/workers/RecordingThread.h"

#include <QElapsedTimer>
#include <QThread>
#include <QWidget>

#include <memory>
#include <optional>

class QLabel;
class QPushButton;
class QSpinBox;
class QTimer;

namespace prisca::app {
class DrivingInput;
}

namespace prisca::app {

class EmergencyStop;
class LabSession;

/// Record a demonstration by driving the simulated plant with the keyboard: arrows or WASD,
/// with a proportional ramp (holding a key pushes the input towards full at 2 per second;
/// releasing it returns to neutral at 3 per second), or with a gamepad's sticks when one is
/// plugged in (left stick forward: first control; right stick sideways: second). A countdown first,
/// then Stop; the recording becomes the session's demonstration at once and can be saved or
/// discarded. It streams to a file as it goes (the header at once, rows every quarter second), so
/// a crash loses at most a quarter second of driving.
class RecordPanel : public QWidget {
    Q_OBJECT
  public:
    /// A recording ends when `emergency` engages (its take kept on disk) and none starts while
    /// it is latched.
    RecordPanel(LabSession& session, EmergencyStop& emergency, QWidget* parent = nullptr);
    ~RecordPanel() override;

    /// Where recordings stream to (the application's data folder, "recordings").
    static QString recordingsFolder();
    /// The input the keyboard is asking for now (tests).
    const Eigen::VectorXd& input() const;
    bool isRecording() const { return recording_; }

  public slots:
    void startCountdown();
    void stopRecording();

  signals:
    /// Live samples while recording (the arena draws the plant as it is driven).
    void samplesReady(const QVector<prisca::app::LiveSample>& samples);
    /// Recording started (views clear their trails).
    void recordingStarted();

  protected:
    void changeEvent(QEvent* event) override;

  private:
    /// E-STOP: neutral at once, the recording stops at the next control period.
    void emergencyStop();
    void retranslateUi();
    void tick();
    void beginRecording();
    void finished(const core::Demonstration& demonstration, const QString& streamPath);
    void save();
    void discard();
    void updateButtons();

    LabSession& session_;
    EmergencyStop& emergency_;
    RecordingThread* recorder_;  ///< the recording on its own thread
    DrivingInput* driving_;
    QLabel* keys_;
    QLabel* gamepadLabel_;
    QLabel* countdownLabel_;
    QSpinBox* countdown_;
    QPushButton* record_;
    QPushButton* stop_;
    QPushButton* save_;
    QPushButton* discard_;
    QLabel* status_;
    QTimer* timer_;
    int countdownLeft_ = 0;         ///< ticks until recording starts; 0 when not counting down
    QElapsedTimer recordingClock_;  ///< since the recording began, for the live readout
    qint64 lastReadoutMs_ = -1000;  ///< when the readout was last refreshed [ms on that clock]
    bool recording_ = false;
    /// The recording under way was ended by E-STOP: kept on disk, not made the demonstration.
    bool endedByEmergency_ = false;
    bool padShown_ = false;  ///< the label says a pad is there
    QString streamPath_;
    /// The demonstration before the recording, restored by Discard.
    std::shared_ptr<const core::Demonstration> previous_;
    QString previousSource_;
};

}  // namespace prisca::app
