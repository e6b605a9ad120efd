#include "app/plot/Figure.h"

#include <QFileInfo>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QLinearGradient>
#include <QPainter>
#include <QSaveFile>
#include <QSvgGenerator>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace prisca::app::plot {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxImageSide = 16384;
// Points per drawPolyline call (SVG, shape outlines): one stroked path's cost grows faster than
// linearly with its length where it overlaps itself; raster lines avoid polylines altogether.
constexpr int kPolylineChunk = 1024;
// Segments per drawLines call (raster images).
constexpr std::size_t kSegmentBatch = 1024;

const QColor kFrameColor(0x33, 0x33, 0x33);
const QColor kGridColor(0xe3, 0xe3, 0xe3);
const QColor kTextColor(0x22, 0x22, 0x22);
const QColor kNoteColor(0x88, 0x88, 0x88);
const QColor kShapeColor(0x44, 0x44, 0x44);

bool finite(double v) {
    return std::isfinite(v);
}

// ---------------------------------------------------------------------------------------------
// Fonts and sizes

struct Style {
    qreal scale = 1.0;  // 1 at the default 1200 x 800
    qreal em = 16.0;    // axis-label font size [px]
    QFont tickFont, exponentFont, labelFont, titleFont, figureTitleFont, noteFont;
    qreal pad = 8.0;         // around a panel's cell
    qreal gap = 5.0;         // between a tick label and its axis label
    qreal tickLength = 5.0;  // outward ticks
};

QFont makeFont(qreal pixels, int weight = QFont::Normal) {
    QFont font;
    // DejaVu first: it has U+2212 and the superscript-free digits used for tick labels, and is
    // what the offscreen platform finds on Debian; the others are what an SVG viewer may have.
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
    style.exponentFont = makeFont(style.em * 0.6);
    style.labelFont = makeFont(style.em);
    style.titleFont = makeFont(style.em * 1.1, QFont::Medium);
    style.figureTitleFont = makeFont(style.em * 1.25, QFont::Bold);
    style.noteFont = makeFont(style.em);
    style.noteFont.setItalic(true);
    style.pad = style.em * 0.6;
    style.gap = style.em * 0.35;
    style.tickLength = style.em * 0.35;
    return style;
}

qreal textWidth(const QFont& font, const QString& text) {
    return QFontMetricsF(font).horizontalAdvance(text);
}

qreal textHeight(const QFont& font) {
    return QFontMetricsF(font).height();
}

// ---------------------------------------------------------------------------------------------
// Ticks

// A tick step m * 10^e with m in {1, 2, 5}; values are computed as integers scaled by an exact
// power of ten so 0.3 prints as 0.3, not 0.30000000000000004.
struct Step {
    int mantissa = 1;
    int exponent = 0;
    double value() const { return at(1); }
    double at(long long i) const {
        const double n = static_cast<double>(i * mantissa);
        return exponent >= 0 ? n * std::pow(10.0, exponent) : n / std::pow(10.0, -exponent);
    }
    Step smaller() const {
        if (mantissa == 1) {
            return {5, exponent - 1};
        }
        return {mantissa == 5 ? 2 : 1, exponent};
    }
};

Step niceStep(double span, int target) {
    const double raw = span / target;
    int exponent = static_cast<int>(std::floor(std::log10(raw)));
    const double normalized = raw / std::pow(10.0, exponent);
    int mantissa = 10;
    if (normalized < 1.5) {
        mantissa = 1;
    } else if (normalized < 3.0) {
        mantissa = 2;
    } else if (normalized < 7.0) {
        mantissa = 5;
    }
    if (mantissa == 10) {
        mantissa = 1;
        ++exponent;
    }
    return {mantissa, exponent};
}

// The decimals a label needs for ticks a step apart.
int decimalsFor(double step) {
    return std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
}

QString withMinusSign(QString text) {
    // U+2212: the typographic minus, as wide as a plus; a hyphen looks cramped in tick labels.
    return text.replace(QLatin1Char('-'), QChar(0x2212));
}

// "1e+06" -> "1e6", "2.5e-05" -> "2.5e-5".
QString compactExponent(QString text) {
    const int e = text.indexOf(QLatin1Char('e'));
    if (e < 0) {
        return text;
    }
    QString mantissa = text.left(e);
    QString exponent = text.mid(e + 1);
    const bool negative = exponent.startsWith(QLatin1Char('-'));
    if (exponent.startsWith(QLatin1Char('+')) || negative) {
        exponent.remove(0, 1);
    }
    while (exponent.size() > 1 && exponent.startsWith(QLatin1Char('0'))) {
        exponent.remove(0, 1);
    }
    return mantissa + QLatin1Char('e') + (negative ? QStringLiteral("-") : QString()) + exponent;
}

// A tick label: mantissa, and for powers of ten on a log axis an exponent drawn superscript.
struct TickLabel {
    QString text;
    QString exponent;
};

std::vector<TickLabel> linearLabels(const std::vector<double>& ticks) {
    std::vector<TickLabel> labels;
    if (ticks.empty()) {
        return labels;
    }
    double step = ticks.size() > 1 ? std::abs(ticks[1] - ticks[0]) : 0.0;
    double largest = 0.0;
    for (const double t : ticks) {
        largest = std::max(largest, std::abs(t));
    }
    if (!(step > 0.0)) {
        step = largest > 0.0 ? largest : 1.0;
    }
    // Up to six digits read more easily than "2e4" (step counts, time in ms).
    const bool scientific = largest >= 1e6 || (largest > 0.0 && largest < 1e-3);
    for (const double t : ticks) {
        const double v = std::abs(t) < step * 1e-9 ? 0.0 : t;
        QString text;
        if (v == 0.0) {
            text = QStringLiteral("0");
        } else if (scientific) {
            const int digits = std::clamp(static_cast<int>(std::floor(std::log10(largest))) -
                                              static_cast<int>(std::floor(std::log10(step))) + 1,
                                          1, 15);
            text = compactExponent(QString::number(v, 'g', digits));
        } else {
            text = QString::number(v, 'f', decimalsFor(step));
        }
        labels.push_back({withMinusSign(text), {}});
    }
    return labels;
}

bool isPowerOfTen(double v) {
    const double exponent = std::log10(v);
    return std::abs(exponent - std::round(exponent)) < 1e-9;
}

// Powers of ten as 10 with a superscript exponent; a mix with 2 and 5 multiples (axes spanning
// few decades) as plain numbers throughout, so neighbouring labels read alike.
std::vector<TickLabel> logLabels(const std::vector<double>& ticks) {
    const bool decades = std::all_of(ticks.begin(), ticks.end(), isPowerOfTen);
    std::vector<TickLabel> labels;
    for (const double t : ticks) {
        if (decades) {
            const long exponent = std::lround(std::log10(t));
            labels.push_back({QStringLiteral("10"), withMinusSign(QString::number(exponent))});
        } else {
            labels.push_back({withMinusSign(compactExponent(QString::number(t, 'g', 6))), {}});
        }
    }
    return labels;
}

qreal labelWidth(const Style& style, const TickLabel& label) {
    qreal width = textWidth(style.tickFont, label.text);
    if (!label.exponent.isEmpty()) {
        width += textWidth(style.exponentFont, label.exponent);
    }
    return width;
}

// Draws a tick label with its anchor at the given horizontal alignment (left, centre, right)
// and vertical alignment (top or centre).
void drawLabel(QPainter& painter, const Style& style, const TickLabel& label, QPointF anchor,
               Qt::Alignment alignment) {
    const QFontMetricsF metrics(style.tickFont);
    const qreal width = labelWidth(style, label);
    qreal x = anchor.x();
    if (alignment & Qt::AlignRight) {
        x -= width;
    } else if (alignment & Qt::AlignHCenter) {
        x -= width / 2.0;
    }
    qreal baseline = anchor.y() + metrics.ascent();
    if (alignment & Qt::AlignVCenter) {
        baseline = anchor.y() + (metrics.ascent() - metrics.descent()) / 2.0;
    }
    painter.setFont(style.tickFont);
    painter.drawText(QPointF(x, baseline), label.text);
    if (!label.exponent.isEmpty()) {
        painter.setFont(style.exponentFont);
        painter.drawText(
            QPointF(x + metrics.horizontalAdvance(label.text), baseline - metrics.ascent() * 0.45),
            label.exponent);
    }
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

struct ColourScale {
    QColor low, high;  // both invalid: viridis
    QColor at(double t) const {
        if (low.isValid() && high.isValid()) {
            return mix(low, high, t);
        }
        t = std::clamp(t, 0.0, 1.0) * (kViridis.size() - 1);
        const auto i = std::min<std::size_t>(static_cast<std::size_t>(t), kViridis.size() - 2);
        return mix(QColor(kViridis[i]), QColor(kViridis[i + 1]), t - static_cast<double>(i));
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

QColor bandFill(QColor color) {
    if (color.alpha() == 255) {
        color.setAlphaF(0.25f);
    }
    return color;
}

// ---------------------------------------------------------------------------------------------
// Geometry: data -> pixels, clipping

struct Mapping {
    QRectF area;
    double x0 = 0.0, x1 = 1.0;  // data x at the left and right edges
    double y0 = 0.0, y1 = 1.0;  // data y (log10 of it on a log axis) at the bottom and top edges
    bool logY = false;

    double sx() const { return area.width() / (x1 - x0); }
    double sy() const { return area.height() / (y1 - y0); }
    double px(double x) const { return area.left() + (x - x0) * sx(); }
    double py(double y) const {
        const double t = logY ? (y > 0.0 ? std::log10(y) : kNaN) : y;
        return area.bottom() - (t - y0) * sy();
    }
    QPointF operator()(double x, double y) const { return {px(x), py(y)}; }
};

bool validPixel(const QPointF& p) {
    return finite(p.x()) && finite(p.y());
}

// Liang-Barsky: narrows [t0, t1] of the segment a + t (b - a) to the part inside rect.
bool clipSegment(QPointF a, QPointF b, const QRectF& rect, double* t0, double* t1) {
    const double dx = b.x() - a.x();
    const double dy = b.y() - a.y();
    const auto edge = [&](double p, double q) {
        if (p == 0.0) {
            return q >= 0.0;
        }
        const double t = q / p;
        if (p < 0.0) {
            if (t > *t1) {
                return false;
            }
            *t0 = std::max(*t0, t);
        } else {
            if (t < *t0) {
                return false;
            }
            *t1 = std::min(*t1, t);
        }
        return true;
    };
    return edge(-dx, a.x() - rect.left()) && edge(dx, rect.right() - a.x()) &&
           edge(-dy, a.y() - rect.top()) && edge(dy, rect.bottom() - a.y());
}

using Polyline = std::vector<QPointF>;

// Builds the visible pieces of a polyline fed point by point in pixels: breaks at gaps and where
// it leaves the clip rectangle (QSvgGenerator in Qt 6.4 ignores the painter's clip, so the
// geometry itself must stay inside).
class PolylineClipper {
  public:
    PolylineClipper(const QRectF& clip, std::vector<Polyline>* pieces)
        : clip_(clip), pieces_(pieces) {}
    ~PolylineClipper() { flush(); }

    void add(QPointF p) {
        if (!validPixel(p)) {
            breakLine();
            return;
        }
        if (havePrevious_) {
            segment(previous_, p);
        }
        previous_ = p;
        havePrevious_ = true;
    }
    void breakLine() {
        flush();
        havePrevious_ = false;
    }

  private:
    void segment(QPointF a, QPointF b) {
        double t0 = 0.0;
        double t1 = 1.0;
        if (!clipSegment(a, b, clip_, &t0, &t1)) {
            flush();
            return;
        }
        const QPointF d = b - a;
        if (current_.empty() || t0 > 0.0) {
            flush();
            current_.push_back(t0 > 0.0 ? a + d * t0 : a);
        }
        current_.push_back(t1 < 1.0 ? a + d * t1 : b);
        if (t1 < 1.0) {
            flush();
        }
    }
    void flush() {
        if (current_.size() >= 2) {
            pieces_->push_back(std::move(current_));
        }
        current_.clear();
    }

    QRectF clip_;
    std::vector<Polyline>* pieces_;
    Polyline current_;
    QPointF previous_;
    bool havePrevious_ = false;
};

// Sutherland-Hodgman against the four edges of rect.
QPolygonF clipPolygon(const QPolygonF& polygon, const QRectF& rect) {
    QPolygonF input = polygon;
    QPolygonF output;
    for (int edge = 0; edge < 4 && !input.isEmpty(); ++edge) {
        const auto inside = [&](const QPointF& p) {
            switch (edge) {
                case 0:
                    return p.x() >= rect.left();
                case 1:
                    return p.x() <= rect.right();
                case 2:
                    return p.y() >= rect.top();
                default:
                    return p.y() <= rect.bottom();
            }
        };
        const auto intersect = [&](const QPointF& a, const QPointF& b) {
            double t = 0.0;
            switch (edge) {
                case 0:
                    t = (rect.left() - a.x()) / (b.x() - a.x());
                    break;
                case 1:
                    t = (rect.right() - a.x()) / (b.x() - a.x());
                    break;
                case 2:
                    t = (rect.top() - a.y()) / (b.y() - a.y());
                    break;
                default:
                    t = (rect.bottom() - a.y()) / (b.y() - a.y());
                    break;
            }
            return a + (b - a) * t;
        };
        output.clear();
        output.reserve(input.size() + 4);
        QPointF previous = input.last();
        bool previousInside = inside(previous);
        for (const QPointF& current : std::as_const(input)) {
            const bool currentInside = inside(current);
            if (currentInside != previousInside) {
                output.append(intersect(previous, current));
            }
            if (currentInside) {
                output.append(current);
            }
            previous = current;
            previousInside = currentInside;
        }
        std::swap(input, output);
    }
    return input;
}

// Keeps, per column 1/columnsPerPixel wide, the first, lowest, highest and last point (in their
// order): what an antialiased line of many more points than columns looks like, at a fraction
// of the cost and file size.
Polyline decimate(const Polyline& points, qreal columnsPerPixel) {
    Polyline out;
    out.reserve(std::min<std::size_t>(points.size(), 4096));
    std::size_t begin = 0;
    const auto emitBucket = [&](std::size_t first, std::size_t end) {
        std::size_t lowest = first;
        std::size_t highest = first;
        for (std::size_t i = first; i < end; ++i) {
            if (points[i].y() < points[lowest].y()) {
                lowest = i;
            }
            if (points[i].y() > points[highest].y()) {
                highest = i;
            }
        }
        std::array<std::size_t, 4> keep = {first, std::min(lowest, highest),
                                           std::max(lowest, highest), end - 1};
        for (std::size_t i = 0; i < keep.size(); ++i) {
            if (i == 0 || keep[i] != keep[i - 1]) {
                out.push_back(points[keep[i]]);
            }
        }
    };
    for (std::size_t i = 1; i <= points.size(); ++i) {
        if (i == points.size() || std::floor(points[i].x() * columnsPerPixel) !=
                                      std::floor(points[begin].x() * columnsPerPixel)) {
            emitBucket(begin, i);
            begin = i;
        }
    }
    return out;
}

// ---------------------------------------------------------------------------------------------
// Layout

struct AxisTicks {
    std::vector<double> major;
    std::vector<double> minor;
    std::vector<TickLabel> labels;
};

struct Margins {
    qreal left = 0.0, top = 0.0, right = 0.0, bottom = 0.0;
};

Margins maxOf(const Margins& a, const Margins& b) {
    return {std::max(a.left, b.left), std::max(a.top, b.top), std::max(a.right, b.right),
            std::max(a.bottom, b.bottom)};
}

bool fits(const Margins& need, const Margins& have) {
    constexpr qreal kSlack = 0.5;
    return need.left <= have.left + kSlack && need.top <= have.top + kSlack &&
           need.right <= have.right + kSlack && need.bottom <= have.bottom + kSlack;
}

struct LegendEntry {
    QString label;
    const Line* line = nullptr;
    QColor lineColor;
    bool band = false;
    QColor bandColor;
};

struct HeatmapPlan {
    bool valid = false;
    double minimum = 0.0, maximum = 1.0;
    ColourScale scale;
    QColor below, above;  // threshold mode
    AxisTicks ticks;      // colour bar ticks
};

struct PanelPlan {
    const Axes* axes = nullptr;
    QRectF cell;
    QRectF area;
    Mapping map;
    double baseX0 = 0.0, baseX1 = 1.0, baseY0 = 0.0, baseY1 = 1.0;  // before equal aspect
    AxisTicks xTicks, yTicks;
    bool empty = true;
    std::vector<QColor> lineColors, bandColors;
    std::vector<LegendEntry> legend;
    HeatmapPlan heatmap;
    Margins need;
};

bool heatmapUsable(const std::optional<Heatmap>& heatmap) {
    return heatmap && heatmap->columns > 0 && heatmap->rows > 0 &&
           heatmap->values.size() == static_cast<std::size_t>(heatmap->columns) *
                                         static_cast<std::size_t>(heatmap->rows) &&
           heatmap->extent.isValid() && finite(heatmap->extent.left()) &&
           finite(heatmap->extent.right()) && finite(heatmap->extent.top()) &&
           finite(heatmap->extent.bottom());
}

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
    bool hasX() const { return x0 <= x1; }
    bool hasY() const { return y0 <= y1; }
};

// Pads [lo, hi] by a fraction of its span (in log10 units on a log axis) and widens a
// zero-width span so a single value sits in the middle.
void pad(double* lo, double* hi, double fraction, bool log) {
    if (log) {
        double a = std::log10(*lo);
        double b = std::log10(*hi);
        const double span = b - a;
        if (span <= 0.0) {
            a -= 0.5;
            b += 0.5;
        } else {
            a -= span * fraction;
            b += span * fraction;
        }
        *lo = std::pow(10.0, a);
        *hi = std::pow(10.0, b);
        return;
    }
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

void resolveRange(PanelPlan* plan) {
    const Axes& axes = *plan->axes;
    const bool logY = axes.logY;
    Bounds data;
    bool any = false;
    for (const Line& line : axes.lines) {
        for (const QPointF& p : line.points) {
            if (finite(p.x()) && finite(p.y()) && (!logY || p.y() > 0.0)) {
                data.addX(p.x());
                data.addY(p.y(), logY);
                any = true;
            }
        }
    }
    for (const Band& band : axes.bands) {
        const std::size_t n = std::min({band.x.size(), band.lower.size(), band.upper.size()});
        for (std::size_t i = 0; i < n; ++i) {
            if (finite(band.x[i]) && finite(band.lower[i]) && finite(band.upper[i])) {
                data.addX(band.x[i]);
                data.addY(band.lower[i], logY);
                data.addY(band.upper[i], logY);
                any = true;
            }
        }
    }
    for (const Shape& shape : axes.shapes) {
        for (const QPointF& p : shape.points) {
            if (finite(p.x()) && finite(p.y())) {
                data.addX(p.x());
                data.addY(p.y(), logY);
                any = true;
            }
        }
    }
    for (const Text& text : axes.texts) {
        if (finite(text.at.x()) && finite(text.at.y())) {
            data.addX(text.at.x());
            data.addY(text.at.y(), logY);
            any = true;
        }
    }
    Bounds others = data;
    const bool heatmap = heatmapUsable(axes.heatmap);
    if (heatmap) {
        const QRectF extent = axes.heatmap->extent;
        data.addX(extent.left());
        data.addX(extent.right());
        data.addY(extent.top(), logY);
        data.addY(extent.bottom(), logY);
        any = true;
    }
    plan->empty = !any;

    double x0 = data.hasX() ? data.x0 : 0.0;
    double x1 = data.hasX() ? data.x1 : 1.0;
    double y0 = data.hasY() ? data.y0 : (logY ? 1.0 : 0.0);
    double y1 = data.hasY() ? data.y1 : (logY ? 10.0 : 1.0);
    // A heatmap fills its panel edge to edge unless other data reaches beyond it.
    const QRectF extent = heatmap ? axes.heatmap->extent : QRectF();
    const bool snugX =
        heatmap && (!others.hasX() || (others.x0 >= extent.left() && others.x1 <= extent.right()));
    const bool snugY =
        heatmap && (!logY || extent.top() > 0.0) &&
        (!others.hasY() || (others.y0 >= extent.top() && others.y1 <= extent.bottom()));
    if (any && !snugX) {
        pad(&x0, &x1, 0.05, false);
    }
    if (any && !snugY) {
        pad(&y0, &y1, 0.05, logY);
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
        pad(&x0, &x1, 0.0, false);
    }
    if (!(y1 > y0)) {
        pad(&y0, &y1, 0.0, logY);
    }
    plan->baseX0 = x0;
    plan->baseX1 = x1;
    plan->baseY0 = y0;
    plan->baseY1 = y1;
}

void resolveColors(PanelPlan* plan) {
    const Axes& axes = *plan->axes;
    int next = 0;
    for (const Line& line : axes.lines) {
        plan->lineColors.push_back(line.color.isValid() ? line.color : paletteColor(next++));
    }
    for (const Band& band : axes.bands) {
        QColor color = band.color;
        if (!color.isValid() && !band.label.isEmpty()) {
            for (std::size_t i = 0; i < axes.lines.size(); ++i) {
                if (axes.lines[i].label == band.label) {
                    color = plan->lineColors[i];
                    break;
                }
            }
        }
        plan->bandColors.push_back(color.isValid() ? color : paletteColor(next++));
    }
    if (!axes.legend) {
        return;
    }
    for (std::size_t i = 0; i < axes.lines.size(); ++i) {
        if (!axes.lines[i].label.isEmpty()) {
            plan->legend.push_back(
                {axes.lines[i].label, &axes.lines[i], plan->lineColors[i], false, {}});
        }
    }
    for (std::size_t i = 0; i < axes.bands.size(); ++i) {
        const QString& label = axes.bands[i].label;
        if (label.isEmpty()) {
            continue;
        }
        const auto same = std::find_if(plan->legend.begin(), plan->legend.end(),
                                       [&](const LegendEntry& e) { return e.label == label; });
        if (same != plan->legend.end()) {
            same->band = true;
            same->bandColor = plan->bandColors[i];
        } else {
            plan->legend.push_back({label, nullptr, {}, true, plan->bandColors[i]});
        }
    }
}

void resolveHeatmap(PanelPlan* plan) {
    const Axes& axes = *plan->axes;
    if (!heatmapUsable(axes.heatmap)) {
        return;
    }
    const Heatmap& heatmap = *axes.heatmap;
    HeatmapPlan& h = plan->heatmap;
    h.valid = true;
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
        h.scale.low = heatmap.low.isValid() ? heatmap.low : QColor(Qt::white);
        h.scale.high = heatmap.high.isValid() ? heatmap.high : QColor(Qt::white);
    } else {
        h.scale.low = heatmap.low;
        h.scale.high = heatmap.high;
    }
    h.below = heatmap.high.isValid() ? heatmap.high : QColor(0xa0, 0xa0, 0xa0);
    h.above = heatmap.low.isValid() ? heatmap.low : QColor(Qt::white);
}

// Widens one axis of the base range so a data unit has the same length in x and y.
void applyAspect(PanelPlan* plan) {
    const Axes& axes = *plan->axes;
    double x0 = plan->baseX0, x1 = plan->baseX1, y0 = plan->baseY0, y1 = plan->baseY1;
    if (axes.equalAspect && !axes.logY && plan->area.width() > 0 && plan->area.height() > 0) {
        const double ux = plan->area.width() / (x1 - x0);
        const double uy = plan->area.height() / (y1 - y0);
        if (ux > uy) {
            const double half = plan->area.width() / uy / 2.0;
            const double mid = (x0 + x1) / 2.0;
            x0 = mid - half;
            x1 = mid + half;
        } else {
            const double half = plan->area.height() / ux / 2.0;
            const double mid = (y0 + y1) / 2.0;
            y0 = mid - half;
            y1 = mid + half;
        }
    }
    plan->map.area = plan->area;
    plan->map.x0 = x0;
    plan->map.x1 = x1;
    plan->map.logY = axes.logY;
    plan->map.y0 = axes.logY ? std::log10(y0) : y0;
    plan->map.y1 = axes.logY ? std::log10(y1) : y1;
}

std::vector<double> inRange(const std::vector<double>& ticks, double lo, double hi) {
    std::vector<double> kept;
    const double slack = (hi - lo) * 1e-9;
    for (const double t : ticks) {
        if (t >= lo - slack && t <= hi + slack) {
            kept.push_back(t);
        }
    }
    return kept;
}

void computeTicks(PanelPlan* plan, const Style& style) {
    const Mapping& map = plan->map;
    // x: fewer ticks until neighbouring labels keep an em apart.
    int target = std::clamp(static_cast<int>(plan->area.width() / (style.em * 5.5)), 2, 10);
    for (;; --target) {
        plan->xTicks.major = niceTicks(map.x0, map.x1, target);
        plan->xTicks.labels = linearLabels(plan->xTicks.major);
        bool overlap = false;
        for (std::size_t i = 1; i < plan->xTicks.major.size() && !overlap; ++i) {
            const qreal distance =
                map.px(plan->xTicks.major[i]) - map.px(plan->xTicks.major[i - 1]);
            const qreal room = (labelWidth(style, plan->xTicks.labels[i]) +
                                labelWidth(style, plan->xTicks.labels[i - 1])) /
                                   2.0 +
                               style.em;
            overlap = distance < room;
        }
        if (!overlap || target <= 2) {
            break;
        }
    }
    const int yTarget = std::clamp(static_cast<int>(plan->area.height() / (style.em * 3.0)), 2, 10);
    plan->yTicks.minor.clear();
    if (map.logY) {
        const double lo = std::pow(10.0, map.y0);
        const double hi = std::pow(10.0, map.y1);
        plan->yTicks.major = logTicks(lo, hi, yTarget);
        plan->yTicks.labels = logLabels(plan->yTicks.major);
        // Minor ticks at 2..9 x 10^k, only while they are far enough apart to read.
        if (map.y1 - map.y0 <= 8.0) {
            for (int k = static_cast<int>(std::floor(map.y0)); k <= std::ceil(map.y1); ++k) {
                for (int m = 2; m <= 9; ++m) {
                    const double v = k >= 0 ? m * std::pow(10.0, k) : m / std::pow(10.0, -k);
                    const bool major =
                        std::find(plan->yTicks.major.begin(), plan->yTicks.major.end(), v) !=
                        plan->yTicks.major.end();
                    if (v >= lo && v <= hi && !major) {
                        plan->yTicks.minor.push_back(v);
                    }
                }
            }
        }
    } else {
        plan->yTicks.major = niceTicks(map.y0, map.y1, yTarget);
        plan->yTicks.labels = linearLabels(plan->yTicks.major);
    }
    plan->xTicks.major = inRange(plan->xTicks.major, map.x0, map.x1);
    if (plan->heatmap.valid && !plan->axes->heatmap->threshold) {
        plan->heatmap.ticks.major =
            niceTicks(plan->heatmap.minimum, plan->heatmap.maximum, yTarget);
        plan->heatmap.ticks.labels = linearLabels(plan->heatmap.ticks.major);
    }
}

QString thresholdText(double threshold) {
    return withMinusSign(compactExponent(QString::number(threshold, 'g', 6)));
}

QString belowText(const Heatmap& heatmap) {
    return QStringLiteral("< ") + thresholdText(*heatmap.threshold);
}

QString aboveText(const Heatmap& heatmap) {
    return QStringLiteral("\u2265 ") + thresholdText(*heatmap.threshold);
}

// The width right of the plot area taken by a heatmap's colour bar or two-colour key.
qreal colourKeyWidth(const PanelPlan& plan, const Style& style) {
    if (!plan.heatmap.valid) {
        return 0.0;
    }
    const Heatmap& heatmap = *plan.axes->heatmap;
    if (heatmap.threshold) {
        const qreal text =
            std::max({textWidth(style.tickFont, belowText(heatmap)),
                      textWidth(style.tickFont, aboveText(heatmap)),
                      textWidth(style.tickFont, heatmap.valueLabel) - style.em * 1.4});
        return style.em + style.em + style.gap * 1.5 + text;
    }
    qreal labels = 0.0;
    for (const TickLabel& label : plan.heatmap.ticks.labels) {
        labels = std::max(labels, labelWidth(style, label));
    }
    const qreal caption =
        heatmap.valueLabel.isEmpty() ? 0.0 : style.gap * 2 + textHeight(style.labelFont);
    return style.em + style.em * 0.9 + style.tickLength + style.gap + labels + caption;
}

Margins neededMargins(const PanelPlan& plan, const Style& style) {
    const Axes& axes = *plan.axes;
    const qreal tickHeight = textHeight(style.tickFont);
    Margins m;
    m.top = style.pad + tickHeight / 2.0;
    if (!axes.title.isEmpty()) {
        m.top = std::max(m.top, style.pad + textHeight(style.titleFont) + style.gap * 1.5);
    }
    m.bottom = style.pad + style.tickLength + style.gap / 2.0 + tickHeight;
    if (!axes.xLabel.isEmpty()) {
        m.bottom += style.gap + textHeight(style.labelFont);
    }
    qreal yLabels = 0.0;
    for (const TickLabel& label : plan.yTicks.labels) {
        yLabels = std::max(yLabels, labelWidth(style, label));
    }
    m.left = style.pad + yLabels + style.gap + style.tickLength;
    if (!axes.yLabel.isEmpty()) {
        m.left += style.gap + textHeight(style.labelFont);
    }
    // The first and last x labels are centred on their ticks and may hang over the edges.
    const Mapping& map = plan.map;
    qreal overhangLeft = 0.0;
    qreal overhangRight = 0.0;
    for (std::size_t i = 0; i < plan.xTicks.major.size(); ++i) {
        const qreal half = labelWidth(style, plan.xTicks.labels[i]) / 2.0;
        const qreal x = map.px(plan.xTicks.major[i]);
        overhangLeft = std::max(overhangLeft, plan.area.left() - (x - half));
        overhangRight = std::max(overhangRight, x + half - plan.area.right());
    }
    m.left = std::max(m.left, style.pad + overhangLeft);
    m.right =
        style.pad + std::max<qreal>(overhangRight, style.em * 0.5) + colourKeyWidth(plan, style);
    return m;
}

// Lays out one panel in its cell with at least the given margins: margins grow until the tick
// labels fit (they depend on the area, which depends on the margins).
void layoutPanel(PanelPlan* plan, const Style& style, const Margins& minimum) {
    Margins margins = minimum;
    for (int iteration = 0; iteration < 6; ++iteration) {
        QRectF area =
            plan->cell.adjusted(margins.left, margins.top, -margins.right, -margins.bottom);
        // Whole pixels, so the frame and grid can be drawn crisp.
        area = QRectF(QPointF(std::round(area.left()), std::round(area.top())),
                      QPointF(std::round(area.right()), std::round(area.bottom())));
        if (area.width() < 4.0 || area.height() < 4.0) {
            const QPointF centre = plan->cell.center();
            area = QRectF(centre - QPointF(2, 2), QSizeF(4, 4));
        }
        plan->area = area;
        applyAspect(plan);
        computeTicks(plan, style);
        plan->need = neededMargins(*plan, style);
        if (fits(plan->need, margins)) {
            break;
        }
        margins = maxOf(margins, plan->need);
    }
}

qreal figureTitleHeight(const Figure& figure, const Style& style) {
    return figure.title.isEmpty() ? 0.0 : textHeight(style.figureTitleFont) + style.pad;
}

std::vector<PanelPlan> planFigure(const Figure& figure, const Style& style) {
    std::vector<PanelPlan> plans(figure.panels.size());
    if (plans.empty()) {
        return plans;
    }
    const int columns = std::max(1, std::min<int>(figure.columns, static_cast<int>(plans.size())));
    const int rows = (static_cast<int>(plans.size()) + columns - 1) / columns;
    const qreal top = figureTitleHeight(figure, style);
    const qreal cellWidth = figure.size.width() / static_cast<qreal>(columns);
    const qreal cellHeight = (figure.size.height() - top) / static_cast<qreal>(rows);
    for (std::size_t i = 0; i < plans.size(); ++i) {
        PanelPlan& plan = plans[i];
        plan.axes = &figure.panels[i];
        const int row = static_cast<int>(i) / columns;
        const int column = static_cast<int>(i) % columns;
        plan.cell = QRectF(column * cellWidth, top + row * cellHeight, cellWidth, cellHeight);
        resolveRange(&plan);
        resolveColors(&plan);
        resolveHeatmap(&plan);
        layoutPanel(&plan, style, {});
    }
    // Second pass: panels in a row share top and bottom margins, panels in a column share left
    // and right ones, so plot areas line up.
    std::vector<Margins> rowMargins(rows), columnMargins(columns);
    for (std::size_t i = 0; i < plans.size(); ++i) {
        const int row = static_cast<int>(i) / columns;
        const int column = static_cast<int>(i) % columns;
        const Margins& need = plans[i].need;
        rowMargins[row].top = std::max(rowMargins[row].top, need.top);
        rowMargins[row].bottom = std::max(rowMargins[row].bottom, need.bottom);
        columnMargins[column].left = std::max(columnMargins[column].left, need.left);
        columnMargins[column].right = std::max(columnMargins[column].right, need.right);
    }
    for (std::size_t i = 0; i < plans.size(); ++i) {
        const int row = static_cast<int>(i) / columns;
        const int column = static_cast<int>(i) % columns;
        layoutPanel(&plans[i], style,
                    {columnMargins[column].left, rowMargins[row].top, columnMargins[column].right,
                     rowMargins[row].bottom});
    }
    return plans;
}

// ---------------------------------------------------------------------------------------------
// Drawing

struct Target {
    bool vector = false;  // SVG: no clipping by the painter, antialiasing by the viewer
    bool mask = false;    // legend placement: everything opaque, in one colour
};

qreal crisp(qreal v) {
    return std::floor(v) + 0.5;
}

QPen dataPen(const QColor& color, qreal width, Qt::PenStyle style, const Target& target) {
    QPen pen(target.mask ? QColor(Qt::black) : color, width, style, Qt::RoundCap, Qt::RoundJoin);
    return pen;
}

void drawPieces(QPainter& painter, const std::vector<Polyline>& pieces, QPen pen) {
    const bool dashed = pen.style() != Qt::SolidLine;
    const qreal unit = std::max<qreal>(pen.widthF(), 1.0);
    for (const Polyline& piece : pieces) {
        qreal dashOffset = 0.0;
        for (std::size_t start = 0; start + 1 < piece.size(); start += kPolylineChunk - 1) {
            const std::size_t count = std::min<std::size_t>(kPolylineChunk, piece.size() - start);
            if (dashed) {
                // Carry the dash pattern across chunk boundaries.
                pen.setDashOffset(dashOffset);
                for (std::size_t i = start + 1; i < start + count; ++i) {
                    const QPointF d = piece[i] - piece[i - 1];
                    dashOffset += std::hypot(d.x(), d.y()) / unit;
                }
            }
            painter.setPen(pen);
            painter.drawPolyline(piece.data() + start, static_cast<int>(count));
        }
    }
}

// Raster images: each segment on its own, which Qt fills as a simple quadrilateral. One long
// self-overlapping polyline is filled as a single path instead, and a dense 4,000-point zigzag
// then takes 16 s rather than 50 ms. Square caps close the joins of curves; a dash pattern
// continues from segment to segment.
void drawSegments(QPainter& painter, const std::vector<Polyline>& pieces, QPen pen) {
    const bool dashed = pen.style() != Qt::SolidLine;
    pen.setCapStyle(dashed ? Qt::FlatCap : Qt::SquareCap);
    painter.setPen(pen);
    const qreal unit = std::max<qreal>(pen.widthF(), 1.0);
    std::vector<QLineF> batch;
    batch.reserve(kSegmentBatch);
    const auto flush = [&] {
        if (!batch.empty()) {
            painter.drawLines(batch.data(), static_cast<int>(batch.size()));
            batch.clear();
        }
    };
    for (const Polyline& piece : pieces) {
        qreal dashOffset = 0.0;
        for (std::size_t i = 1; i < piece.size(); ++i) {
            const QLineF segment(piece[i - 1], piece[i]);
            const qreal length = segment.length();
            if (length <= 0.0) {
                continue;
            }
            if (dashed) {
                pen.setDashOffset(dashOffset);
                painter.setPen(pen);
                painter.drawLine(segment);
                dashOffset += length / unit;
                continue;
            }
            batch.push_back(segment);
            if (batch.size() == kSegmentBatch) {
                flush();
            }
        }
    }
    flush();
}

// Strokes a line's visible pieces. A translucent raster line goes through an opaque layer laid
// on at the line's alpha, so where its segments overlap it does not darken in spots.
void strokePieces(QPainter& painter, const std::vector<Polyline>& pieces, const QPen& pen,
                  const QRectF& clip, const Target& target) {
    if (target.vector) {
        drawPieces(painter, pieces, pen);  // the viewer rasterizes; keep the joins exact
        return;
    }
    if (pen.color().alpha() == 255 || target.mask) {
        drawSegments(painter, pieces, pen);
        return;
    }
    QRectF bounds;
    for (const Polyline& piece : pieces) {
        for (const QPointF& p : piece) {
            bounds |= QRectF(p, QSizeF(0.001, 0.001));
        }
    }
    const qreal reach = pen.widthF() + 2.0;
    const QRect rect =
        bounds.adjusted(-reach, -reach, reach, reach).intersected(clip).toAlignedRect();
    if (rect.isEmpty()) {
        return;
    }
    QImage layer(rect.size(), QImage::Format_ARGB32_Premultiplied);
    layer.fill(Qt::transparent);
    {
        QPainter layerPainter(&layer);
        layerPainter.setRenderHint(QPainter::Antialiasing, true);
        layerPainter.translate(-rect.topLeft());
        QPen opaque = pen;
        QColor color = pen.color();
        color.setAlpha(255);
        opaque.setColor(color);
        drawSegments(layerPainter, pieces, opaque);
    }
    painter.save();
    painter.setOpacity(pen.color().alphaF());
    painter.drawImage(rect.topLeft(), layer);
    painter.restore();
}

void drawHeatmap(QPainter& painter, const PanelPlan& plan, const Target& target) {
    if (!plan.heatmap.valid || target.mask) {
        return;
    }
    const Heatmap& heatmap = *plan.axes->heatmap;
    const HeatmapPlan& h = plan.heatmap;
    const Mapping& map = plan.map;
    const double cellWidth = heatmap.extent.width() / heatmap.columns;
    const double cellHeight = heatmap.extent.height() / heatmap.rows;
    const double span = h.maximum - h.minimum;
    painter.save();
    // Adjacent antialiased rectangles leave faint seams; whole-pixel fills do not.
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(Qt::NoPen);
    // An SVG viewer antialiases every edge, so abutting rectangles show hairline seams. There each
    // run reaches one cell further right and down, rows drawn top to bottom and runs left to
    // right: every cell is painted last by its own rectangle over an already covered boundary.
    const double spill = target.vector ? 1.0 : 0.0;
    std::vector<QRectF> blanks;
    for (int r = heatmap.rows - 1; r >= 0; --r) {
        const double ya = heatmap.extent.top() + r * cellHeight;
        const double yb = ya + cellHeight;
        const qreal top = map.py(yb);
        const qreal bottom = map.py(std::max(ya - spill * cellHeight, heatmap.extent.top()));
        if (!finite(top) || !finite(bottom)) {
            continue;
        }
        const auto colourOf = [&](int c) {
            const double v = heatmap.values[static_cast<std::size_t>(r) * heatmap.columns + c];
            if (!finite(v)) {
                return QColor();  // left blank
            }
            if (heatmap.threshold) {
                return v < *heatmap.threshold ? h.below : h.above;
            }
            return h.scale.at(span > 0.0 ? (v - h.minimum) / span : 0.0);
        };
        // One rectangle per run of equal colour along the row: a threshold map becomes a few
        // dozen rectangles instead of thousands of SVG elements.
        for (int c = 0; c < heatmap.columns;) {
            const QColor color = colourOf(c);
            int end = c + 1;
            while (end < heatmap.columns && colourOf(end) == color) {
                ++end;
            }
            const double xa = heatmap.extent.left() + c * cellWidth;
            const double xb = heatmap.extent.left() + end * cellWidth;
            if (color.isValid()) {
                const double right = std::min(xb + spill * cellWidth, heatmap.extent.right());
                const QRectF run = QRectF(QPointF(map.px(xa), top), QPointF(map.px(right), bottom))
                                       .normalized()
                                       .intersected(plan.area);
                if (!run.isEmpty()) {
                    painter.fillRect(run, color);
                }
            } else if (spill > 0.0) {
                blanks.push_back(QRectF(QPointF(map.px(xa), top), QPointF(map.px(xb), map.py(ya)))
                                     .normalized()
                                     .intersected(plan.area));
            }
            c = end;
        }
    }
    for (const QRectF& blank : blanks) {
        painter.fillRect(blank, Qt::white);  // undo the neighbours' spill
    }
    painter.restore();
}

void drawBands(QPainter& painter, const PanelPlan& plan, const Target& target) {
    const Mapping& map = plan.map;
    const bool logY = plan.axes->logY;
    painter.setPen(Qt::NoPen);
    for (std::size_t b = 0; b < plan.axes->bands.size(); ++b) {
        const Band& band = plan.axes->bands[b];
        painter.setBrush(target.mask ? QColor(Qt::black) : bandFill(plan.bandColors[b]));
        const std::size_t n = std::min({band.x.size(), band.lower.size(), band.upper.size()});
        std::size_t i = 0;
        while (i < n) {
            // One polygon per run of usable samples: upper bound forward, lower bound back.
            const auto usable = [&](std::size_t k) {
                return finite(band.x[k]) && finite(band.lower[k]) && finite(band.upper[k]) &&
                       (!logY || band.upper[k] > 0.0);
            };
            while (i < n && !usable(i)) {
                ++i;
            }
            const std::size_t begin = i;
            while (i < n && usable(i)) {
                ++i;
            }
            if (i - begin < 2) {
                continue;
            }
            QPolygonF polygon;
            polygon.reserve(static_cast<int>(2 * (i - begin)));
            for (std::size_t k = begin; k < i; ++k) {
                polygon.append(map(band.x[k], band.upper[k]));
            }
            const qreal below = plan.area.bottom() + 1.0;  // a log axis' lower bound <= 0
            for (std::size_t k = i; k-- > begin;) {
                const QPointF p = map(band.x[k], band.lower[k]);
                polygon.append(finite(p.y()) ? p : QPointF(p.x(), below));
            }
            painter.drawPolygon(clipPolygon(polygon, plan.area), Qt::WindingFill);
        }
    }
    painter.setBrush(Qt::NoBrush);
}

void drawShapes(QPainter& painter, const PanelPlan& plan, const Style& style,
                const Target& target) {
    const Mapping& map = plan.map;
    for (const Shape& shape : plan.axes->shapes) {
        if (shape.points.empty()) {
            continue;
        }
        QPolygonF polygon;
        for (const QPointF& p : shape.points) {
            const QPointF q = map(p.x(), p.y());
            if (validPixel(q)) {
                polygon.append(q);
            }
        }
        if (shape.closed && shape.brush.alpha() > 0 && polygon.size() >= 3) {
            painter.setPen(Qt::NoPen);
            painter.setBrush(target.mask ? QColor(Qt::black) : shape.brush);
            painter.drawPolygon(clipPolygon(polygon, plan.area), Qt::WindingFill);
            painter.setBrush(Qt::NoBrush);
        }
        std::vector<Polyline> pieces;
        {
            PolylineClipper clipper(plan.area, &pieces);
            for (const QPointF& p : shape.points) {
                clipper.add(map(p.x(), p.y()));
            }
            if (shape.closed) {
                clipper.add(map(shape.points.front().x(), shape.points.front().y()));
            }
        }
        QPen pen = dataPen(shape.pen.isValid() ? shape.pen : kShapeColor, shape.width * style.scale,
                           shape.style, target);
        pen.setJoinStyle(Qt::MiterJoin);  // crisp corners on cars and lots
        pen.setCapStyle(Qt::FlatCap);
        drawPieces(painter, pieces, pen);
    }
}

void drawLines(QPainter& painter, const PanelPlan& plan, const Style& style, const Target& target) {
    const Mapping& map = plan.map;
    // Geometry is cut at the plot area (SVG); a raster image gets a margin and the painter's
    // exact clip instead, so line ends at the frame are not capped.
    const QRectF clip = target.vector ? plan.area : plan.area.adjusted(-4, -4, 4, 4);
    // SVG keeps quarter-pixel detail, so a reader may zoom in four times.
    const qreal columnsPerPixel = target.vector ? 4.0 : 1.0;
    const auto decimateAbove = static_cast<std::size_t>(4.0 * columnsPerPixel * plan.area.width());
    for (std::size_t l = 0; l < plan.axes->lines.size(); ++l) {
        const Line& line = plan.axes->lines[l];
        const qreal width = line.width * style.scale;
        std::vector<Polyline> pieces;
        {
            PolylineClipper clipper(clip, &pieces);
            for (const QPointF& p : line.points) {
                clipper.add(map(p.x(), p.y()));
            }
        }
        for (Polyline& piece : pieces) {
            if (piece.size() > decimateAbove) {
                piece = decimate(piece, columnsPerPixel);
            }
        }
        if (line.style != Qt::NoPen) {
            strokePieces(painter, pieces, dataPen(plan.lineColors[l], width, line.style, target),
                         clip, target);
        }
        if (line.markers) {
            std::vector<QPointF> visible;
            for (const QPointF& p : line.points) {
                const QPointF q = map(p.x(), p.y());
                if (validPixel(q) && plan.area.contains(q)) {
                    visible.push_back(q);
                }
            }
            QPen dot = dataPen(plan.lineColors[l], std::max<qreal>(width * 2.6, 4.0 * style.scale),
                               Qt::SolidLine, target);
            painter.setPen(dot);
            for (std::size_t start = 0; start < visible.size(); start += kPolylineChunk) {
                const std::size_t count =
                    std::min<std::size_t>(kPolylineChunk, visible.size() - start);
                painter.drawPoints(visible.data() + start, static_cast<int>(count));
            }
        }
    }
}

QRectF alignedTextRect(QPointF anchor, QSizeF size, Qt::Alignment alignment, qreal offset) {
    qreal x = anchor.x() + offset;  // AlignLeft: text starts just right of the anchor
    if (alignment & Qt::AlignRight) {
        x = anchor.x() - offset - size.width();
    } else if (alignment & Qt::AlignHCenter) {
        x = anchor.x() - size.width() / 2.0;
    }
    qreal y = anchor.y() - size.height() / 2.0;
    if (alignment & Qt::AlignTop) {
        y = anchor.y();
    } else if (alignment & Qt::AlignBottom) {
        y = anchor.y() - size.height();
    }
    return {QPointF(x, y), size};
}

void drawTexts(QPainter& painter, const PanelPlan& plan, const Style& style, const Target& target) {
    painter.setFont(style.tickFont);
    const QFontMetricsF metrics(style.tickFont);
    for (const Text& text : plan.axes->texts) {
        const QPointF p = plan.map(text.at.x(), text.at.y());
        if (!validPixel(p) || !plan.area.contains(p) || text.text.isEmpty()) {
            continue;
        }
        const QRectF rect =
            alignedTextRect(p, QSizeF(metrics.horizontalAdvance(text.text), metrics.height()),
                            text.alignment, style.gap);
        if (target.mask) {
            painter.fillRect(rect, Qt::black);
            continue;
        }
        painter.setPen(text.color);
        painter.drawText(rect, Qt::AlignCenter | Qt::TextSingleLine, text.text);
    }
}

void drawData(QPainter& painter, const PanelPlan& plan, const Style& style, const Target& target) {
    drawHeatmap(painter, plan, target);
    drawBands(painter, plan, target);
    drawShapes(painter, plan, style, target);
    drawLines(painter, plan, style, target);
    drawTexts(painter, plan, style, target);
}

void drawGrid(QPainter& painter, const PanelPlan& plan, const Style& style) {
    painter.setPen(QPen(kGridColor, std::max<qreal>(1.0, style.scale)));
    const QRectF& area = plan.area;
    for (const double t : plan.xTicks.major) {
        const qreal x = crisp(plan.map.px(t));
        if (x > area.left() + 1 && x < area.right() - 1) {
            painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
        }
    }
    for (const double t : plan.yTicks.major) {
        const qreal y = crisp(plan.map.py(t));
        if (y > area.top() + 1 && y < area.bottom() - 1) {
            painter.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
        }
    }
}

void drawAxes(QPainter& painter, const PanelPlan& plan, const Style& style) {
    const QRectF& area = plan.area;
    const Axes& axes = *plan.axes;
    const qreal lineWidth = std::max<qreal>(1.0, style.scale);
    painter.setPen(QPen(kFrameColor, lineWidth, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin));
    painter.setBrush(Qt::NoBrush);
    // The frame sits on the pixels just outside the area so it never hides data at the edge.
    painter.drawRect(area.adjusted(-0.5, -0.5, 0.5, 0.5));

    painter.setPen(QPen(kFrameColor, lineWidth, Qt::SolidLine, Qt::FlatCap));
    const qreal tick = style.tickLength;
    for (const double t : plan.xTicks.major) {
        const qreal x = crisp(plan.map.px(t));
        painter.drawLine(QPointF(x, area.bottom() + 1), QPointF(x, area.bottom() + 1 + tick));
    }
    for (const double t : plan.yTicks.major) {
        const qreal y = crisp(plan.map.py(t));
        painter.drawLine(QPointF(area.left() - 1, y), QPointF(area.left() - 1 - tick, y));
    }
    for (const double t : plan.yTicks.minor) {
        const qreal y = crisp(plan.map.py(t));
        painter.drawLine(QPointF(area.left() - 1, y), QPointF(area.left() - 1 - tick * 0.55, y));
    }

    painter.setPen(kTextColor);
    for (std::size_t i = 0; i < plan.xTicks.major.size(); ++i) {
        drawLabel(
            painter, style, plan.xTicks.labels[i],
            QPointF(plan.map.px(plan.xTicks.major[i]), area.bottom() + 1 + tick + style.gap / 2.0),
            Qt::AlignHCenter | Qt::AlignTop);
    }
    for (std::size_t i = 0; i < plan.yTicks.major.size(); ++i) {
        drawLabel(painter, style, plan.yTicks.labels[i],
                  QPointF(area.left() - 1 - tick - style.gap, plan.map.py(plan.yTicks.major[i])),
                  Qt::AlignRight | Qt::AlignVCenter);
    }

    const qreal labelHeight = textHeight(style.labelFont);
    painter.setFont(style.labelFont);
    if (!axes.xLabel.isEmpty()) {
        const qreal top =
            area.bottom() + 1 + tick + style.gap / 2.0 + textHeight(style.tickFont) + style.gap;
        const QString text = QFontMetricsF(style.labelFont)
                                 .elidedText(axes.xLabel, Qt::ElideRight, plan.cell.width());
        painter.drawText(QRectF(area.left() - plan.cell.width(), top,
                                area.width() + 2 * plan.cell.width(), labelHeight),
                         Qt::AlignHCenter | Qt::AlignTop, text);
    }
    if (!axes.yLabel.isEmpty()) {
        painter.save();
        const qreal x = plan.cell.left() + style.pad + labelHeight / 2.0;
        painter.translate(x, area.center().y());
        painter.rotate(-90.0);
        const QString text = QFontMetricsF(style.labelFont)
                                 .elidedText(axes.yLabel, Qt::ElideRight, plan.cell.height());
        painter.drawText(
            QRectF(-plan.cell.height(), -labelHeight / 2.0, 2 * plan.cell.height(), labelHeight),
            Qt::AlignCenter, text);
        painter.restore();
    }
    if (!axes.title.isEmpty()) {
        painter.setFont(style.titleFont);
        const qreal height = textHeight(style.titleFont);
        const QString text =
            QFontMetricsF(style.titleFont)
                .elidedText(axes.title, Qt::ElideRight, plan.cell.width() - 2 * style.pad);
        // Centred over the plot area, but kept inside the cell.
        QRectF rect(0, area.top() - style.gap * 1.5 - height, textWidth(style.titleFont, text),
                    height);
        rect.moveLeft(std::clamp(area.center().x() - rect.width() / 2.0,
                                 plan.cell.left() + style.pad,
                                 plan.cell.right() - style.pad - rect.width()));
        painter.drawText(rect, Qt::AlignCenter, text);
    }
    if (plan.empty && !axes.emptyNote.isEmpty()) {
        painter.setFont(style.noteFont);
        painter.setPen(kNoteColor);
        painter.drawText(area, Qt::AlignCenter, axes.emptyNote);
    }
}

QSizeF legendSize(const PanelPlan& plan, const Style& style) {
    const QFontMetricsF metrics(style.tickFont);
    qreal text = 0.0;
    for (const LegendEntry& entry : plan.legend) {
        text = std::max(text, metrics.horizontalAdvance(entry.label));
    }
    const qreal row = metrics.height() * 1.25;
    return {style.em * 0.5 * 2 + style.em * 2.0 + style.em * 0.5 + text,
            style.em * 0.4 * 2 + row * static_cast<qreal>(plan.legend.size())};
}

// Places the legend where the data leave the most room: the data are drawn once more into a
// coarse mask and each candidate corner is scored by the ink it would cover. Top right wins ties.
QRectF placeLegend(const PanelPlan& plan, const Style& style, QSizeF size) {
    const QRectF& area = plan.area;
    const qreal inset = style.em * 0.5;
    const std::array<QPointF, 8> corners = {
        QPointF(area.right() - inset - size.width(), area.top() + inset),  // top right
        QPointF(area.left() + inset, area.top() + inset),                  // top left
        QPointF(area.right() - inset - size.width(), area.bottom() - inset - size.height()),
        QPointF(area.left() + inset, area.bottom() - inset - size.height()),  // bottom left
        QPointF(area.right() - inset - size.width(), area.center().y() - size.height() / 2),
        QPointF(area.center().x() - size.width() / 2, area.top() + inset),    // top centre
        QPointF(area.left() + inset, area.center().y() - size.height() / 2),  // left middle
        QPointF(area.center().x() - size.width() / 2, area.bottom() - inset - size.height()),
    };
    if (size.width() + 2 * inset > area.width() || size.height() + 2 * inset > area.height()) {
        return {corners[0], size};
    }
    constexpr qreal kMaskScale = 0.25;
    const QSize maskSize(std::max(1, qCeil(area.width() * kMaskScale)),
                         std::max(1, qCeil(area.height() * kMaskScale)));
    QImage mask(maskSize, QImage::Format_Alpha8);
    mask.fill(0);
    {
        QPainter painter(&mask);
        painter.scale(kMaskScale, kMaskScale);
        painter.translate(-area.topLeft());
        drawData(painter, plan, style, Target{false, true});
    }
    // A summed-area table makes each candidate's ink count four lookups.
    const int w = mask.width();
    const int h = mask.height();
    std::vector<long> sums(static_cast<std::size_t>((w + 1) * (h + 1)), 0);
    const auto at = [&](int x, int y) -> long& {
        return sums[static_cast<std::size_t>(y * (w + 1) + x)];
    };
    for (int y = 0; y < h; ++y) {
        const uchar* row = mask.constScanLine(y);
        for (int x = 0; x < w; ++x) {
            at(x + 1, y + 1) = (row[x] > 0 ? 1 : 0) + at(x, y + 1) + at(x + 1, y) - at(x, y);
        }
    }
    const auto ink = [&](const QRectF& rect) {
        const int x0 = std::clamp(static_cast<int>((rect.left() - area.left()) * kMaskScale), 0, w);
        const int x1 = std::clamp(qCeil((rect.right() - area.left()) * kMaskScale), 0, w);
        const int y0 = std::clamp(static_cast<int>((rect.top() - area.top()) * kMaskScale), 0, h);
        const int y1 = std::clamp(qCeil((rect.bottom() - area.top()) * kMaskScale), 0, h);
        return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0);
    };
    QRectF best(corners[0], size);
    long bestInk = ink(best);
    for (std::size_t i = 1; i < corners.size() && bestInk > 0; ++i) {
        const QRectF candidate(corners[i], size);
        const long covered = ink(candidate);
        if (covered < bestInk) {
            best = candidate;
            bestInk = covered;
        }
    }
    return best;
}

void drawLegend(QPainter& painter, const PanelPlan& plan, const Style& style) {
    if (plan.legend.empty()) {
        return;
    }
    const QSizeF size = legendSize(plan, style);
    const QRectF box = placeLegend(plan, style, size);
    painter.setPen(QPen(QColor(0xc8, 0xc8, 0xc8), std::max<qreal>(1.0, style.scale)));
    // Mostly opaque: readable over data, yet data it must cover still shows through.
    painter.setBrush(QColor(255, 255, 255, 217));
    painter.drawRoundedRect(box, style.em * 0.2, style.em * 0.2);
    painter.setBrush(Qt::NoBrush);

    const QFontMetricsF metrics(style.tickFont);
    const qreal row = metrics.height() * 1.25;
    const qreal swatchLeft = box.left() + style.em * 0.5;
    const qreal swatchWidth = style.em * 2.0;
    painter.setFont(style.tickFont);
    for (std::size_t i = 0; i < plan.legend.size(); ++i) {
        const LegendEntry& entry = plan.legend[i];
        const qreal top = box.top() + style.em * 0.4 + row * static_cast<qreal>(i);
        const qreal middle = top + row / 2.0;
        if (entry.band) {
            painter.fillRect(QRectF(swatchLeft, middle - row * 0.3, swatchWidth, row * 0.6),
                             bandFill(entry.bandColor));
        }
        if (entry.line) {
            const qreal width = entry.line->width * style.scale;
            if (entry.line->style != Qt::NoPen) {
                painter.setPen(QPen(entry.lineColor, width, entry.line->style, Qt::FlatCap));
                painter.drawLine(QPointF(swatchLeft, middle),
                                 QPointF(swatchLeft + swatchWidth, middle));
            }
            if (entry.line->markers) {
                painter.setPen(QPen(entry.lineColor,
                                    std::max<qreal>(width * 2.6, 4.0 * style.scale), Qt::SolidLine,
                                    Qt::RoundCap));
                painter.drawPoint(QPointF(swatchLeft + swatchWidth / 2.0, middle));
            }
        }
        painter.setPen(kTextColor);
        painter.drawText(QRectF(swatchLeft + swatchWidth + style.em * 0.5, top,
                                box.right() - swatchLeft - swatchWidth, row),
                         Qt::AlignLeft | Qt::AlignVCenter, entry.label);
    }
}

void drawColourKey(QPainter& painter, const PanelPlan& plan, const Style& style) {
    if (!plan.heatmap.valid) {
        return;
    }
    const Heatmap& heatmap = *plan.axes->heatmap;
    const QRectF& area = plan.area;
    const qreal lineWidth = std::max<qreal>(1.0, style.scale);
    const qreal left = area.right() + style.em;
    painter.setFont(style.tickFont);
    if (heatmap.threshold) {
        // Two swatches with "< t" and ">= t", under the value's name.
        const QFontMetricsF metrics(style.tickFont);
        const qreal row = metrics.height() * 1.3;
        qreal top = area.top();
        if (!heatmap.valueLabel.isEmpty()) {
            painter.setPen(kTextColor);
            painter.drawText(QPointF(left, top + metrics.ascent()), heatmap.valueLabel);
            top += row;
        }
        const std::array<std::pair<QColor, QString>, 2> entries = {
            std::make_pair(plan.heatmap.below, belowText(heatmap)),
            std::make_pair(plan.heatmap.above, aboveText(heatmap))};
        for (const auto& [color, text] : entries) {
            const QRectF swatch(left, top + (row - style.em) / 2.0, style.em, style.em);
            painter.setPen(QPen(kFrameColor, lineWidth));
            painter.setBrush(color);
            painter.drawRect(swatch);
            painter.setBrush(Qt::NoBrush);
            painter.setPen(kTextColor);
            painter.drawText(QRectF(swatch.right() + style.gap * 1.5, top, area.width(), row),
                             Qt::AlignLeft | Qt::AlignVCenter, text);
            top += row;
        }
        return;
    }
    const QRectF bar(left, area.top(), style.em * 0.9, area.height());
    QLinearGradient gradient(bar.bottomLeft(), bar.topLeft());
    for (const auto& [position, color] : plan.heatmap.scale.stops()) {
        gradient.setColorAt(position, color);
    }
    painter.fillRect(bar, gradient);
    painter.setPen(QPen(kFrameColor, lineWidth));
    painter.drawRect(bar);
    const double span = plan.heatmap.maximum - plan.heatmap.minimum;
    qreal labels = 0.0;
    for (std::size_t i = 0; i < plan.heatmap.ticks.major.size(); ++i) {
        const double t = plan.heatmap.ticks.major[i];
        const qreal y = span > 0.0 ? bar.bottom() - (t - plan.heatmap.minimum) / span * bar.height()
                                   : bar.center().y();
        painter.setPen(QPen(kFrameColor, lineWidth));
        painter.drawLine(QPointF(bar.right(), crisp(y)),
                         QPointF(bar.right() + style.tickLength, crisp(y)));
        painter.setPen(kTextColor);
        drawLabel(painter, style, plan.heatmap.ticks.labels[i],
                  QPointF(bar.right() + style.tickLength + style.gap, y),
                  Qt::AlignLeft | Qt::AlignVCenter);
        labels = std::max(labels, labelWidth(style, plan.heatmap.ticks.labels[i]));
    }
    if (!heatmap.valueLabel.isEmpty()) {
        const qreal height = textHeight(style.labelFont);
        painter.save();
        painter.setFont(style.labelFont);
        painter.translate(
            bar.right() + style.tickLength + style.gap + labels + style.gap * 2 + height / 2.0,
            bar.center().y());
        painter.rotate(-90.0);
        painter.drawText(QRectF(-bar.height(), -height / 2.0, 2 * bar.height(), height),
                         Qt::AlignCenter, heatmap.valueLabel);
        painter.restore();
    }
}

void paintFigure(QPainter& painter, const Figure& figure, const Target& target) {
    const Style style = makeStyle(figure.size);
    const std::vector<PanelPlan> plans = planFigure(figure, style);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    painter.fillRect(QRectF(QPointF(0, 0), QSizeF(figure.size)), Qt::white);
    if (!figure.title.isEmpty()) {
        painter.setFont(style.figureTitleFont);
        painter.setPen(kTextColor);
        painter.drawText(
            QRectF(0, style.pad * 0.6, figure.size.width(), textHeight(style.figureTitleFont)),
            Qt::AlignHCenter | Qt::AlignTop,
            QFontMetricsF(style.figureTitleFont)
                .elidedText(figure.title, Qt::ElideRight, figure.size.width() - 2 * style.pad));
    }
    for (const PanelPlan& plan : plans) {
        drawGrid(painter, plan, style);
        painter.save();
        painter.setClipRect(plan.area);
        drawData(painter, plan, style, target);
        painter.restore();
        drawAxes(painter, plan, style);
        drawLegend(painter, plan, style);
        drawColourKey(painter, plan, style);
    }
}

bool validSize(QSize size) {
    return size.width() > 0 && size.height() > 0 && size.width() <= kMaxImageSide &&
           size.height() <= kMaxImageSide;
}

bool fail(QString* error, const QString& message) {
    if (error) {
        *error = message;
    }
    return false;
}

}  // namespace

std::vector<double> niceTicks(double lo, double hi, int target) {
    if (!finite(lo) || !finite(hi)) {
        return {};
    }
    if (lo > hi) {
        std::swap(lo, hi);
    }
    if (lo == hi) {
        return {lo};
    }
    target = std::clamp(target, 2, 100);
    Step step = niceStep(hi - lo, target);
    // Tick indices are integers; beyond 2^53 the span is below double precision anyway.
    constexpr double kLargestIndex = 1e15;
    for (int attempt = 0; attempt < 4; ++attempt) {
        const double s = step.value();
        if (std::abs(lo / s) > kLargestIndex || std::abs(hi / s) > kLargestIndex) {
            return {lo, hi};
        }
        const auto first = static_cast<long long>(std::ceil(lo / s - 1e-9));
        const auto last = static_cast<long long>(std::floor(hi / s + 1e-9));
        if (last - first + 1 >= 2) {
            std::vector<double> ticks;
            ticks.reserve(static_cast<std::size_t>(last - first + 1));
            for (long long i = first; i <= last; ++i) {
                ticks.push_back(step.at(i));
            }
            return ticks;
        }
        step = step.smaller();
    }
    return {lo, hi};
}

std::vector<double> logTicks(double lo, double hi, int target) {
    if (!finite(lo) || !finite(hi)) {
        return {};
    }
    if (lo > hi) {
        std::swap(lo, hi);
    }
    if (!(lo > 0.0)) {
        return {};
    }
    target = std::clamp(target, 2, 100);
    const int k0 = static_cast<int>(std::ceil(std::log10(lo) - 1e-9));
    const int k1 = static_cast<int>(std::floor(std::log10(hi) + 1e-9));
    const int decades = k1 - k0 + 1;
    std::vector<double> ticks;
    // Fewer than three powers of ten inside: 1, 2 and 5 times powers of ten label the axis
    // better (0.02 0.05 0.1 0.2 ...), if they are not too many.
    if (decades < 3) {
        for (int k = static_cast<int>(std::floor(std::log10(lo)));
             k <= static_cast<int>(std::ceil(std::log10(hi))); ++k) {
            for (const int m : {1, 2, 5}) {
                const double v = k >= 0 ? m * std::pow(10.0, k) : m / std::pow(10.0, -k);
                if (v >= lo * (1 - 1e-12) && v <= hi * (1 + 1e-12)) {
                    ticks.push_back(v);
                }
            }
        }
        if (ticks.size() >= 2 && static_cast<int>(ticks.size()) <= target) {
            return ticks;
        }
        ticks.clear();
    }
    if (decades >= 2) {
        const int every = (decades + target - 1) / target;
        // Multiples of the stride (10^0, 10^3, 10^6, ...), so labels read as a regular scale.
        int first = k0 + ((every - (k0 % every)) % every + every) % every;
        if ((k1 - first) / every + 1 < 2) {
            first = k0;
        }
        for (int k = first; k <= k1; k += every) {
            ticks.push_back(std::pow(10.0, k));
        }
        return ticks;
    }
    // Within a decade and too many 1-2-5 values for the room: evenly spaced nice values.
    return niceTicks(lo, hi, target);
}

QColor paletteColor(int index) {
    static const std::array<QRgb, 10> kPalette = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                                  0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};
    const int n = static_cast<int>(kPalette.size());
    return QColor(kPalette[static_cast<std::size_t>(((index % n) + n) % n)]);
}

std::vector<PanelGeometry> layoutFigure(const Figure& figure) {
    std::vector<PanelGeometry> result;
    if (!validSize(figure.size)) {
        return result;
    }
    const Style style = makeStyle(figure.size);
    for (const PanelPlan& plan : planFigure(figure, style)) {
        PanelGeometry geometry;
        geometry.area = plan.area;
        geometry.xMin = plan.map.x0;
        geometry.xMax = plan.map.x1;
        geometry.logY = plan.map.logY;
        geometry.yMin = plan.map.logY ? std::pow(10.0, plan.map.y0) : plan.map.y0;
        geometry.yMax = plan.map.logY ? std::pow(10.0, plan.map.y1) : plan.map.y1;
        result.push_back(geometry);
    }
    return result;
}

QPointF toPixel(const PanelGeometry& panel, QPointF data) {
    Mapping map;
    map.area = panel.area;
    map.x0 = panel.xMin;
    map.x1 = panel.xMax;
    map.logY = panel.logY;
    map.y0 = panel.logY ? std::log10(panel.yMin) : panel.yMin;
    map.y1 = panel.logY ? std::log10(panel.yMax) : panel.yMax;
    return map(data.x(), data.y());
}

QImage renderFigure(const Figure& figure) {
    if (!validSize(figure.size)) {
        return {};
    }
    QImage image(figure.size, QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    paintFigure(painter, figure, Target{});
    painter.end();
    return image.convertToFormat(QImage::Format_ARGB32);
}

bool saveFigure(const Figure& figure, const QString& path, QString* error) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QLatin1String("png") && suffix != QLatin1String("svg")) {
        return fail(
            error,
            QStringLiteral("%1: unknown plot format \"%2\" (use .png or .svg)").arg(path, suffix));
    }
    if (!validSize(figure.size)) {
        return fail(error, QStringLiteral("%1: bad figure size %2 x %3")
                               .arg(path)
                               .arg(figure.size.width())
                               .arg(figure.size.height()));
    }
    if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance())) {
        // Fonts need the GUI application's platform (e.g. -platform offscreen).
        return fail(error,
                    QStringLiteral("%1: rendering a plot needs a QGuiApplication").arg(path));
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        return fail(error, QStringLiteral("%1: cannot write: %2").arg(path, file.errorString()));
    }
    if (suffix == QLatin1String("png")) {
        if (!renderFigure(figure).save(&file, "PNG")) {
            file.cancelWriting();
            return fail(error,
                        QStringLiteral("%1: cannot encode PNG: %2").arg(path, file.errorString()));
        }
    } else {
        QSvgGenerator generator;
        generator.setOutputDevice(&file);
        generator.setSize(figure.size);
        generator.setViewBox(QRect(QPoint(0, 0), figure.size));
        generator.setResolution(96);  // so width and height in mm come out as CSS pixels
        generator.setTitle(figure.title);
        generator.setDescription(QStringLiteral("PRISCA Lab figure"));
        QPainter painter;
        if (!painter.begin(&generator)) {
            file.cancelWriting();
            return fail(error, QStringLiteral("%1: cannot start the SVG").arg(path));
        }
        paintFigure(painter, figure, Target{true, false});
        painter.end();
    }
    if (!file.commit()) {
        return fail(error, QStringLiteral("%1: cannot write: %2").arg(path, file.errorString()));
    }
    return true;
}

}  // namespace prisca::app::plot
