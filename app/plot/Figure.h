#pragma once

// Scientific figures as plain data, drawn with QtCharts (FigureScene: one QChart per panel) to
// an image, a PNG or an SVG file. Never opens a window, but QtCharts is made of widgets: a
// QApplication must exist (the command line creates one on the "offscreen" platform), and
// figures are rendered on its thread only.

#include <QColor>
#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QSize>
#include <QString>

#include <optional>
#include <vector>

namespace prisca::app::plot {

/// A polyline in data coordinates. A non-finite point breaks it (so does y <= 0 on a log axis).
struct Line {
    QString label;                       ///< Legend text; empty: not in the legend.
    std::vector<QPointF> points;         ///< Data coordinates, joined in order.
    QColor color;                        ///< Invalid: the panel's next palette colour.
    qreal width = 1.5;                   ///< Pen width [px at 1200 x 800; scales with the figure]
    Qt::PenStyle style = Qt::SolidLine;  ///< Qt::DashLine etc.
    bool markers = false;                ///< A dot at every point as well.
};

/// A filled area between lower(x) and upper(x), drawn translucent (a confidence band).
/// A non-finite sample breaks it; on a log axis a lower bound <= 0 reaches the bottom edge.
struct Band {
    QString label;              ///< Legend text; a Line with the same label shares its entry.
    std::vector<double> x;      ///< Abscissae, same length as lower and upper.
    std::vector<double> lower;  ///< Lower bound at each x.
    std::vector<double> upper;  ///< Upper bound at each x.
    /// Opaque: drawn at 25 % opacity; with alpha < 255: drawn as given. Invalid: the colour of
    /// the Line with the same label, else the panel's next palette colour.
    QColor color;
};

/// An outline in data coordinates: a car's body, a parking lot. Not in the legend.
struct Shape {
    std::vector<QPointF> points;         ///< Vertices in data coordinates.
    QColor pen;                          ///< Outline colour; invalid: dark grey.
    QColor brush = Qt::transparent;      ///< Fill (closed shapes only).
    qreal width = 1.0;                   ///< Outline width [px at 1200 x 800]
    Qt::PenStyle style = Qt::SolidLine;  ///< Outline style.
    bool closed = true;                  ///< Joins the last vertex to the first.
};

/// A note placed at a data point (clipped to the plot area like the data).
struct Text {
    QPointF at;                ///< Anchor in data coordinates.
    QString text;              ///< One line.
    QColor color = Qt::black;  ///< Text colour.
    /// Which side of the text sits on the anchor; the default puts the text just right of it.
    Qt::Alignment alignment = Qt::AlignLeft | Qt::AlignVCenter;
};

/// A grid of values over a rectangle of the data plane (Lemma 4.1's (H, gamma) grid).
struct Heatmap {
    int columns = 0;  ///< Cells along x.
    int rows = 0;     ///< Cells along y.
    QRectF extent;  ///< Data rectangle covered: x from left() to right(), y from top() to bottom()
                    ///< (QRectF's top() is the smaller y).
    /// columns * rows values, row-major, row 0 at the smallest y. Non-finite: cell left blank.
    std::vector<double> values;
    /// Colours of the smallest and largest value; the scale between is linear in RGB. Both
    /// invalid: the viridis scale.
    QColor low, high;
    QString valueLabel;  ///< What a value is, with units: the colour bar's (or key's) caption.
    /// If set, cells are two-colour: value < threshold in the high colour (e.g. grey for
    /// "satisfied"), otherwise the low colour, with a two-entry key instead of a colour bar.
    std::optional<double> threshold;
};

/// One panel: axes, data layers (drawn in the order heatmap, bands, shapes, lines, texts) and a
/// legend.
struct Axes {
    QString title;   ///< Above the panel.
    QString xLabel;  ///< With units, e.g. "x [cm]".
    QString yLabel;  ///< With units.
    /// Data range shown (x from left() to right(), y from top() to bottom(), i.e. QRectF's
    /// smaller y first). Unset: all data with a 5 % margin (a heatmap alone: its extent).
    std::optional<QRectF> range;
    /// One unit of x is as long as one unit of y (trajectories): the range is widened along one
    /// axis to fill the panel, never distorted. Ignored with logY.
    bool equalAspect = false;
    /// Logarithmic y, ticks at powers of ten: the range is widened to whole decades.
    bool logY = false;
    bool legend = true;  ///< A legend below the panel when some line or band has a label.
    std::vector<Band> bands;
    std::vector<Line> lines;
    std::vector<Shape> shapes;
    std::vector<Text> texts;
    std::optional<Heatmap> heatmap;
    QString emptyNote = QStringLiteral("no data");  ///< Shown in a panel without any data.
};

/// A whole figure: panels laid out in a grid, row by row.
struct Figure {
    QSize size{1200, 800};  ///< Image size [px]; fonts and pen widths scale with it.
    QString title;          ///< Above all panels; empty: none.
    int columns = 1;        ///< Panels per row (>= 1).
    std::vector<Axes> panels;
};

/// The i-th colour of the default palette (a ten-colour categorical palette); wraps around.
QColor paletteColor(int index);

}  // namespace prisca::app::plot
