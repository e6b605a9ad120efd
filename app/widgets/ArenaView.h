#pragma once

#include "app/workers/RunWorker.h"
#include "sim/PlantCatalog.h"
#include "sim/plants/Plant.h"

#include <QPointF>
#include <QVector>
#include <QWidget>

#include <memory>
#include <optional>

namespace prisca::app {

/// The plant drawn as the operator sees the lab: the slide-car and the aircraft top-down (body,
/// wheels, skid marks, parking lot, desired path, the actual trail of this trial and faintly of
/// the last), the acrobot from the side (desired pose as a ghost). A metre grid with labels in m
/// or cm as the zoom needs. Mouse wheel zooms about the cursor, dragging pans, double-click or
/// Home fits the scene. Paints only from data it was given; never touches the simulation.
class ArenaView : public QWidget {
    Q_OBJECT
  public:
    explicit ArenaView(QWidget* parent = nullptr);

    /// A new plant and demonstration: clears trails and fits the view.
    void setScene(const sim::PlantInfo& info,
                  std::shared_ptr<const core::Demonstration> demonstration);
    /// Live samples of a run (appended to the trail; a new trial starts a new trail).
    void addSamples(const QVector<LiveSample>& samples);
    /// Shows a single state (recording, or an idle plant) without adding to the trail.
    void showState(const Eigen::VectorXd& state, const Eigen::VectorXd& action);
    /// Clears the trails (a new run).
    void clearTrails();
    /// This trial's trail as given (a replay up to its moment) [m], replacing the live one.
    void setTrail(const QVector<QPointF>& points);
    /// The rig's fence on the floor [m] (closed from 3 corners; empty: none).
    void setFence(const QVector<QPointF>& corners);
    /// Fits the whole scene into the view.
    void fitScene();

    QSize sizeHint() const override { return {640, 480}; }

  protected:
    void paintEvent(QPaintEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

  private:
    QPointF toScreen(const QPointF& world) const;
    QPointF toWorld(const QPointF& screen) const;
    QRectF sceneBounds() const;
    /// Where the robot is (planar plants), if known.
    std::optional<QPointF> robotPosition() const;
    /// Refits the view when the robot is about to leave it (not after the operator moved it).
    void followRobot();
    void drawGrid(QPainter& painter) const;
    void drawPlanar(QPainter& painter) const;
    void drawCar(QPainter& painter, const Eigen::VectorXd& state, double steering) const;
    void drawAircraft(QPainter& painter, const Eigen::VectorXd& state) const;
    void drawMarker(QPainter& painter, const Eigen::VectorXd& state) const;
    void drawAcrobot(QPainter& painter) const;
    void drawWind(QPainter& painter) const;
    QPointF acrobotTip(double theta1, double theta2, QPointF* elbow) const;

    sim::PlantInfo info_;
    sim::PlantEntry::Drawing drawing_ = sim::PlantEntry::Drawing::Vehicle;  // from the catalog
    std::shared_ptr<const core::Demonstration> demonstration_;
    QVector<QPointF> desired_;    ///< demonstration path (world) or acrobot tip path
    QVector<QPointF> fence_;      ///< floor [m]
    QVector<QPointF> trail_;      ///< this trial
    QVector<QPointF> lastTrail_;  ///< the previous trial, drawn faintly
    QVector<QPointF> skidMarks_;  ///< rear-axle points where the car slid (this trial)
    Eigen::VectorXd state_;
    Eigen::VectorXd action_;
    std::optional<Eigen::Vector2d> wind_;  ///< last wind seen [m/s], world frame
    int referenceIndex_ = -1;
    int trial_ = -1;
    double scale_ = 100.0;  ///< pixels per metre
    QPointF centre_;        ///< world point at the widget centre
    QPointF dragStart_;
    QPointF dragCentre_;
    bool dragging_ = false;
    bool userMoved_ = false;  ///< the operator zoomed or panned: do not refit on resize
};

}  // namespace prisca::app
