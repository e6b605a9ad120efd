#pragma once

#include "core/FeatureMap.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace prisca::app {

class LabSession;

/// The controller: the method, and PRISCA's parameters (H, gamma, beta, step scale, theta
/// bound, matching window) with tooltips naming the paper's equations; PGSD's fixed step; the
/// scales of the features phi (of the method chosen: PRISCA may have its own) and the action
/// limits the controller saturates to; a button restoring the plant's tuned preset. Every valid
/// edit goes straight into the session; an invalid one is named and not applied.
class ControllerPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ControllerPanel(LabSession& session, QWidget* parent = nullptr);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslateUi();
    void showSession();
    void apply();
    /// alpha_0 and the feature scales are PRISCA's own to set only with automatic defaults off.
    void enableScales();
    /// The feature set the chosen method uses (PRISCA's own where the plant has one).
    const core::FeatureMap& editedFeatures() const;

    LabSession& session_;
    bool updating_ = false;
    QFormLayout* form_;
    QComboBox* method_;
    QSpinBox* horizon_;
    QDoubleSpinBox* gamma_;
    QDoubleSpinBox* beta_;
    QCheckBox* automatic_;  // PRISCA's automatic defaults (PlantProfile::priscaAutomatic)
    QDoubleSpinBox* stepScale_;
    QDoubleSpinBox* thetaBound_;
    QCheckBox* fromPd_;       // PRISCA starts from the PD law (PlantProfile::priscaFromPd)
    QComboBox* gradient_;     // one-step (eq. 14) or closed loop (eq. 4 over the window)
    QDoubleSpinBox* effort_;  // R of the correction's effort (0: none)
    QSpinBox* window_;
    QDoubleSpinBox* pgsdStep_;
    QDoubleSpinBox* ilcLearning_;
    QSpinBox* ilcLead_;
    QDoubleSpinBox* ilcCutoff_;
    QLabel* featuresLabel_;
    QTableWidget* features_;
    QLabel* limitsLabel_;
    QTableWidget* limits_;
    QLabel* problem_;
    QPushButton* preset_;
};

}  // namespace prisca::app
