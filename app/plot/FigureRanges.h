#pragma once

// The data range a panel shows: all its data with a margin, a heatmap edge to edge, an explicit
// range as given, whole decades on a log axis, and equal aspect where asked. Internal to app/plot.

#include "app/plot/DataClipping.h"
#include "app/plot/Figure.h"
#include "app/plot/FigureStyle.h"

#include <QPointF>
#include <QSizeF>

#include <algorithm>
#include <limits>

namespace prisca::app::plot::detail {

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
void pad(double* lo, double* hi, double fraction);

// The range shown before equal aspect: all data with a 5 % margin, a lone heatmap edge to edge,
// an explicit range as given; on a log axis whole decades, so there are labelled ticks.
DataView baseView(const Axes& axes, bool* empty);

// Widens one axis of the base range so a data unit is as long in x as in y on the plot area.
DataView withEqualAspect(const DataView& base, QSizeF area);

bool sameView(const DataView& a, const DataView& b);

}  // namespace prisca::app::plot::detail
