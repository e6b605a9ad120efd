#pragma once

#include "app/ExperimentWorker.h"
#include "app/plot/Figure.h"
#include "core/Table1Report.h"

#include <QThread>
#include <QWidget>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace prisca::app {

class LabSession;

/// Table I (slide parking) and the learning curves (Fig. 3b) in the background on the session's
/// target, with a progress bar and Cancel (what finished is kept); the result table and figure
/// (Fig. 7 or Fig. 3b); export of the table as Markdown, CSV or LaTeX and of the figure as PNG or
/// SVG.
class ExperimentsPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ExperimentsPanel(LabSession& session, QWidget* parent = nullptr);
    ~ExperimentsPanel() override;

    /// Starts the chosen experiment (the Start button).
    void start();
    /// Cancels the experiment in progress; what finished is shown.
    void cancel();
    bool isRunning() const { return running_; }
    /// The batch's progress: trials (or runs) done and asked for (0 of 0 when not known yet).
    int progressDone() const;
    int progressTotal() const;
    /// The last result as a table in a format (empty before any result).
    QString tableText(core::TableFormat format) const;
    /// Writes the table (format from the suffix: .md, .csv, .tex) or the figure (.png, .svg).
    bool exportTable(const QString& path, QString* error) const;
    bool exportFigure(const QString& path, QString* error) const;

  signals:
    void finished();

  protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

  private:
    void retranslateUi();
    void showTable1(std::shared_ptr<const sim::Table1Result> result);
    void showCurves(std::shared_ptr<const std::vector<sim::CurveSummary>> curves, bool cancelled);
    /// The table, caption and figure of a result (again on a language change).
    void displayTable1(const sim::Table1Result& result);
    void displayCurves(const std::shared_ptr<const std::vector<sim::CurveSummary>>& curves,
                       bool cancelled);
    void showFigure();
    void setRunning(bool running);
    void askExportTable();
    void askExportFigure();

    LabSession& session_;
    QThread thread_;
    ExperimentWorker* worker_;
    QComboBox* kind_;
    QLabel* countLabel_;
    QSpinBox* count_;
    QLabel* seedLabel_;
    QSpinBox* seed_;
    QLabel* budgetLabel_;
    QSpinBox* budget_;
    QPushButton* start_;
    QPushButton* cancel_;
    QProgressBar* progress_;
    QLabel* status_;
    QTableWidget* table_;
    QLabel* figureView_;
    QPushButton* exportTable_;
    QPushButton* exportFigure_;
    bool running_ = false;
    std::vector<core::Table1Row> rows_;
    QString caption_;
    plot::Figure figure_;
    QString demonstrationUsed_;  ///< the demonstration of the experiment under way or shown
    bool hasFigure_ = false;
    std::shared_ptr<const sim::Table1Result> lastTable1_;
    std::shared_ptr<const std::vector<sim::CurveSummary>> lastCurves_;
    bool lastCurvesCancelled_ = false;
};

}  // namespace prisca::app
