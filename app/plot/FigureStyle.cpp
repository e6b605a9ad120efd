#include "app/plot/FigureStyle.h"

#include <QLegend>
#include <QLegendMarker>

#include <limits>

namespace prisca::app::plot::detail {

QFont makeFont(qreal pixels, int weight) {
    QFont font;
    // DejaVu first: what the offscreen platform finds on Debian; the others are what an SVG
    // viewer may have.
    font.setFamilies({QStringLiteral("DejaVu Sans"), QStringLiteral("Liberation Sans"),
                      QStringLiteral("Arial"), QStringLiteral("Helvetica")});
    font.setStyleHint(QFont::SansSerif);
    font.setPixelSize(std::max(6, qRound(pixels)));
    font.setWeight(static_cast<QFont::Weight>(weight));
    return font;
}

Style makeStyle(QSize size) {
    Style style;
    // Grows with the square root of the shorter side (a 3:2 landscape figure's height counted as
    // its width): 16 px labels at 1200 x 800, 14.6 px at 1000 x 800, not proportionally smaller
    // text on smaller figures, which would drop below readable sizes first.
    const qreal side = std::min<qreal>(size.width(), size.height() * 1.5);
    style.em = std::clamp(16.0 * std::sqrt(std::max<qreal>(side, 1.0) / 1200.0), 9.0, 48.0);
    style.scale = style.em / 16.0;
    style.tickFont = makeFont(style.em * 0.85);
    style.labelFont = makeFont(style.em);
    style.titleFont = makeFont(style.em * 1.1, QFont::Medium);
    style.figureTitleFont = makeFont(style.em * 1.25, QFont::Bold);
    style.noteFont = makeFont(style.em);
    style.noteFont.setItalic(true);
    style.pad = style.em * 0.6;
    style.lineWidth = std::max<qreal>(1.0, style.scale);
    return style;
}

QColor mix(const QColor& a, const QColor& b, double t) {
    t = std::clamp(t, 0.0, 1.0);
    return QColor::fromRgbF(static_cast<float>(a.redF() + (b.redF() - a.redF()) * t),
                            static_cast<float>(a.greenF() + (b.greenF() - a.greenF()) * t),
                            static_cast<float>(a.blueF() + (b.blueF() - a.blueF()) * t),
                            static_cast<float>(a.alphaF() + (b.alphaF() - a.alphaF()) * t));
}

bool heatmapUsable(const std::optional<Heatmap>& heatmap) {
    return heatmap && heatmap->columns > 0 && heatmap->rows > 0 &&
           heatmap->values.size() == static_cast<std::size_t>(heatmap->columns) *
                                         static_cast<std::size_t>(heatmap->rows) &&
           heatmap->extent.isValid() && finite(heatmap->extent.left()) &&
           finite(heatmap->extent.right()) && finite(heatmap->extent.top()) &&
           finite(heatmap->extent.bottom());
}

HeatmapColours heatmapColours(const Heatmap& heatmap) {
    HeatmapColours h;
    h.minimum = std::numeric_limits<double>::infinity();
    h.maximum = -h.minimum;
    for (const double v : heatmap.values) {
        if (finite(v)) {
            h.minimum = std::min(h.minimum, v);
            h.maximum = std::max(h.maximum, v);
        }
    }
    if (h.minimum > h.maximum) {
        h.minimum = 0.0;
        h.maximum = 1.0;
    }
    if (heatmap.low.isValid() != heatmap.high.isValid()) {
        // One colour given: scale from white to it (or from it to white).
        h.low = heatmap.low.isValid() ? heatmap.low : QColor(Qt::white);
        h.high = heatmap.high.isValid() ? heatmap.high : QColor(Qt::white);
    } else {
        h.low = heatmap.low;
        h.high = heatmap.high;
    }
    h.below = heatmap.high.isValid() ? heatmap.high : QColor(0xa0, 0xa0, 0xa0);
    h.above = heatmap.low.isValid() ? heatmap.low : QColor(Qt::white);
    return h;
}

QString thresholdText(double threshold) {
    return QString::number(threshold, 'g', 6);
}

QColor bandFill(QColor color) {
    if (color.alpha() == 255) {
        color.setAlphaF(0.25f);
    }
    return color;
}

int decimalsFor(double step) {
    return std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
}

void styleAxis(QAbstractAxis* axis, const QString& title, const Style& style) {
    axis->setTitleText(title.toHtmlEscaped());  // titles and legend names are rich text
    axis->setTitleFont(style.labelFont);
    axis->setTitleBrush(kTextColor);
    axis->setLabelsFont(style.tickFont);
    axis->setLabelsBrush(kTextColor);
    axis->setLinePen(QPen(kFrameColor, style.lineWidth));
    axis->setGridLinePen(QPen(kGridColor, style.lineWidth));
    axis->setMinorGridLinePen(QPen(kMinorGridColor, style.lineWidth));
    axis->setTruncateLabels(false);
}

QPen dataPen(const QColor& color, qreal width, Qt::PenStyle style) {
    // Flat caps: a line cut at the plot area's edge ends on it.
    QPen pen(color, width, style, Qt::FlatCap, Qt::RoundJoin);
    if (style == Qt::SolidLine) {
        // QtCharts strokes a solid line segment by segment, which darkens a translucent line at
        // every vertex and leaves notches at the corners of a wide one; any other pen style is
        // stroked as one path. One dash longer than any line is that style, drawn solid.
        pen.setDashPattern({1e6, 1.0});
    }
    return pen;
}

// A legend entry for an area with no data draws its swatch only with the colours set on it.
void paintSwatch(QChart* chart, QAbstractSeries* series, const QBrush& brush, const QPen& pen) {
    for (QLegendMarker* marker : chart->legend()->markers(series)) {
        marker->setShape(QLegend::MarkerShapeRectangle);
        marker->setBrush(brush);
        marker->setPen(pen);
    }
}

void hideFromLegend(QChart* chart, QAbstractSeries* series) {
    for (QLegendMarker* marker : chart->legend()->markers(series)) {
        marker->setVisible(false);
    }
}

// True if x never decreases: a function of x, which min/max decimation keeps intact.
bool ascendingX(const QList<QPointF>& points) {
    for (qsizetype i = 1; i < points.size(); ++i) {
        if (points[i].x() < points[i - 1].x()) {
            return false;
        }
    }
    return true;
}

// Where a text box goes for an anchor: alignment names the side of the text on the anchor.
QPointF alignedTopLeft(QPointF anchor, QSizeF size, Qt::Alignment alignment, qreal offset) {
    qreal x = anchor.x() + offset;  // AlignLeft: text starts just right of the anchor
    if (alignment & Qt::AlignRight) {
        x = anchor.x() - offset - size.width();
    } else if (alignment & Qt::AlignHCenter) {
        x = anchor.x() - size.width() / 2.0;
    }
    qreal y = anchor.y() - size.height() / 2.0;
    if (alignment & Qt::AlignTop) {
        y = anchor.y() + offset;
    } else if (alignment & Qt::AlignBottom) {
        y = anchor.y() - offset - size.height();
    }
    return {x, y};
}

QGraphicsSimpleTextItem* addText(QGraphicsItem* parent, const QString& text, const QFont& font,
                                 const QColor& color) {
    auto* item = new QGraphicsSimpleTextItem(text, parent);
    item->setFont(font);
    item->setBrush(color);
    item->setZValue(kTextZ);
    return item;
}

}  // namespace prisca::app::plot::detail
