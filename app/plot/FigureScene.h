#pragma once

#include "app/plot/Figure.h"

#include <QPointF>
#include <QRectF>
#include <QSize>

#include <memory>
#include <vector>

class QChart;
class QGraphicsScene;
class QPainter;

namespace prisca::app::plot {

/// Whether a figure of this size can be drawn: not empty, and no side over 16384 px.
bool drawableFigureSize(QSize size);

/// A Figure built as QtCharts objects: one QChart per panel laid out in a grid in a
/// QGraphicsScene of the figure's size, the figure's title above them, laid out and ready to
/// render. Lines, bands and shapes become series cut to the visible range (so an SVG needs no
/// clip), texts and heatmap cells items placed where the chart maps their data.
/// Needs a QApplication; create, use and destroy on its thread.
class FigureScene {
  public:
    /// How finely long lines are kept: min/max decimated to this many points per pixel column
    /// of the plot area (1 for an image; more for an SVG a reader may zoom into).
    explicit FigureScene(const Figure& figure, int columnsPerPixel = 1);
    ~FigureScene();
    FigureScene(const FigureScene&) = delete;
    FigureScene& operator=(const FigureScene&) = delete;

    /// False for an empty or absurd figure size (> 16384 px) or without a QApplication: then
    /// nothing is built.
    bool isValid() const;

    QChart* chart(int panel) const;

    /// A panel's plot area [px in the figure].
    QRectF plotArea(int panel) const;

    /// Where a data point of a panel lands [px in the figure], as the chart maps it.
    QPointF toPixel(int panel, QPointF data) const;

    /// Paints the whole figure (white background included) into a painter on a device of the
    /// figure's size.
    void render(QPainter* painter) const;

  private:
    struct Panel;
    void build(const Figure& figure);
    void layOut();
    void fill(Panel& panel);

    QSize size_;
    int columnsPerPixel_ = 1;
    std::unique_ptr<QGraphicsScene> scene_;
    std::vector<std::unique_ptr<Panel>> panels_;
};

}  // namespace prisca::app::plot
