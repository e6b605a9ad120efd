#pragma once

#include "core/FeatureMap.h"
#include "sim/tuning/MethodParameter.h"

#include <vector>

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

/// The controller: the method, and the parameters its catalog entry declares
/// (sim::MethodSpec::parameters: label, unit, range and help come from there), the scales of the
/// features φ (of the method chosen: PRISCA may have its own) and the action limits the
/// controller saturates to; a button restoring the plant's tuned preset. Every valid edit goes
/// straight into the session; an invalid one is named and not applied. Each parameter's editor
/// is named after the parameter ("prisca.H"; one per control "pd.kp[0]", "pd.kp[1]").
class ControllerPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ControllerPanel(LabSession& session, QWidget* parent = nullptr);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    /// A parameter's unit as shown: words ("steps") translated, symbols ("s", "Hz") as they are.
    static QString unitText(const char* unit);
    struct Editor {
        const sim::MethodParameter* parameter = nullptr;
        QLabel* label = nullptr;
        std::vector<QWidget*> fields;  // one, or one per control
    };
    void retranslateUi();
    /// The method's parameters as editors (rebuilt when the method or the plant changes).
    void buildEditors();
    void showSession();
    void apply();
    /// alpha_0 and the feature scales are PRISCA's own to set only with automatic defaults off.
    void enableScales();
    /// The feature set the chosen method uses (PRISCA's own where the plant has one).
    const core::FeatureMap& editedFeatures() const;

    LabSession& session_;
    bool updating_ = false;
    QString editorsFor_;  // the method and plant the editors were built for
    QFormLayout* form_;
    QComboBox* method_;
    std::vector<Editor> editors_;
    QLabel* featuresLabel_;
    QTableWidget* features_;
    QLabel* limitsLabel_;
    QTableWidget* limits_;
    QLabel* problem_;
    QPushButton* preset_;
};

}  // namespace prisca::app
