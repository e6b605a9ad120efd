#include "app/plot/FigureRanges.h"

#include <cmath>

namespace prisca::app::plot::detail {

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

}  // namespace prisca::app::plot::detail
