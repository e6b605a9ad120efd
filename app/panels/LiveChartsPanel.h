#pragma once

#include "app/workers/RunWorker.h"
#include "sim/plants/Plant.h"

#include <QPointF>
#include <QVector>
#include <QWidget>

class QChart;
class QChartView;
class QCheckBox;
class QLineSeries;
class QPushButton;
class QTabWidget;
class QTimer;
class QValueAxis;

namespace prisca::app {

/// Live charts of a run against run time: the tracking error (raw and smoothed), theta, and
/// each action u against the demonstration's u*. Samples are buffered as they arrive and the
/// charts redrawn from a single-shot 40 ms timer with min/max decimation, so a 40 Hz stream with
/// 100,000 points stays fluid. Freeze stops redrawing (the data keeps coming), drag zooms, Fit
/// restores; PNG and CSV export.
class LiveChartsPanel : public QWidget {
    Q_OBJECT
  public:
    explicit LiveChartsPanel(QWidget* parent = nullptr);

    /// A new plant: series for its actions and parameters; clears the data.
    /// Entries of theta the chart has a series for.
    int parameterCount() const { return static_cast<int>(thetaSeries_.size()); }
    void setPlant(const sim::PlantInfo& info, int parameterCount);
    /// Clears the data (a new run).
    void clear();
    /// What the charts show (method, target, demonstration): written with every export.
    void setCaption(const QString& caption) { caption_ = caption; }
    /// Buffers samples; the charts follow within one redraw period.
    void addSamples(const QVector<LiveSample>& samples);

    /// Redraws the charts from the buffers now (what the 40 ms timer does; for benchmarks).
    void redraw();
    /// Points buffered for the tracking-error series (tests).
    int bufferedPoints() const { return static_cast<int>(error_.size()); }
    /// Points the tracking-error chart shows after decimation (tests).
    int drawnPoints() const;

    /// Run times [s] at which a trial after the first began (drawn as dashed lines).
    const QVector<double>& trialStarts() const { return trialStarts_; }
    /// What the hover readout says at run time t [s] on the chart on show (empty: no data).
    QString readoutAt(double t) const;
    /// Writes every buffered sample as CSV (trial, time, error, smoothed error, theta..., u...,
    /// u*...) with a "# units:" line.
    /// On failure returns false and sets *error.
    bool exportCsv(const QString& path, QString* error) const;
    /// Renders the three charts into one PNG. On failure returns false and sets *error.
    bool exportPng(const QString& path, QString* error);

  protected:
    void changeEvent(QEvent* event) override;
    /// The hover readout: the mouse over a chart shows the values at that run time.
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    QString caption_;
    void scheduleRedraw();
    void retranslateUi();
    void askExportCsv();
    void askExportPng();
    QChartView* makeView(QChart* chart);

    sim::PlantInfo info_;
    QTabWidget* tabs_;
    QChart* errorChart_;
    QChart* thetaChart_;
    QChart* actionChart_;
    QChartView* errorView_;
    QChartView* thetaView_;
    QChartView* actionView_;
    QLineSeries* errorSeries_;
    QLineSeries* smoothSeries_;
    QVector<QLineSeries*> thetaSeries_;
    QVector<QLineSeries*> actionSeries_;     ///< u per channel
    QVector<QLineSeries*> referenceSeries_;  ///< u* per channel
    QCheckBox* freeze_;
    QPushButton* fit_;
    QPushButton* exportCsv_;
    QPushButton* exportPng_;
    QTimer* redrawTimer_;
    // Buffers (GUI thread only).
    QVector<QPointF> error_, smooth_;
    QVector<int> trial_;                             ///< each buffered sample's trial (0-based)
    QVector<double> trialStarts_;                    ///< run times where a later trial began
    QVector<QVector<QLineSeries*>> boundarySeries_;  ///< per chart, one dashed line per boundary
    void drawTrialBoundaries(QChart* chart, QVector<QLineSeries*>& lines);
    QVector<QVector<QPointF>> theta_, action_, reference_;
    double smoothed_ = 0.0;
    bool zoomed_ = false;
    bool fitting_ = false;   ///< redraw() is moving the axes (not the operator)
    bool forceAll_ = false;  ///< redraw every chart, not only the one on show (export)
};

}  // namespace prisca::app
