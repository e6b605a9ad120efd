#pragma once

// Plot data cut to a panel's visible range, in data coordinates. The SVG writer ignores the
// painter's clip, so a figure's geometry must stop at the plot area's edge by itself; and a
// series cut to what is visible is what decimation should see.

#include "app/plot/Figure.h"

#include <QList>
#include <QPointF>

#include <vector>

namespace prisca::app::plot {

/// The visible range of a panel. On a logarithmic y axis the cuts are made in (x, log10 y),
/// where the chart draws segments straight.
struct DataView {
    double xMin = 0.0;  ///< Data x at the left edge.
    double xMax = 1.0;  ///< Data x at the right edge (> xMin).
    double yMin = 0.0;  ///< Data y at the bottom edge (> 0 on a log axis).
    double yMax = 1.0;  ///< Data y at the top edge (> yMin).
    bool logY = false;  ///< y is drawn logarithmically.

    /// True for a finite point inside the range or on its edge.
    bool contains(QPointF point) const;
};

/// The parts of a polyline inside the view, each a run of at least two points. A non-finite
/// point (and y <= 0 on a log axis) breaks the line.
std::vector<QList<QPointF>> clipPolyline(const std::vector<QPointF>& points, const DataView& view);

/// A closed polygon cut to the view (empty if nothing is left). Non-finite vertices (and
/// y <= 0 on a log axis) are left out.
QList<QPointF> clipPolygon(const std::vector<QPointF>& points, const DataView& view);

/// One run of a band cut to the view: its upper and lower bounds at the same abscissae.
struct BandPiece {
    QList<QPointF> upper;
    QList<QPointF> lower;
};

/// A band (x ascending) cut to the view: one piece per run of usable samples (a non-finite
/// sample breaks it); on a log axis a lower bound <= 0 reaches the bottom edge.
std::vector<BandPiece> clipBand(const Band& band, const DataView& view);

}  // namespace prisca::app::plot
