#pragma once

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace prisca::app {

class LabSession;

/// The action mapping: B~ as a table of -1 / 0 / +1 (rows are controls, columns state
/// components), the options of the B_v fit (eq. 8), and what the fit found: B = B_v (.) B~ per
/// entry, R² and residual RMS per state component, the share of samples the robust fit set aside,
/// and its warnings in the operator's words. Fit applies the table and options to the session.
class MappingPanel : public QWidget {
    Q_OBJECT
  public:
    explicit MappingPanel(LabSession& session, QWidget* parent = nullptr);

    /// Sets entry (control, state) of the B~ table (tests; the operator uses the combo boxes).
    void setSign(int control, int state, int sign);
    /// Applies the table and the options and refits (the Fit button).
    void fit();

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslateUi();
    void showSession();
    void showFit();

    LabSession& session_;
    QLabel* signsLabel_;
    QTableWidget* signs_;
    QLabel* latencyLabel_;
    QSpinBox* latency_;
    QLabel* responseLabel_;
    QSpinBox* response_;
    QCheckBox* nonNegative_;
    QCheckBox* robust_;
    QPushButton* fit_;
    QLabel* resultLabel_;
    QTableWidget* result_;
    QLabel* warnings_;
    /// A table exactly as tall as its header and rows.
    static void fitToRows(
        QTableWidget* table);  ///< the fit's warnings, one paragraph each, as tall as they need
    bool refittingForLanguage_ = false;
};

}  // namespace prisca::app
