#pragma once

#include "app/plot/Figure.h"
#include "app/workers/ExperimentArchive.h"
#include "app/workers/ExperimentThread.h"
#include "core/Table1Report.h"

#include <QElapsedTimer>
#include <QThread>
#include <QWidget>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace prisca::app {

class EmergencyStop;
class LabSession;

/// Table I (slide parking) and the learning curves (Fig. 3b) in the background on the session's
/// target, with a progress bar and Cancel (what finished is kept); the result table and figure
/// (Fig. 7 or Fig. 3b); export of the table as Markdown, CSV or LaTeX and of the figure as PNG or
/// SVG. The last result is kept on disk (keptExperimentPath()) and shown again after a restart.
/// E-STOP cancels the experiment like Cancel (what finished is kept, marked partial); none starts
/// while it is latched. The status line says how far it is, how long it has taken and about how
/// long is left.
class ExperimentsPanel : public QWidget {
    Q_OBJECT
  public:
    ExperimentsPanel(LabSession& session, EmergencyStop& emergency, QWidget* parent = nullptr);
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
    /// What the result shown is about (empty plant before any result).
    const ExperimentRecord& shownRecord() const { return record_; }
    /// Shows the result kept by an earlier session, if there is one (the window calls it once
    /// its message log is ready; a damaged kept file is logged and nothing is shown).
    void restoreKeptResult();
    /// True while the result shown is one kept from an earlier session.
    bool showsKeptResult() const { return showsKept_; }

  signals:
    void finished();

  protected:
    void changeEvent(QEvent* event) override;
    /// The figure is redrawn at its view's size whenever that changes (a result restored before
    /// the panel was first shown included).
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void retranslateUi();
    /// The status line while it runs: how far, how long so far, about how long is left.
    void showProgress();
    /// The bar and status once it is over (finished or cancelled, and how far it got).
    void showEnd(int done, int asked, bool cancelled);
    void showTable1(std::shared_ptr<const sim::Table1Result> result);
    void showCurves(std::shared_ptr<const std::vector<sim::CurveSummary>> curves, bool cancelled);
    /// The table, caption and figure of a result (again on a language change).
    void displayTable1(const sim::Table1Result& result);
    void displayCurves(const std::shared_ptr<const std::vector<sim::CurveSummary>>& curves,
                       bool cancelled);
    void showFigure();
    /// The figure in a window of its own, large (a click on it).
    void openFigure();
    void renderLargeFigure();
    /// The experiment under way becomes the one shown, finished now.
    void adoptFinishedRecord();
    /// Writes the result just shown to keptExperimentPath() (a failure is logged, not fatal).
    void keepResult();
    void setRunning(bool running);
    void askExportTable();
    void askExportFigure();

    LabSession& session_;
    EmergencyStop& emergency_;
    ExperimentThread* experiment_;  ///< the experiment on its own thread
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
    bool stoppedByEmergency_ = false;  ///< the run under way was cancelled by E-STOP
    QElapsedTimer clock_;              ///< since Start
    int done_ = 0, total_ = 0;         ///< trials (runs) done and asked for, as last reported
    class QTimer* ticker_ = nullptr;   ///< the elapsed time, once a second
    std::vector<core::Table1Row> rows_;
    QString caption_;
    plot::Figure figure_;
    ExperimentRecord pending_;  ///< the experiment under way
    ExperimentRecord record_;   ///< the result shown
    bool showsKept_ = false;
    bool hasFigure_ = false;
    std::shared_ptr<const sim::Table1Result> lastTable1_;
    std::shared_ptr<const std::vector<sim::CurveSummary>> lastCurves_;
    bool lastCurvesCancelled_ = false;
};

}  // namespace prisca::app
