#pragma once

#include "rig/TrialBundle.h"

#include <QDialog>

class QChart;
class QLabel;
class QLineSeries;
class QPushButton;
class QSlider;
class QTimer;

namespace prisca::app {

class ArenaView;
class CameraView;

/// A trial bundle looked at again, frame by frame: one time slider moves the camera frame (with
/// the tracked pose drawn through the bundle's calibration), the arena (the car at that
/// moment, its trail so far, the demonstration's path, the fence) and a cursor on the
/// tracking-error chart together; the frame shown is the stored one nearest the sample in time.
/// Left and right step a sample; Play runs it at the frames' pace. (Space stays E-STOP's.)
/// Sized to its screen: at 1280 x 800 every control is in view.
class ReplayDialog : public QDialog {
    Q_OBJECT
  public:
    explicit ReplayDialog(rig::TrialBundle bundle, QWidget* parent = nullptr);
    /// Moves everything to sample `index`.
    void showSample(int index);
    int sampleCount() const { return static_cast<int>(bundle_.samples.size()); }
    int currentSample() const;

  protected:
    void keyPressEvent(QKeyEvent* event) override;

  private:
    rig::TrialBundle bundle_;
    std::vector<double> errors_;  ///< per sample: distance from the nearest demonstration point [m]
    QVector<QPointF> trail_;      ///< the tracked positions [m], one per sample (NaN: none)
    CameraView* camera_;
    ArenaView* arena_;
    QChart* chart_;
    QLineSeries* cursor_;
    QSlider* slider_;
    QLabel* time_;
    QLabel* summary_;
    QPushButton* play_;
    QTimer* timer_;
};

}  // namespace prisca::app
