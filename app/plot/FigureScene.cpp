#include "app/plot/FigureScene.h"

#include "app/plot/ChartDecimation.h"
#include "app/plot/DataClipping.h"
#include "app/plot/FigureRanges.h"
#include "app/plot/FigureStyle.h"

#include <QApplication>
#include <QAreaSeries>
#include <QChart>
#include <QFontMetricsF>
#include <QGraphicsLayout>
#include <QGraphicsPathItem>
#include <QGraphicsRectItem>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLinearGradient>
#include <QLogValueAxis>
#include <QPainter>
#include <QPainterPath>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace prisca::app::plot {

namespace {

constexpr int kMaxImageSide = 16384;

}  // namespace

using namespace detail;

// ---------------------------------------------------------------------------------------------

struct FigureScene::Panel {
    const Axes* axes = nullptr;
    QRectF cell;
    QChart* chart = nullptr;
    QValueAxis* xAxis = nullptr;
    QAbstractAxis* yAxis = nullptr;
    QLineSeries* anchor = nullptr;  // empty: what data is mapped through
    DataView base;                  // before equal aspect
    DataView view;                  // as shown
    bool empty = true;
    std::vector<QColor> lineColors, bandColors;
    std::optional<HeatmapColours> heatmap;
    std::vector<std::pair<double, QString>> colourBarTicks;
    QMargins margins;  // the chart's, grown so plot areas in a row or column line up
    Style style;

    void addSeries(QAbstractSeries* series, bool inLegend) {
        chart->addSeries(series);
        series->attachAxis(xAxis);
        series->attachAxis(yAxis);
        if (!inLegend) {
            hideFromLegend(chart, series);
        }
    }

    void showView(const DataView& shown) {
        view = shown;
        // The plot area once laid out, before that most of the cell.
        const QSizeF area = chart->plotArea().isValid() && chart->plotArea().width() > 1.0
                                ? chart->plotArea().size()
                                : cell.size() * 0.8;
        const qreal em = style.em;
        setLinearRange(xAxis, view.xMin, view.xMax, area.width(), style.tickFont,
                       [em](qreal width) { return width + 2.0 * em; });
        if (view.logY) {
            static_cast<QLogValueAxis*>(yAxis)->setRange(view.yMin, view.yMax);
        } else {
            setLinearRange(static_cast<QValueAxis*>(yAxis), view.yMin, view.yMax, area.height(),
                           style.tickFont, [em](qreal) { return 3.0 * em; });
        }
    }

    QPointF map(QPointF data) const { return chart->mapToPosition(data, anchor); }
};

FigureScene::FigureScene(const Figure& figure, int columnsPerPixel)
    : size_(figure.size), columnsPerPixel_(std::max(1, columnsPerPixel)) {
    if (!isValid()) {
        return;
    }
    scene_ = std::make_unique<QGraphicsScene>(QRectF(QPointF(0, 0), QSizeF(size_)));
    scene_->setBackgroundBrush(Qt::white);
    build(figure);
    layOut();
    for (const auto& panel : panels_) {
        fill(*panel);
        // The legend shows its entries on a posted layout request; deliver it now, not in some
        // later turn of the event loop after the figure was rendered.
        QCoreApplication::sendPostedEvents(panel->chart->legend(), QEvent::LayoutRequest);
    }
}

FigureScene::~FigureScene() = default;

bool drawableFigureSize(QSize size) {
    return size.width() > 0 && size.height() > 0 && size.width() <= kMaxImageSide &&
           size.height() <= kMaxImageSide;
}

bool FigureScene::isValid() const {
    return drawableFigureSize(size_) &&
           qobject_cast<QApplication*>(QCoreApplication::instance()) != nullptr;
}

QChart* FigureScene::chart(int panel) const {
    return panels_.at(static_cast<std::size_t>(panel))->chart;
}

QRectF FigureScene::plotArea(int panel) const {
    const QChart* chart = this->chart(panel);
    return chart->mapRectToScene(chart->plotArea());
}

QPointF FigureScene::toPixel(int panel, QPointF data) const {
    const Panel& p = *panels_.at(static_cast<std::size_t>(panel));
    return p.chart->mapToScene(p.map(data));
}

void FigureScene::render(QPainter* painter) const {
    if (!scene_) {
        return;
    }
    const QRectF all(QPointF(0, 0), QSizeF(size_));
    painter->setRenderHint(QPainter::Antialiasing, true);
    painter->setRenderHint(QPainter::TextAntialiasing, true);
    scene_->render(painter, all, all);
}

void FigureScene::build(const Figure& figure) {
    const Style style = makeStyle(size_);
    qreal top = 0.0;
    if (!figure.title.isEmpty()) {
        const QFontMetricsF metrics(style.figureTitleFont);
        auto* title = new QGraphicsSimpleTextItem(
            metrics.elidedText(figure.title, Qt::ElideRight, size_.width() - 2 * style.pad));
        title->setFont(style.figureTitleFont);
        title->setBrush(kTextColor);
        title->setPos((size_.width() - title->boundingRect().width()) / 2.0, style.pad * 0.6);
        scene_->addItem(title);
        top = style.pad * 0.6 + metrics.height();
    }
    const int count = static_cast<int>(figure.panels.size());
    if (count == 0) {
        return;
    }
    const int columns = std::max(1, std::min(figure.columns, count));
    const int rows = (count + columns - 1) / columns;
    const qreal cellWidth = size_.width() / static_cast<qreal>(columns);
    const qreal cellHeight = (size_.height() - top) / static_cast<qreal>(rows);
    for (int i = 0; i < count; ++i) {
        auto panel = std::make_unique<Panel>();
        Panel& p = *panel;
        p.style = style;
        p.axes = &figure.panels[static_cast<std::size_t>(i)];
        const Axes& axes = *p.axes;
        p.cell = QRectF((i % columns) * cellWidth, top + (i / columns) * cellHeight, cellWidth,
                        cellHeight);
        p.base = baseView(axes, &p.empty);
        if (heatmapUsable(axes.heatmap)) {
            p.heatmap = heatmapColours(*axes.heatmap);
        }

        int next = 0;
        for (const Line& line : axes.lines) {
            p.lineColors.push_back(line.color.isValid() ? line.color : paletteColor(next++));
        }
        for (const Band& band : axes.bands) {
            QColor color = band.color;
            for (std::size_t l = 0; l < axes.lines.size() && !color.isValid(); ++l) {
                if (!band.label.isEmpty() && axes.lines[l].label == band.label) {
                    color = p.lineColors[l];
                }
            }
            p.bandColors.push_back(color.isValid() ? color : paletteColor(next++));
        }

        auto* chart = new QChart;
        p.chart = chart;
        chart->setBackgroundRoundness(0);
        chart->setDropShadowEnabled(false);
        chart->setBackgroundBrush(Qt::white);
        chart->setBackgroundPen(Qt::NoPen);
        chart->setPlotAreaBackgroundVisible(true);
        chart->setPlotAreaBackgroundBrush(Qt::white);
        chart->setPlotAreaBackgroundPen(QPen(kFrameColor, style.lineWidth));
        chart->layout()->setContentsMargins(0, 0, 0, 0);
        chart->setTitle(axes.title.toHtmlEscaped());
        chart->setTitleFont(style.titleFont);
        chart->setTitleBrush(kTextColor);
        chart->legend()->setAlignment(Qt::AlignBottom);
        chart->legend()->setFont(style.tickFont);
        chart->legend()->setLabelColor(kTextColor);
        chart->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries);
        scene_->addItem(chart);
        chart->setGeometry(p.cell);

        p.xAxis = new QValueAxis;
        styleAxis(p.xAxis, axes.xLabel, style);
        if (axes.logY) {
            auto* log = new QLogValueAxis;
            log->setBase(10.0);
            log->setMinorTickCount(-1);  // 2..9 times each power of ten
            const bool plain = p.base.yMin >= 1e-3 && p.base.yMax <= 1e5;
            log->setLabelFormat(plain ? QStringLiteral("%g") : QStringLiteral("%.0e"));
            p.yAxis = log;
        } else {
            p.yAxis = new QValueAxis;
        }
        styleAxis(p.yAxis, axes.yLabel, style);
        chart->addAxis(p.xAxis, Qt::AlignBottom);
        chart->addAxis(p.yAxis, Qt::AlignLeft);
        p.showView(p.base);
        p.anchor = new QLineSeries;
        p.addSeries(p.anchor, false);

        // The legend: entries without data (the data's own series stay out of it), so a line
        // broken into pieces or drawn under its band still has one entry.
        bool legend = false;
        if (axes.legend) {
            for (std::size_t l = 0; l < axes.lines.size(); ++l) {
                const Line& line = axes.lines[l];
                if (line.label.isEmpty()) {
                    continue;
                }
                auto* entry = new QLineSeries;
                entry->setName(line.label.toHtmlEscaped());
                entry->setPen(dataPen(p.lineColors[l], line.width * style.scale, line.style));
                p.addSeries(entry, true);
                legend = true;
            }
            for (std::size_t b = 0; b < axes.bands.size(); ++b) {
                const Band& band = axes.bands[b];
                const bool withLine =
                    std::any_of(axes.lines.begin(), axes.lines.end(),
                                [&](const Line& line) { return line.label == band.label; });
                if (band.label.isEmpty() || withLine) {
                    continue;
                }
                auto* entry = new QAreaSeries(new QLineSeries(chart));
                entry->setName(band.label.toHtmlEscaped());
                entry->setBrush(bandFill(p.bandColors[b]));
                entry->setPen(Qt::NoPen);
                p.addSeries(entry, true);
                paintSwatch(chart, entry, entry->brush(), entry->pen());
                legend = true;
            }
        }
        if (p.heatmap && axes.heatmap->threshold) {
            // The two-entry key: which colour is below the threshold and which is not.
            const Heatmap& heatmap = *axes.heatmap;
            const QString name =
                heatmap.valueLabel.isEmpty() ? QStringLiteral("value") : heatmap.valueLabel;
            const QString limit = thresholdText(*heatmap.threshold);
            for (const auto& [color, text] :
                 {std::pair{p.heatmap->below, name + QStringLiteral(" < ") + limit},
                  {p.heatmap->above, name + QStringLiteral(" \u2265 ") + limit}}) {
                auto* entry = new QAreaSeries(new QLineSeries(chart));
                entry->setName(text.toHtmlEscaped());
                entry->setBrush(color);
                entry->setPen(QPen(kFrameColor, style.lineWidth));
                p.addSeries(entry, true);
                paintSwatch(chart, entry, entry->brush(), entry->pen());
            }
            legend = true;
        } else if (p.heatmap) {
            // Room at the right for the colour bar: bar, ticks, labels and the caption.
            QValueAxis nice;
            nice.setRange(p.heatmap->minimum, p.heatmap->maximum);
            nice.setTickCount(6);
            nice.applyNiceNumbers();
            const double step = (nice.max() - nice.min()) / std::max(1, nice.tickCount() - 1);
            const int decimals = decimalsFor(step);
            const QFontMetricsF metrics(style.tickFont);
            qreal labels = 0.0;
            for (int k = static_cast<int>(std::ceil(p.heatmap->minimum / step - 1e-9));
                 k * step <= p.heatmap->maximum + step * 1e-9; ++k) {
                const QString label = QString::number(k * step, 'f', decimals);
                p.colourBarTicks.emplace_back(k * step, label);
                labels = std::max(labels, metrics.horizontalAdvance(label));
            }
            const qreal caption = axes.heatmap->valueLabel.isEmpty()
                                      ? 0.0
                                      : style.em * 0.7 + QFontMetricsF(style.labelFont).height();
            p.margins.setRight(qCeil(style.em * 2.3 + labels + caption));
        }
        chart->legend()->setVisible(legend);
        p.margins += QMargins(qRound(style.pad), qRound(style.pad / 2), qRound(style.pad),
                              qRound(style.pad / 2));
        chart->setMargins(p.margins);
        panels_.push_back(std::move(panel));
    }
}

void FigureScene::layOut() {
    const auto activate = [this] {
        for (const auto& panel : panels_) {
            panel->chart->layout()->invalidate();
            panel->chart->layout()->activate();
        }
    };
    activate();
    // The plot area depends on the tick labels, which depend on the range, which equal aspect
    // takes from the plot area; and panels in a row share top and bottom edges, panels in a
    // column left and right ones. A few rounds settle both.
    std::vector<QMargins> extra(panels_.size());
    for (int round = 0; round < 6; ++round) {
        bool changed = false;
        for (const auto& panel : panels_) {
            const DataView view =
                panel->axes->equalAspect
                    ? withEqualAspect(panel->base, panel->chart->plotArea().size())
                    : panel->base;
            if (!sameView(view, panel->view)) {
                panel->showView(view);
                changed = true;
            } else if (round == 0) {
                panel->showView(view);  // ticks for the plot area as laid out
            }
        }
        activate();
        // Insets of each plot area in its cell, less what was added to line them up.
        std::map<int, int> left, right, top, bottom;  // by column (left, right) or row
        std::vector<QMarginsF> natural;
        for (std::size_t i = 0; i < panels_.size(); ++i) {
            const Panel& p = *panels_[i];
            const QRectF area = p.chart->plotArea();
            const QMarginsF inset(area.left() - extra[i].left(), area.top() - extra[i].top(),
                                  p.cell.width() - area.right() - extra[i].right(),
                                  p.cell.height() - area.bottom() - extra[i].bottom());
            natural.push_back(inset);
            const int column = qRound(p.cell.left());
            const int row = qRound(p.cell.top());
            left[column] = std::max(left[column], qCeil(inset.left()));
            right[column] = std::max(right[column], qCeil(inset.right()));
            top[row] = std::max(top[row], qCeil(inset.top()));
            bottom[row] = std::max(bottom[row], qCeil(inset.bottom()));
        }
        for (std::size_t i = 0; i < panels_.size(); ++i) {
            Panel& p = *panels_[i];
            const int column = qRound(p.cell.left());
            const int row = qRound(p.cell.top());
            const QMargins wanted(qRound(left[column] - natural[i].left()),
                                  qRound(top[row] - natural[i].top()),
                                  qRound(right[column] - natural[i].right()),
                                  qRound(bottom[row] - natural[i].bottom()));
            if (wanted != extra[i]) {
                p.chart->setMargins(p.margins + wanted);
                extra[i] = wanted;
                changed = true;
            }
        }
        if (!changed) {
            break;
        }
        activate();
    }
}

void FigureScene::fill(Panel& p) {
    const Axes& axes = *p.axes;
    const Style& style = p.style;
    QChart* chart = p.chart;
    const QRectF area = chart->plotArea();

    if (p.heatmap) {
        // One path per colour of runs of equal cells along each row: a threshold map is two
        // items, not thousands; each path's outline in its own colour hides the seams.
        const Heatmap& heatmap = *axes.heatmap;
        const double cellWidth = heatmap.extent.width() / heatmap.columns;
        const double cellHeight = heatmap.extent.height() / heatmap.rows;
        std::map<QRgb, QPainterPath> paths;
        for (int r = 0; r < heatmap.rows; ++r) {
            const double ya = std::max(heatmap.extent.top() + r * cellHeight, p.view.yMin);
            const double yb = std::min(ya + cellHeight, p.view.yMax);
            if (!(yb > ya)) {
                continue;
            }
            const auto colourOf = [&](int c) {
                return p.heatmap->of(
                    heatmap.values[static_cast<std::size_t>(r) * heatmap.columns + c], heatmap);
            };
            for (int c = 0; c < heatmap.columns;) {
                const QColor color = colourOf(c);
                int end = c + 1;
                while (end < heatmap.columns && colourOf(end) == color) {
                    ++end;
                }
                const double xa = std::max(heatmap.extent.left() + c * cellWidth, p.view.xMin);
                const double xb = std::min(heatmap.extent.left() + end * cellWidth, p.view.xMax);
                if (color.isValid() && xb > xa) {
                    paths[color.rgba()].addRect(
                        QRectF(p.map({xa, yb}), p.map({xb, ya})).normalized());
                }
                c = end;
            }
        }
        for (const auto& [rgba, path] : paths) {
            auto* item = new QGraphicsPathItem(path, chart);
            const QColor color = QColor::fromRgba(rgba);
            item->setBrush(color);
            item->setPen(QPen(color, 1.0));
            item->setZValue(kHeatmapZ);
        }
        if (!heatmap.threshold) {
            // The colour bar right of the plot area.
            const QRectF bar(area.right() + style.em, area.top(), style.em * 0.9, area.height());
            QLinearGradient gradient(bar.bottomLeft(), bar.topLeft());
            for (const auto& [position, color] : p.heatmap->stops()) {
                gradient.setColorAt(position, color);
            }
            auto* barItem = new QGraphicsRectItem(bar, chart);
            barItem->setBrush(gradient);
            barItem->setPen(QPen(kFrameColor, style.lineWidth));
            const double span = p.heatmap->maximum - p.heatmap->minimum;
            const qreal tick = style.em * 0.35;
            qreal labels = 0.0;
            for (const auto& [value, label] : p.colourBarTicks) {
                const qreal y =
                    span > 0.0 ? bar.bottom() - (value - p.heatmap->minimum) / span * bar.height()
                               : bar.center().y();
                auto* line = new QGraphicsLineItem(bar.right(), y, bar.right() + tick, y, chart);
                line->setPen(QPen(kFrameColor, style.lineWidth));
                auto* text = addText(chart, label, style.tickFont, kTextColor);
                const QSizeF size = text->boundingRect().size();
                text->setPos(bar.right() + tick + style.em * 0.3, y - size.height() / 2.0);
                labels = std::max(labels, size.width());
            }
            if (!heatmap.valueLabel.isEmpty()) {
                auto* caption = addText(chart, heatmap.valueLabel, style.labelFont, kTextColor);
                const QSizeF size = caption->boundingRect().size();
                caption->setRotation(-90.0);
                caption->setPos(bar.right() + tick + style.em * 0.6 + labels,
                                bar.center().y() + size.width() / 2.0);
            }
        }
    }

    // Bands, shapes and lines: each piece cut to the view is one series, drawn in this order.
    for (std::size_t b = 0; b < axes.bands.size(); ++b) {
        for (const BandPiece& piece : clipBand(axes.bands[b], p.view)) {
            auto* upper = new QLineSeries(chart);
            upper->replace(piece.upper);
            auto* lower = new QLineSeries(chart);
            lower->replace(piece.lower);
            auto* band = new QAreaSeries(upper, lower);
            band->setBrush(bandFill(p.bandColors[b]));
            band->setPen(Qt::NoPen);
            p.addSeries(band, false);
        }
    }
    for (const Shape& shape : axes.shapes) {
        if (shape.points.empty()) {
            continue;
        }
        if (shape.closed && shape.brush.alpha() > 0) {
            // An area whose upper bound is the outline and whose lower bound is its first
            // vertex: the filled polygon.
            const QList<QPointF> polygon = clipPolygon(shape.points, p.view);
            if (!polygon.isEmpty()) {
                auto* upper = new QLineSeries(chart);
                upper->replace(polygon);
                auto* lower = new QLineSeries(chart);
                lower->append(polygon.front());
                auto* fill = new QAreaSeries(upper, lower);
                fill->setBrush(shape.brush);
                fill->setPen(Qt::NoPen);
                p.addSeries(fill, false);
            }
        }
        std::vector<QPointF> outline = shape.points;
        if (shape.closed) {
            outline.push_back(shape.points.front());
        }
        QPen pen = dataPen(shape.pen.isValid() ? shape.pen : kShapeColor, shape.width * style.scale,
                           shape.style);
        pen.setJoinStyle(Qt::MiterJoin);  // crisp corners on cars and lots
        for (const QList<QPointF>& piece : clipPolyline(outline, p.view)) {
            auto* series = new QLineSeries;
            series->replace(piece);
            series->setPen(pen);
            p.addSeries(series, false);
        }
    }
    // Long lines keep the first, lowest, highest and last point of each pixel column.
    const int buckets = std::max(1, qRound(area.width())) * columnsPerPixel_;
    for (std::size_t l = 0; l < axes.lines.size(); ++l) {
        const Line& line = axes.lines[l];
        const QColor color = p.lineColors[l];
        const qreal width = line.width * style.scale;
        if (line.style != Qt::NoPen) {
            for (QList<QPointF> piece : clipPolyline(line.points, p.view)) {
                if (piece.size() > 4 * buckets && ascendingX(piece)) {
                    piece = decimateMinMax(piece, buckets);
                }
                auto* series = new QLineSeries;
                series->replace(piece);
                series->setPen(dataPen(color, width, line.style));
                p.addSeries(series, false);
            }
        }
        if (line.markers) {
            auto* dots = new QScatterSeries;
            for (const QPointF& point : line.points) {
                if (p.view.contains(point)) {
                    dots->append(point);
                }
            }
            dots->setMarkerShape(QScatterSeries::MarkerShapeCircle);
            dots->setMarkerSize(std::max<qreal>(width * 2.6, 4.0 * style.scale));
            dots->setColor(color);
            dots->setBorderColor(color);
            p.addSeries(dots, false);
        }
    }

    for (const Text& text : axes.texts) {
        if (!p.view.contains(text.at) || text.text.isEmpty()) {
            continue;  // clipped like the data
        }
        auto* item = addText(chart, text.text, style.tickFont, text.color);
        item->setPos(alignedTopLeft(p.map(text.at), item->boundingRect().size(), text.alignment,
                                    style.em * 0.3));
    }
    if (p.empty && !axes.emptyNote.isEmpty()) {
        auto* note = addText(chart, axes.emptyNote, style.noteFont, kNoteColor);
        note->setPos(area.center() - note->boundingRect().center());
    }
}

}  // namespace prisca::app::plot
