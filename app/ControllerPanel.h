#pragma once

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QSpinBox;

namespace prisca::app {

class LabSession;

/// The controller: the method, and PRISCA's parameters (H, gamma, beta, step scale, theta
/// bound, matching window) with tooltips naming the paper's equations; PGSD's fixed step; a
/// button restoring the plant's tuned preset. Every edit goes straight into the session.
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

    LabSession& session_;
    bool updating_ = false;
    QFormLayout* form_;
    QComboBox* method_;
    QSpinBox* horizon_;
    QDoubleSpinBox* gamma_;
    QDoubleSpinBox* beta_;
    QDoubleSpinBox* stepScale_;
    QDoubleSpinBox* thetaBound_;
    QSpinBox* window_;
    QDoubleSpinBox* pgsdStep_;
    QPushButton* preset_;
};

}  // namespace prisca::app
