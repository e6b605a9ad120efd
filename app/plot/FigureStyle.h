#pragma once

// The look FigureScene draws with: fonts and sizes that grow with the figure, the colours, a
// heatmap's colour scale, and the helpers that style a chart's axes, series and notes. Internal to
// app/plot.

#include "app/plot/Figure.h"

#include <QAbstractAxis>
#include <QAbstractSeries>
#include <QBrush>
#include <QChart>
#include <QColor>
#include <QFont>
#include <QFontMetricsF>
#include <QGraphicsSimpleTextItem>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace prisca::app::plot::detail {

inline const QColor kTextColor(0x22, 0x22, 0x22);
inline const QColor kFrameColor(0x33, 0x33, 0x33);
inline const QColor kGridColor(0xe3, 0xe3, 0xe3);
inline const QColor kMinorGridColor(0xf0, 0xf0, 0xf0);
inline const QColor kNoteColor(0x88, 0x88, 0x88);
inline const QColor kShapeColor(0x44, 0x44, 0x44);

// Stacking among a chart's own items: QtCharts puts its grid at 2, the axes at 3 and the series
// at 4; heatmap cells go over the grid and under the axes, notes over the series.
constexpr qreal kHeatmapZ = 2.5;
constexpr qreal kTextZ = 4.5;

inline bool finite(double v) {
    return std::isfinite(v);
}

// ---- Fonts and sizes

struct Style {
    qreal scale = 1.0;  // 1 at the default 1200 x 800
    qreal em = 16.0;    // axis-label font size [px]
    QFont tickFont, labelFont, titleFont, figureTitleFont, noteFont;
    qreal pad = 8.0;  // around a panel
    qreal lineWidth = 1.0;
};

QFont makeFont(qreal pixels, int weight = QFont::Normal);

Style makeStyle(QSize size);

// ---- Colours

QColor mix(const QColor& a, const QColor& b, double t);

// The viridis colour scale at nine evenly spaced points: perceptually uniform and readable in grey.
inline const std::array<QRgb, 9> kViridis = {0x440154, 0x482878, 0x3e4989, 0x31688e, 0x26828e,
                                             0x1f9e89, 0x35b779, 0x6ece58, 0xfde725};

// A heatmap's colours: a linear scale between its smallest and largest value, or two colours
// either side of a threshold.
struct HeatmapColours {
    double minimum = 0.0, maximum = 1.0;
    QColor low, high;     // both invalid: viridis
    QColor below, above;  // threshold mode

    QColor at(double t) const {
        if (low.isValid() && high.isValid()) {
            return mix(low, high, t);
        }
        t = std::clamp(t, 0.0, 1.0) * (kViridis.size() - 1);
        const auto i = std::min<std::size_t>(static_cast<std::size_t>(t), kViridis.size() - 2);
        return mix(QColor(kViridis[i]), QColor(kViridis[i + 1]), t - static_cast<double>(i));
    }
    QColor of(double value, const Heatmap& heatmap) const {
        if (!finite(value)) {
            return {};  // left blank
        }
        if (heatmap.threshold) {
            return value < *heatmap.threshold ? below : above;
        }
        const double span = maximum - minimum;
        return at(span > 0.0 ? (value - minimum) / span : 0.0);
    }
    std::vector<std::pair<double, QColor>> stops() const {
        if (low.isValid() && high.isValid()) {
            return {{0.0, low}, {1.0, high}};
        }
        std::vector<std::pair<double, QColor>> result;
        for (std::size_t i = 0; i < kViridis.size(); ++i) {
            result.emplace_back(static_cast<double>(i) / (kViridis.size() - 1),
                                QColor(kViridis[i]));
        }
        return result;
    }
};

bool heatmapUsable(const std::optional<Heatmap>& heatmap);

HeatmapColours heatmapColours(const Heatmap& heatmap);

QString thresholdText(double threshold);

QColor bandFill(QColor color);

// ---- Axes, series and notes

int decimalsFor(double step);

// A linear axis over exactly [lo, hi] (applyNiceNumbers alone would move the range) with ticks
// at multiples of the finest step QtCharts' nice numbers offer whose labels keep `spacing` px
// apart on an axis `length` px long; spacing(labelWidth) says how far apart labels that wide
// must be.
template <typename Spacing>
void setLinearRange(QValueAxis* axis, double lo, double hi, qreal length, const QFont& font,
                    Spacing spacing) {
    const QFontMetricsF metrics(font);
    double step = hi - lo;
    for (int count = 21; count >= 2; --count) {
        QValueAxis nice;
        nice.setRange(lo, hi);
        nice.setTickCount(count);
        nice.applyNiceNumbers();
        step = (nice.max() - nice.min()) / std::max(1, nice.tickCount() - 1);
        const int decimals = decimalsFor(step);
        const qreal width = std::max(metrics.horizontalAdvance(QString::number(lo, 'f', decimals)),
                                     metrics.horizontalAdvance(QString::number(hi, 'f', decimals)));
        if (step / (hi - lo) * length >= spacing(width)) {
            break;
        }
    }
    axis->setRange(lo, hi);
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0.0);
    axis->setTickInterval(step);
    axis->setLabelFormat(QStringLiteral("%.%1f").arg(decimalsFor(step)));
}

void styleAxis(QAbstractAxis* axis, const QString& title, const Style& style);

QPen dataPen(const QColor& color, qreal width, Qt::PenStyle style);

// A legend entry for an area with no data draws its swatch only with the colours set on it.
void paintSwatch(QChart* chart, QAbstractSeries* series, const QBrush& brush, const QPen& pen);

void hideFromLegend(QChart* chart, QAbstractSeries* series);

// True if x never decreases: a function of x, which min/max decimation keeps intact.
bool ascendingX(const QList<QPointF>& points);

// Where a text box goes for an anchor: alignment names the side of the text on the anchor.
QPointF alignedTopLeft(QPointF anchor, QSizeF size, Qt::Alignment alignment, qreal offset);

QGraphicsSimpleTextItem* addText(QGraphicsItem* parent, const QString& text, const QFont& font,
                                 const QColor& color);

}  // namespace prisca::app::plot::detail
