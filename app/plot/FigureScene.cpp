#include "app/plot/FigureScene.h"

#include "app/plot/ChartDecimation.h"
#include "app/plot/DataClipping.h"

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

const QColor kTextColor(0x22, 0x22, 0x22);
const QColor kFrameColor(0x33, 0x33, 0x33);
const QColor kGridColor(0xe3, 0xe3, 0xe3);
const QColor kMinorGridColor(0xf0, 0xf0, 0xf0);
const QColor kNoteColor(0x88, 0x88, 0x88);
const QColor kShapeColor(0x44, 0x44, 0x44);

// Stacking among a chart's own items: QtCharts puts its grid at 2, the axes at 3 and the series
// at 4; heatmap cells go over the grid and under the axes, notes over the series.
constexpr qreal kHeatmapZ = 2.5;
constexpr qreal kTextZ = 4.5;

bool finite(double v) {
    return std::isfinite(v);
}

// ---------------------------------------------------------------------------------------------
// Fonts and sizes

struct Style {
    qreal scale = 1.0;  // 1 at the default 1200 x 800
    qreal em = 16.0;    // axis-label font size [px]
    QFont tickFont, labelFont, titleFont, figureTitleFont, noteFont;
    qreal pad = 8.0;  // around a panel
    qreal lineWidth = 1.0;
};

QFont makeFont(qreal pixels, int weight = QFont::Normal) {
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

// ---------------------------------------------------------------------------------------------
// Colours

QColor mix(const QColor& a, const QColor& b, double t) {
    t = std::clamp(t, 0.0, 1.0);
    return QColor::fromRgbF(static_cast<float>(a.redF() + (b.redF() - a.redF()) * t),
                            static_cast<float>(a.greenF() + (b.greenF() - a.greenF()) * t),
                            static_cast<float>(a.blueF() + (b.blueF() - a.blueF()) * t),
                            static_cast<float>(a.alphaF() + (b.alphaF() - a.alphaF()) * t));
}

// The viridis colour scale at nine evenly spaced points: perceptually uniform and readable in grey.
const std::array<QRgb, 9> kViridis = {0x440154, 0x482878, 0x3e4989, 0x31688e, 0x26828e,
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

// ---------------------------------------------------------------------------------------------
// Ranges

struct Bounds {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
    double y0 = x0, y1 = -x0;
    void addX(double x) {
        if (finite(x)) {
            x0 = std::min(x0, x);
            x1 = std::max(x1, x);
        }
    }
    void addY(double y, bool logY) {
        if (finite(y) && (!logY || y > 0.0)) {
            y0 = std::min(y0, y);
            y1 = std::max(y1, y);
        }
    }
    void add(QPointF p, bool logY) {
        if (finite(p.x()) && finite(p.y()) && (!logY || p.y() > 0.0)) {
            addX(p.x());
            addY(p.y(), logY);
        }
    }
    bool hasX() const { return x0 <= x1; }
    bool hasY() const { return y0 <= y1; }
};

// Pads [lo, hi] by a fraction of its span and widens a zero-width span so a single value sits
// in the middle.
void pad(double* lo, double* hi, double fraction) {
    const double span = *hi - *lo;
    if (span <= 0.0) {
        const double half = std::max(std::abs(*lo) * 0.05, 0.5);
        *lo -= half;
        *hi += half;
        return;
    }
    *lo -= span * fraction;
    *hi += span * fraction;
}

// The range shown before equal aspect: all data with a 5 % margin, a lone heatmap edge to edge,
// an explicit range as given; on a log axis whole decades, so there are labelled ticks.
DataView baseView(const Axes& axes, bool* empty) {
    const bool logY = axes.logY;
    Bounds data;
    for (const Line& line : axes.lines) {
        for (const QPointF& p : line.points) {
            data.add(p, logY);
        }
    }
    for (const Band& band : axes.bands) {
        const std::size_t n = std::min({band.x.size(), band.lower.size(), band.upper.size()});
        for (std::size_t i = 0; i < n; ++i) {
            if (finite(band.x[i]) && finite(band.lower[i]) && finite(band.upper[i])) {
                data.addX(band.x[i]);
                data.addY(band.lower[i], logY);
                data.addY(band.upper[i], logY);
            }
        }
    }
    for (const Shape& shape : axes.shapes) {
        for (const QPointF& p : shape.points) {
            data.add(p, logY);
        }
    }
    for (const Text& text : axes.texts) {
        data.add(text.at, logY);
    }
    const Bounds others = data;
    const bool heatmap = heatmapUsable(axes.heatmap);
    const QRectF extent = heatmap ? axes.heatmap->extent : QRectF();
    if (heatmap) {
        data.addX(extent.left());
        data.addX(extent.right());
        data.addY(extent.top(), logY);
        data.addY(extent.bottom(), logY);
    }
    *empty = !data.hasX() || !data.hasY();

    double x0 = data.hasX() ? data.x0 : 0.0;
    double x1 = data.hasX() ? data.x1 : 1.0;
    double y0 = data.hasY() ? data.y0 : (logY ? 1.0 : 0.0);
    double y1 = data.hasY() ? data.y1 : (logY ? 10.0 : 1.0);
    // A heatmap fills its panel edge to edge unless other data reaches beyond it.
    const bool snugX =
        heatmap && (!others.hasX() || (others.x0 >= extent.left() && others.x1 <= extent.right()));
    const bool snugY =
        heatmap && (!others.hasY() || (others.y0 >= extent.top() && others.y1 <= extent.bottom()));
    if (!*empty && !snugX) {
        pad(&x0, &x1, 0.05);
    }
    if (!*empty && !snugY && !logY) {
        pad(&y0, &y1, 0.05);
    }
    if (axes.range) {
        const QRectF r = axes.range->normalized();
        if (finite(r.left()) && finite(r.right()) && r.width() > 0.0) {
            x0 = r.left();
            x1 = r.right();
        }
        if (finite(r.top()) && finite(r.bottom()) && r.height() > 0.0 && (!logY || r.top() > 0.0)) {
            y0 = r.top();
            y1 = r.bottom();
        }
    }
    if (!(x1 > x0)) {
        pad(&x0, &x1, 0.0);
    }
    if (logY) {
        // Whole decades: QLogValueAxis labels powers of ten only.
        y0 = std::pow(10.0, std::floor(std::log10(y0) + 1e-9));
        y1 = std::pow(10.0, std::ceil(std::log10(y1) - 1e-9));
        if (!(y1 > y0)) {
            y1 = y0 * 10.0;
        }
    } else if (!(y1 > y0)) {
        pad(&y0, &y1, 0.0);
    }
    return {x0, x1, y0, y1, logY};
}

// Widens one axis of the base range so a data unit is as long in x as in y on the plot area.
DataView withEqualAspect(const DataView& base, QSizeF area) {
    DataView view = base;
    if (base.logY || !(area.width() > 0.0) || !(area.height() > 0.0)) {
        return view;
    }
    const double ux = area.width() / (base.xMax - base.xMin);
    const double uy = area.height() / (base.yMax - base.yMin);
    if (ux > uy) {
        const double half = area.width() / uy / 2.0;
        const double mid = (base.xMin + base.xMax) / 2.0;
        view.xMin = mid - half;
        view.xMax = mid + half;
    } else {
        const double half = area.height() / ux / 2.0;
        const double mid = (base.yMin + base.yMax) / 2.0;
        view.yMin = mid - half;
        view.yMax = mid + half;
    }
    return view;
}

bool sameView(const DataView& a, const DataView& b) {
    return a.xMin == b.xMin && a.xMax == b.xMax && a.yMin == b.yMin && a.yMax == b.yMax;
}

// ---------------------------------------------------------------------------------------------
// Axes

int decimalsFor(double step) {
    return std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
}

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

}  // namespace

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

bool FigureScene::isValid() const {
    return size_.width() > 0 && size_.height() > 0 && size_.width() <= kMaxImageSide &&
           size_.height() <= kMaxImageSide &&
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
